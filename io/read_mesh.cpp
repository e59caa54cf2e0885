// read_mesh and read_mesh_from_memory: the file mapped or read into memory (existence, size and
// memory checks), the reader of its format (read_obj.cpp, read_off.cpp, read_ply.cpp, read_stl.cpp),
// the errors of CGAL and the allocator turned into IoError naming the file, and the polygon
// soup turned into a Mesh (polygons triangulated, degenerate triangles dropped, attributes, notes).
#include "msmesh/read_mesh.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstring>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include "gzip.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/memory.h"
#include "msmesh/mesh_attributes.h"
#include "msmesh/mesh_format.h"
#include "read_common.h"

namespace msmesh {

using namespace io_detail;  // the readers' shared pieces (read_common.h)

namespace {

/// Why `path` cannot be opened, from the errno of open(2): each cause in words, so that a
/// symlink loop or a permission problem does not read as a missing file.
std::string open_error(const std::string& path, int err) {
  switch (err) {
    case ENOENT:
      return path + ": no such file";
    case ELOOP:
      return path + ": too many levels of symbolic links (a symlink loop)";
    case EACCES:
      return path + ": permission denied (the file is not readable or a folder on its path not searchable)";
    case ENAMETOOLONG:
      return path + ": file name too long (a name over 255 bytes or a path over 4095)";
    case ENOTDIR:
      return path + ": a component of the path is not a folder";
    case EISDIR:
      return path + ": is a directory, not a mesh file";
    default:
      return path + ": cannot open file for reading: " + std::strerror(err);
  }
}

/// The bytes of a file: the file mapped read-only (MAP_POPULATE: the page cache's pages themselves,
/// no copy and no fresh memory to fault in, ~6x cheaper than read(2) into a new buffer for a
/// 33 MB file, docs/performance.md "Reading and writing"), or, where mapping fails, read into a
/// buffer that is not zeroed first (the read fills it).
class FileBytes {
 public:
  FileBytes() = default;
  FileBytes(const FileBytes&) = delete;
  FileBytes& operator=(const FileBytes&) = delete;
  ~FileBytes() {
    if (mapped_) ::munmap(mapped_, size_);
  }
  std::string_view view() const { return {mapped_ ? static_cast<const char*>(mapped_) : bytes_.get(), size_}; }

  /// Maps `size` bytes of `fd`; false (nothing changed) when the system refuses.
  bool map(int fd, std::size_t size) {
    void* p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (p == MAP_FAILED) return false;
    ::madvise(p, size, MADV_SEQUENTIAL);
    mapped_ = p;
    size_ = size;
    return true;
  }
  char* allocate(std::size_t size) {
    bytes_.reset(new char[std::max<std::size_t>(size, 1)]);
    size_ = size;
    return bytes_.get();
  }
  void shrink(std::size_t size) { size_ = size; }  // a file that shrank while being read

 private:
  void* mapped_ = nullptr;
  std::unique_ptr<char[]> bytes_;
  std::size_t size_ = 0;
};

void read_whole_file(const std::string& path, FileBytes& data) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);  // a FIFO must not block: it is refused below
  if (fd < 0) throw IoError(open_error(path, errno));
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw IoError(path + ": cannot examine the file: " + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw IoError(open_error(path, EISDIR));
  if (!S_ISREG(st.st_mode)) throw IoError(path + ": not a regular file (a device, FIFO or socket), not a mesh file");
  const auto size = static_cast<std::uint64_t>(st.st_size);
  // The file, CGAL's polygon soup and the mesh: about four times the size of a binary file.
  check_memory(4.0 * static_cast<double>(size), path + ": reading a " + std::to_string(size) + "-byte file");
  // Files of a few pages are read (mapping costs more than the copy). A mapped file that another
  // process truncates while it is parsed would fault (SIGBUS); the mapping lasts one parse.
  constexpr std::uint64_t kMapFrom = 1 << 16;
  if (size >= kMapFrom && data.map(fd, static_cast<std::size_t>(size))) return;
  char* const bytes = data.allocate(static_cast<std::size_t>(size));
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::read(fd, bytes + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw IoError(path + ": read error: " + std::strerror(errno));
    if (n == 0) break;
    done += static_cast<std::size_t>(n);
  }
  data.shrink(done);
}

// ---------------------------------------------------------------------------------------------
// Soup to mesh

/// The attributes beyond V, F, colours, uv and normals: alpha, per-face values of the polygon
/// each triangle comes from, per-corner texture coordinates, and the document-level ones.
void fill_face_attributes(const Soup& soup, const std::vector<int>& tri_polygon,
                          const std::vector<std::array<long long, 3>>& tri_texcoord, Mesh& mesh) {
  const Eigen::Index nv = mesh.V.rows(), nf = mesh.F.rows();
  const std::size_t np = soup.polygon_count();
  if (soup.alpha.size() == static_cast<std::size_t>(nv)) {
    if (mesh.vertex_colors.rows() != nv) mesh.vertex_colors = Eigen::MatrixXd::Ones(nv, 3);
    mesh.vertex_colors.conservativeResize(nv, 4);
    for (Eigen::Index i = 0; i < nv; ++i) mesh.vertex_colors(i, 3) = soup.alpha[static_cast<std::size_t>(i)];
  }
  if (soup.face_rgba.size() == np) {
    mesh.face_colors.resize(nf, soup.face_color_channels);
    for (Eigen::Index t = 0; t < nf; ++t)
      for (int c = 0; c < soup.face_color_channels; ++c)
        mesh.face_colors(t, c) = soup.face_rgba[static_cast<std::size_t>(tri_polygon[t])][static_cast<std::size_t>(c)];
  }
  auto per_face = [&](const std::vector<int>& of_polygon, Eigen::VectorXi& out) {
    if (of_polygon.size() != np) return;
    out.resize(nf);
    for (Eigen::Index t = 0; t < nf; ++t) out(t) = of_polygon[static_cast<std::size_t>(tri_polygon[t])];
  };
  per_face(soup.polygon_material, mesh.face_materials);
  per_face(soup.polygon_group, mesh.face_groups);
  per_face(soup.polygon_object, mesh.face_objects);
  if (!tri_texcoord.empty() || (!soup.corner_texcoord.empty() && nf == 0)) {
    mesh.texcoords.resize(static_cast<Eigen::Index>(soup.texcoord_table.size()), 2);
    for (std::size_t i = 0; i < soup.texcoord_table.size(); ++i)
      mesh.texcoords.row(static_cast<Eigen::Index>(i)) << soup.texcoord_table[i][0], soup.texcoord_table[i][1];
    mesh.face_texcoords.resize(nf, 3);
    for (Eigen::Index t = 0; t < nf; ++t)
      for (int k = 0; k < 3; ++k)
        mesh.face_texcoords(t, k) =
            static_cast<int>(tri_texcoord[static_cast<std::size_t>(t)][static_cast<std::size_t>(k)]);
  }
  const Mesh& x = soup.extra;
  copy_document_attributes(x, mesh);
  for (const VertexProperty& p : x.vertex_properties)
    if (p.values.size() == nv) mesh.vertex_properties.push_back(p);
}

Mesh soup_to_mesh(const std::string& path, const Soup& soup, Eigen::Index* dropped_degenerate) {
  const std::size_t nv = soup.points.size();
  if (nv == 0) throw IoError(path + ": the file contains no vertices");
  if (nv > static_cast<std::size_t>(INT_MAX)) throw IoError(path + ": too many vertices (" + std::to_string(nv) + ")");
  Mesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(nv), 3);
  for (std::size_t i = 0; i < nv; ++i)
    for (int c = 0; c < 3; ++c) mesh.V(static_cast<Eigen::Index>(i), c) = soup.points[i][c];

  std::size_t triangles = 0;
  const std::size_t np = soup.polygon_count();
  for (std::size_t p = 0; p < np; ++p) {
    const PolygonRef poly = soup.polygon(p);
    for (std::size_t idx : poly)
      if (idx >= nv)  // a negative index of a binary file arrives wrapped: print it signed
        throw IoError(path + ": face " + std::to_string(p) + " refers to vertex " +
                      std::to_string(static_cast<long long>(idx)) + " (0-based), out of range [0, " +
                      std::to_string(nv) + ")");
    if (poly.size >= 3) triangles += poly.size - 2;
  }
  // Polygons are triangulated (a fan when convex, ear clipping otherwise); triangles
  // repeating a vertex are dropped. Per-polygon and per-corner attributes follow the triangles.
  Eigen::Index dropped = 0;
  mesh.F.resize(static_cast<Eigen::Index>(triangles), 3);
  std::vector<int> tri_polygon;  // polygon of each triangle
  std::vector<std::array<long long, 3>> tri_texcoord;
  const bool corner_tc = !soup.corner_texcoord.empty();
  tri_polygon.reserve(triangles);
  if (corner_tc) tri_texcoord.reserve(triangles);
  Eigen::Index f = 0;
  std::size_t first_corner = 0;
  std::vector<int> corners;
  std::vector<std::array<int, 3>> tris;
  for (std::size_t p = 0; p < np; ++p) {
    const PolygonRef poly = soup.polygon(p);
    const std::size_t corner0 = first_corner;
    first_corner += poly.size;
    if (poly.size < 3) {
      ++dropped;
      continue;
    }
    corners.assign(poly.begin(), poly.end());
    tris.clear();
    if (poly.size == 3)
      tris.push_back({corners[0], corners[1], corners[2]});  // what triangulate_polygon gives, without the call
    else
      triangulate_polygon(soup.points, corners, tris);
    for (const auto& [a, b, c] : tris) {
      if (a == b || b == c || a == c) {
        ++dropped;
        continue;
      }
      mesh.F.row(f++) << a, b, c;
      tri_polygon.push_back(static_cast<int>(p));
      if (corner_tc) {
        std::array<long long, 3> t{};
        const int abc[3] = {a, b, c};
        for (int k = 0; k < 3; ++k) {
          const auto at = std::find(corners.begin(), corners.end(), abc[k]) - corners.begin();
          t[static_cast<std::size_t>(k)] = soup.corner_texcoord[corner0 + static_cast<std::size_t>(at)];
        }
        tri_texcoord.push_back(t);
      }
    }
  }
  mesh.F.conservativeResize(f, 3);
  if (f == 0)
    throw IoError(path + (dropped > 0 ? ": all " + std::to_string(dropped) + " faces are degenerate (repeat a vertex)"
                                      : std::string(": the file contains no faces")));
  try {
    validate_mesh(mesh.V, mesh.F, path);
  } catch (const InvalidInput& e) {
    throw IoError(e.what());
  }
  if (soup.vertex_colors.size() == nv) {
    mesh.vertex_colors.resize(static_cast<Eigen::Index>(nv), 3);
    for (std::size_t i = 0; i < nv; ++i) {
      const auto& col = soup.vertex_colors[i];
      mesh.vertex_colors.row(static_cast<Eigen::Index>(i)) << col.red() / 255.0, col.green() / 255.0,
          col.blue() / 255.0;
    }
  }
  auto fill = [&](Eigen::MatrixXd& M, const auto& rows) {
    if (rows.size() != nv) return;
    const Eigen::Index cols = static_cast<Eigen::Index>(rows.front().size());
    M.resize(static_cast<Eigen::Index>(nv), cols);
    for (std::size_t i = 0; i < nv; ++i)
      for (Eigen::Index c = 0; c < cols; ++c) M(static_cast<Eigen::Index>(i), c) = rows[i][static_cast<std::size_t>(c)];
  };
  if (mesh.vertex_colors.size() == 0) fill(mesh.vertex_colors, soup.rgb);
  fill(mesh.uv, soup.uv);
  fill(mesh.vertex_normals, soup.normals);
  // Normals that are not per-vertex (split at creases) are replaced by recomputed ones.
  if (soup.notes.had_normals && mesh.vertex_normals.size() == 0 && soup.normals.empty()) {
    mesh.vertex_normals = vertex_normals(mesh.V, mesh.F);
    // Coordinates near the double range (e.g. 1e308, found by libFuzzer) overflow the cross
    // products: no normals rather than non-finite ones.
    if (!mesh.vertex_normals.allFinite()) mesh.vertex_normals.resize(0, 3);
  }
  fill_face_attributes(soup, tri_polygon, tri_texcoord, mesh);
  if (mesh.face_texcoords.size() > 0) corner_uv_to_vertex_uv(mesh);  // per-vertex after all (no seams)
  if (dropped_degenerate) *dropped_degenerate = dropped;
  return mesh;
}

}  // namespace

Mesh read_mesh(const std::string& path, Eigen::Index* dropped_degenerate) {
  ReadNotes notes;
  Mesh mesh = read_mesh(path, notes);
  if (dropped_degenerate) *dropped_degenerate = notes.dropped_degenerate;
  return mesh;
}

Mesh read_mesh(const std::string& path, ReadNotes& notes) {
  const std::string format = mesh_format_from_path(path);
  FileBytes data;
  read_whole_file(path, data);
  return read_mesh_from_memory(data.view(), is_gzip_path(path) ? format + ".gz" : format, path, notes);
}

Mesh read_mesh_from_memory(std::string_view data, const std::string& format, const std::string& path,
                           Eigen::Index* dropped_degenerate) {
  ReadNotes notes;
  Mesh mesh = read_mesh_from_memory(data, format, path, notes);
  if (dropped_degenerate) *dropped_degenerate = notes.dropped_degenerate;
  return mesh;
}

Mesh read_mesh_from_memory(std::string_view data, const std::string& format, const std::string& path,
                           ReadNotes& notes) {
  const bool gz = format.size() > 3 && format.compare(format.size() - 3, 3, ".gz") == 0;
  const std::string base = gz ? format.substr(0, format.size() - 3) : format;
  if (base != "obj" && base != "off" && base != "ply" && base != "stl" && base != "gltf" && base != "glb")
    throw IoError(path + ": unknown mesh format " + quote_word(format) +
                  "; expected obj, off, ply, stl, gltf or glb (optionally with .gz)");
  if (data.empty()) throw IoError(path + ": empty file");
  std::string inflated;
  if (gz) {
    inflated = gunzip(data, path);
    data = inflated;
    if (data.empty()) throw IoError(path + ": empty file (after gzip decompression)");
  }
  Soup soup;
  t_polygon_limit = data.size();
  try {
    if (base == "obj")
      read_obj(path, data, soup);
    else if (base == "off")
      read_off(path, data, soup);
    else if (base == "ply")
      read_ply(path, data, soup);
    else if (base == "stl")
      read_stl(path, data, soup);
    else
      read_gltf(path, data, base == "glb", soup);
  } catch (const IoError&) {
    throw;
  } catch (const PolygonTooLarge& e) {
    throw IoError(path + ": a face declares " + std::to_string(e.size) +
                  " vertices, more than the file can hold (corrupt file)");
  } catch (const std::bad_alloc&) {
    throw IoError(path + ": out of memory while reading (corrupt counts in the file?)");
  } catch (const std::length_error&) {
    throw IoError(path + ": corrupt file (a count in it is out of range)");
  } catch (const std::exception& e) {
    throw IoError(path + ": reading failed: " + e.what());
  }
  Mesh mesh;
  if (soup.direct) {
    mesh = std::move(soup.mesh);
    notes.dropped_degenerate = soup.direct_dropped;
  } else {
    mesh = soup_to_mesh(path, soup, &notes.dropped_degenerate);
  }
  notes.had_normals = soup.notes.had_normals;
  notes.uv_dropped = false;
  notes.uv_seams = mesh.face_texcoords.size() > 0;
  notes.dropped = soup.notes.dropped;
  return mesh;
}

}  // namespace msmesh
