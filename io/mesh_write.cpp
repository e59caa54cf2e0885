// Mesh and polyline writers. They are short enough to write directly (no CGAL): coordinates
// are printed with the shortest representation that reads back to the same double
// (std::to_chars), binary files are little-endian, and everything goes through
// write_file_atomically so a failed write leaves no partial file.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>

#include <Eigen/Geometry>

#include "msmesh/errors.h"
#include "msmesh/io.h"

namespace msmesh {
namespace {

bool host_is_little_endian() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// Buffered output: formats into a string and hands it to the stream in large chunks.
class OutBuffer {
 public:
  explicit OutBuffer(std::ostream& out) : out_(out), little_(host_is_little_endian()) { buf_.reserve(kChunk + 512); }
  OutBuffer(const OutBuffer&) = delete;
  OutBuffer& operator=(const OutBuffer&) = delete;

  OutBuffer& text(std::string_view s) {
    buf_.append(s);
    return maybe_flush();
  }
  OutBuffer& ch(char c) {
    buf_.push_back(c);
    return maybe_flush();
  }
  /// Shortest decimal form that reads back to exactly `x`.
  OutBuffer& real(double x) {
    char tmp[32];
    const auto r = std::to_chars(tmp, tmp + sizeof tmp, x);
    buf_.append(tmp, r.ptr);
    return maybe_flush();
  }
  OutBuffer& integer(long long v) {
    char tmp[24];
    const auto r = std::to_chars(tmp, tmp + sizeof tmp, v);
    buf_.append(tmp, r.ptr);
    return maybe_flush();
  }
  /// Little-endian binary value.
  template <class T>
  OutBuffer& binary(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    if (!little_) std::reverse(b, b + sizeof(T));
    buf_.append(b, sizeof(T));
    return maybe_flush();
  }
  void finish() { flush(); }

 private:
  static constexpr std::size_t kChunk = std::size_t(1) << 20;
  OutBuffer& maybe_flush() {
    if (buf_.size() >= kChunk) flush();
    return *this;
  }
  void flush() {
    out_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }
  std::ostream& out_;
  bool little_;
  std::string buf_;
};

/// Shapes, index ranges and finiteness; writing a file we could not read back is refused.
void check_for_writing(const std::string& path, const Mesh& mesh) {
  const Eigen::MatrixXd& V = mesh.V;
  const Eigen::MatrixXi& F = mesh.F;
  auto fail = [&path](const std::string& what) { throw InvalidInput(path + ": cannot write mesh: " + what); };
  if (V.cols() != 3) fail("vertex array must be #V by 3, got " + std::to_string(V.rows()) + " by " + std::to_string(V.cols()));
  if (F.rows() > 0 && F.cols() != 3)
    fail("face array must be #F by 3, got " + std::to_string(F.rows()) + " by " + std::to_string(F.cols()));
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(V(i, c))) fail("vertex " + std::to_string(i) + " has a non-finite coordinate");
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (F(f, k) < 0 || F(f, k) >= V.rows())
        fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(F(f, k)) + ", out of range [0, " +
             std::to_string(V.rows()) + ")");
  if (mesh.vertex_colors.size() > 0 && (mesh.vertex_colors.rows() != V.rows() || mesh.vertex_colors.cols() != 3))
    fail("vertex_colors must be empty or #V by 3");
  if (mesh.uv.size() > 0 && (mesh.uv.rows() != V.rows() || mesh.uv.cols() != 2)) fail("uv must be empty or #V by 2");
  if (mesh.vertex_normals.size() > 0 && (mesh.vertex_normals.rows() != V.rows() || mesh.vertex_normals.cols() != 3))
    fail("vertex_normals must be empty or #V by 3");
}

std::uint8_t color_byte(double c) {
  if (!(c > 0)) return 0;  // also NaN
  if (c >= 1) return 255;
  return static_cast<std::uint8_t>(std::lround(c * 255.0));
}

void write_obj(OutBuffer& o, const Mesh& m) {
  const bool colors = m.vertex_colors.size() > 0, uv = m.uv.size() > 0;
  o.text("# written by msmesh\n");
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) {
    o.text("v ").real(m.V(i, 0)).ch(' ').real(m.V(i, 1)).ch(' ').real(m.V(i, 2));
    // "v x y z r g b" is a widespread extension; readers that do not know it ignore the rest.
    if (colors) o.ch(' ').real(m.vertex_colors(i, 0)).ch(' ').real(m.vertex_colors(i, 1)).ch(' ').real(m.vertex_colors(i, 2));
    o.ch('\n');
  }
  if (uv)
    for (Eigen::Index i = 0; i < m.uv.rows(); ++i) o.text("vt ").real(m.uv(i, 0)).ch(' ').real(m.uv(i, 1)).ch('\n');
  const bool normals = m.vertex_normals.size() > 0;
  if (normals)
    for (Eigen::Index i = 0; i < m.vertex_normals.rows(); ++i)
      o.text("vn ").real(m.vertex_normals(i, 0)).ch(' ').real(m.vertex_normals(i, 1)).ch(' ').real(m.vertex_normals(i, 2)).ch('\n');
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    o.ch('f');
    for (int k = 0; k < 3; ++k) {
      o.ch(' ').integer(m.F(f, k) + 1LL);
      if (uv || normals) o.ch('/');
      if (uv) o.integer(m.F(f, k) + 1LL);
      if (normals) o.ch('/').integer(m.F(f, k) + 1LL);
    }
    o.ch('\n');
  }
}

void write_off(OutBuffer& o, const Mesh& m) {
  const bool colors = m.vertex_colors.size() > 0;
  o.text(colors ? "COFF\n" : "OFF\n").integer(m.V.rows()).ch(' ').integer(m.F.rows()).text(" 0\n");
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) {
    o.real(m.V(i, 0)).ch(' ').real(m.V(i, 1)).ch(' ').real(m.V(i, 2));
    if (colors)
      o.ch(' ')
          .integer(color_byte(m.vertex_colors(i, 0)))
          .ch(' ')
          .integer(color_byte(m.vertex_colors(i, 1)))
          .ch(' ')
          .integer(color_byte(m.vertex_colors(i, 2)))
          .text(" 255");
    o.ch('\n');
  }
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    o.text("3 ").integer(m.F(f, 0)).ch(' ').integer(m.F(f, 1)).ch(' ').integer(m.F(f, 2)).ch('\n');
}

/// PLY with double coordinates (exact round trip), optional vertex normals, colours and uv, and
/// optional per-face colours.
void write_ply(OutBuffer& o, const Mesh& m, bool binary, const Eigen::MatrixXd* face_colors) {
  const bool vcolors = m.vertex_colors.size() > 0, uv = m.uv.size() > 0, normals = m.vertex_normals.size() > 0;
  o.text("ply\nformat ").text(binary ? "binary_little_endian" : "ascii").text(" 1.0\ncomment written by msmesh\n");
  o.text("element vertex ").integer(m.V.rows()).text("\nproperty double x\nproperty double y\nproperty double z\n");
  if (normals) o.text("property double nx\nproperty double ny\nproperty double nz\n");
  if (vcolors) o.text("property uchar red\nproperty uchar green\nproperty uchar blue\n");
  if (uv) o.text("property double texture_u\nproperty double texture_v\n");
  o.text("element face ").integer(m.F.rows()).text("\nproperty list uchar int vertex_indices\n");
  if (face_colors) o.text("property uchar red\nproperty uchar green\nproperty uchar blue\n");
  o.text("end_header\n");
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) {
    if (binary) {
      for (int c = 0; c < 3; ++c) o.binary<double>(m.V(i, c));
      if (normals)
        for (int c = 0; c < 3; ++c) o.binary<double>(m.vertex_normals(i, c));
      if (vcolors)
        for (int c = 0; c < 3; ++c) o.binary<std::uint8_t>(color_byte(m.vertex_colors(i, c)));
      if (uv)
        for (int c = 0; c < 2; ++c) o.binary<double>(m.uv(i, c));
    } else {
      o.real(m.V(i, 0)).ch(' ').real(m.V(i, 1)).ch(' ').real(m.V(i, 2));
      if (normals)
        for (int c = 0; c < 3; ++c) o.ch(' ').real(m.vertex_normals(i, c));
      if (vcolors)
        for (int c = 0; c < 3; ++c) o.ch(' ').integer(color_byte(m.vertex_colors(i, c)));
      if (uv) o.ch(' ').real(m.uv(i, 0)).ch(' ').real(m.uv(i, 1));
      o.ch('\n');
    }
  }
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    if (binary) {
      o.binary<std::uint8_t>(3);
      for (int k = 0; k < 3; ++k) o.binary<std::int32_t>(m.F(f, k));
      if (face_colors)
        for (int c = 0; c < 3; ++c) o.binary<std::uint8_t>(color_byte((*face_colors)(f, c)));
    } else {
      o.text("3 ").integer(m.F(f, 0)).ch(' ').integer(m.F(f, 1)).ch(' ').integer(m.F(f, 2));
      if (face_colors)
        for (int c = 0; c < 3; ++c) o.ch(' ').integer(color_byte((*face_colors)(f, c)));
      o.ch('\n');
    }
  }
}

Eigen::Vector3d unit_normal(const Mesh& m, Eigen::Index f) {
  const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double len = n.norm();
  return len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
}

void write_stl(OutBuffer& o, const Mesh& m, bool binary, const std::string& path) {
  if (binary) {
    if (m.F.rows() > static_cast<Eigen::Index>(std::numeric_limits<std::uint32_t>::max()))
      throw InvalidInput(path + ": too many faces for a binary STL (" + std::to_string(m.F.rows()) + ")");
    // The 80-byte header must not start with "solid", which would announce an ascii STL.
    std::string header = "binary STL written by msmesh";
    header.resize(80, ' ');
    o.text(header).binary<std::uint32_t>(static_cast<std::uint32_t>(m.F.rows()));
    for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
      const Eigen::Vector3d n = unit_normal(m, f);
      for (int c = 0; c < 3; ++c) o.binary<float>(static_cast<float>(n(c)));
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c) o.binary<float>(static_cast<float>(m.V(m.F(f, k), c)));
      o.binary<std::uint16_t>(0);
    }
    return;
  }
  // Ascii STL: full double precision (readers that parse floats just round).
  o.text("solid msmesh\n");
  for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d n = unit_normal(m, f);
    o.text("facet normal ").real(n(0)).ch(' ').real(n(1)).ch(' ').real(n(2)).text("\n outer loop\n");
    for (int k = 0; k < 3; ++k) {
      const Eigen::Index v = m.F(f, k);
      o.text("  vertex ").real(m.V(v, 0)).ch(' ').real(m.V(v, 1)).ch(' ').real(m.V(v, 2)).ch('\n');
    }
    o.text(" endloop\nendfacet\n");
  }
  o.text("endsolid msmesh\n");
}

}  // namespace

void write_mesh(const std::string& path, const Mesh& mesh, const WriteOptions& options) {
  const std::string format = mesh_format_from_path(path);
  check_for_writing(path, mesh);
  write_file_atomically(path, [&](std::ostream& out) {
    OutBuffer o(out);
    if (format == "obj")
      write_obj(o, mesh);
    else if (format == "off")
      write_off(o, mesh);
    else if (format == "ply")
      write_ply(o, mesh, options.binary, nullptr);
    else
      write_stl(o, mesh, options.binary, path);
    o.finish();
  });
}

void write_ply_face_colors(const std::string& path, const Mesh& mesh, const Eigen::MatrixXd& face_colors, bool binary) {
  if (mesh_format_from_path(path) != "ply") throw IoError(path + ": face colours can only be written to a .ply file");
  check_for_writing(path, mesh);
  if (face_colors.rows() != mesh.F.rows() || face_colors.cols() != 3)
    throw InvalidInput(path + ": face colours must be #F by 3 (" + std::to_string(mesh.F.rows()) + " by 3), got " +
                       std::to_string(face_colors.rows()) + " by " + std::to_string(face_colors.cols()));
  write_file_atomically(path, [&](std::ostream& out) {
    OutBuffer o(out);
    write_ply(o, mesh, binary, &face_colors);
    o.finish();
  });
}

void write_polylines(const std::string& path, const Eigen::MatrixXd& P, const std::vector<std::vector<int>>& lines) {
  const std::string format = mesh_format_from_path(path);
  if (format != "obj" && format != "ply")
    throw IoError(path + ": polylines can be written to .obj or .ply only, not ." + format);
  if (P.rows() > 0 && P.cols() != 3)
    throw InvalidInput(path + ": polyline points must be #P by 3, got " + std::to_string(P.rows()) + " by " +
                       std::to_string(P.cols()));
  for (Eigen::Index i = 0; i < P.rows(); ++i)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(P(i, c)))
        throw InvalidInput(path + ": polyline point " + std::to_string(i) + " has a non-finite coordinate");
  std::size_t num_edges = 0;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    for (int v : lines[l])
      if (v < 0 || v >= P.rows())
        throw InvalidInput(path + ": polyline " + std::to_string(l) + " refers to point " + std::to_string(v) +
                           ", out of range [0, " + std::to_string(P.rows()) + ")");
    if (lines[l].size() >= 2) num_edges += lines[l].size() - 1;
  }
  write_file_atomically(path, [&](std::ostream& out) {
    OutBuffer o(out);
    if (format == "obj") {
      o.text("# written by msmesh\n");
      for (Eigen::Index i = 0; i < P.rows(); ++i)
        o.text("v ").real(P(i, 0)).ch(' ').real(P(i, 1)).ch(' ').real(P(i, 2)).ch('\n');
      for (const auto& line : lines) {
        if (line.empty()) continue;
        o.ch('l');
        for (int v : line) o.ch(' ').integer(v + 1LL);
        o.ch('\n');
      }
    } else {
      o.text("ply\nformat ascii 1.0\ncomment polylines written by msmesh\nelement vertex ").integer(P.rows());
      o.text("\nproperty double x\nproperty double y\nproperty double z\nelement edge ")
          .integer(static_cast<long long>(num_edges))
          .text("\nproperty int vertex1\nproperty int vertex2\nend_header\n");
      for (Eigen::Index i = 0; i < P.rows(); ++i)
        o.real(P(i, 0)).ch(' ').real(P(i, 1)).ch(' ').real(P(i, 2)).ch('\n');
      for (const auto& line : lines)
        for (std::size_t k = 1; k < line.size(); ++k) o.integer(line[k - 1]).ch(' ').integer(line[k]).ch('\n');
    }
    o.finish();
  });
}

}  // namespace msmesh
