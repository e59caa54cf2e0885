// Plain OBJ files read on every core (read_obj_plain.h): the file cut into chunks of whole
// lines, each chunk's vertex and face lines counted, then each chunk parsed straight into its
// rows of the mesh. At 1.3M faces (a 70 MB file) the line-by-line reader took 0.27 s, its words
// split into a vector per line and the polygons gathered in a soup before the mesh was made;
// this one 0.09 s on two cores (docs/performance.md, "Issue 20, tenth round").
#include "read_obj_plain.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace msmesh::io_detail {
namespace {

constexpr std::size_t kChunkBytes = 1 << 20;  // a chunk per MB at most (small files: one)
constexpr double kMaxSpan = 1e150;            // validate_mesh's bound (src/mesh.cpp)

/// One chunk of whole lines: where its vertices and triangles go in the mesh (counted first),
/// how many it read, the coordinates' bounds; plain = false at the first thing that is not plain.
struct Chunk {
  const char* begin = nullptr;
  const char* end = nullptr;
  std::size_t vertices = 0, faces = 0;           // counted: lines whose first word is "v" or "f"
  std::size_t first_vertex = 0, first_face = 0;  // their rows in the mesh
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool plain = true;
};

/// The lines of c whose first word is "v" and "f" (a letter, then a space); no other line of a
/// plain file has either.
void count_records(Chunk& c) {
  for (const char* p = c.begin; p < c.end;) {
    while (p < c.end && *p != '\n' && is_space(*p)) ++p;
    if (c.end - p >= 2 && is_space(p[1])) {
      c.vertices += p[0] == 'v';
      c.faces += p[0] == 'f';
    }
    p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(c.end - p)));
    p = p ? p + 1 : c.end;
  }
}

/// Parses chunk c into rows c.first_vertex... of V and c.first_face... of F (column-major, #V
/// and #F rows); stops at the first line that is not plain.
void parse_chunk(Chunk& c, Eigen::MatrixXd& V, Eigen::MatrixXi& F) {
  const char* p = c.begin;
  const char* const end = c.end;
  auto skip_spaces = [&] {
    while (p < end && *p != '\n' && is_space(*p)) ++p;
  };
  // The end of the current word (a run of non-space characters).
  auto word_end = [&] {
    const char* q = p;
    while (q < end && !is_space(*q)) ++q;
    return q;
  };
  // After a record's values: the rest of the line must be spaces or a comment.
  auto line_ends = [&] {
    skip_spaces();
    if (p < end && *p == '#') p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
    if (p == nullptr) p = end;
    if (p < end && *p != '\n') return false;
    if (p < end) ++p;
    return true;
  };
  Eigen::Index v = static_cast<Eigen::Index>(c.first_vertex), f = static_cast<Eigen::Index>(c.first_face);
  const Eigen::Index v_end = v + static_cast<Eigen::Index>(c.vertices), f_end = f + static_cast<Eigen::Index>(c.faces);
  while (p < end) {
    skip_spaces();
    if (p == end) break;
    if (*p == '\n') {
      ++p;
      continue;
    }
    if (*p == '#') {  // a comment line
      p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
      p = p ? p + 1 : end;
      continue;
    }
    const char* const key_end = word_end();
    const bool vertex = key_end - p == 1 && *p == 'v' && v < v_end;
    const bool face = key_end - p == 1 && *p == 'f' && f < f_end;
    if (!vertex && !face) {
      c.plain = false;
      return;
    }
    p = key_end;
    if (vertex) {
      double x[3];
      for (double& xc : x) {
        skip_spaces();
        const char* const we = word_end();
        const auto r = fast_float::from_chars(p, we, xc);
        // The whole word, finite (read_obj's parse_double falls back to strtod for the forms
        // fast_float leaves, and refuses non-finite values: not plain).
        if (p == we || r.ec != std::errc() || r.ptr != we || !(xc - xc == 0)) {
          c.plain = false;
          return;
        }
        p = we;
      }
      if (!line_ends()) {  // more values (colours), or a word glued to a number
        c.plain = false;
        return;
      }
      const bool first = v == static_cast<Eigen::Index>(c.first_vertex);
      for (int k = 0; k < 3; ++k) {
        c.lo[k] = first ? x[k] : std::min(c.lo[k], x[k]);
        c.hi[k] = first ? x[k] : std::max(c.hi[k], x[k]);
        V(v, k) = x[k];
      }
      ++v;
    } else {
      int idx[3];
      for (int& i : idx) {
        skip_spaces();
        const char* const we = word_end();
        // Positive decimal digits only, at most 10 of them, within int (read_obj refuses 0 and
        // reads '-' as relative and '/' as texture or normal indices: not plain).
        long long n = 0;
        if (p == we || we - p > 10) {
          c.plain = false;
          return;
        }
        for (; p < we; ++p) {
          const unsigned d = static_cast<unsigned char>(*p) - unsigned('0');
          if (d > 9) {
            c.plain = false;
            return;
          }
          n = n * 10 + d;
        }
        if (n < 1 || n > INT_MAX) {
          c.plain = false;
          return;
        }
        i = static_cast<int>(n - 1);
      }
      if (!line_ends() || idx[0] == idx[1] || idx[1] == idx[2] || idx[0] == idx[2]) {  // a polygon, a repeat
        c.plain = false;
        return;
      }
      for (int k = 0; k < 3; ++k) F(f, k) = idx[k];
      ++f;
    }
  }
  c.plain = c.plain && v == v_end && f == f_end;
}

}  // namespace

bool read_plain_obj(std::string_view data, Soup& soup) {
  const char* const begin = data.data();
  const char* const end = begin + data.size();
  int threads = 1;
#ifdef _OPENMP
  threads = omp_get_max_threads();
#endif
  const std::size_t n_chunks =
      std::max<std::size_t>(1, std::min<std::size_t>(static_cast<std::size_t>(threads), data.size() / kChunkBytes));
  // Chunk k starts after the first '\n' at or beyond k / n of the file.
  std::vector<const char*> cut(n_chunks + 1, end);
  cut[0] = begin;
  for (std::size_t k = 1; k < n_chunks; ++k) {
    const char* from = std::max(cut[k - 1], begin + data.size() / n_chunks * k);
    const char* nl =
        from < end ? static_cast<const char*>(std::memchr(from, '\n', static_cast<std::size_t>(end - from))) : nullptr;
    cut[k] = nl ? nl + 1 : end;
  }
  std::vector<Chunk> chunks(n_chunks);
  for (std::size_t k = 0; k < n_chunks; ++k) {
    chunks[k].begin = cut[k];
    chunks[k].end = cut[k + 1];
  }
  const auto n = static_cast<long>(n_chunks);
  // Counted first, so that every chunk is read straight into its rows of the mesh.
#pragma omp parallel for schedule(static, 1) if (n > 1)
  for (long k = 0; k < n; ++k) count_records(chunks[static_cast<std::size_t>(k)]);
  std::size_t nv = 0, nf = 0;
  for (Chunk& c : chunks) {
    c.first_vertex = nv;
    c.first_face = nf;
    nv += c.vertices;
    nf += c.faces;
  }
  if (nv == 0 || nf == 0 || nv > static_cast<std::size_t>(INT_MAX)) return false;
  Mesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(nv), 3);
  mesh.F.resize(static_cast<Eigen::Index>(nf), 3);
#pragma omp parallel for schedule(static, 1) if (n > 1)
  for (long k = 0; k < n; ++k) parse_chunk(chunks[static_cast<std::size_t>(k)], mesh.V, mesh.F);
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool any_vertex = false;
  for (const Chunk& c : chunks) {
    if (!c.plain) return false;
    if (c.vertices > 0)
      for (int k = 0; k < 3; ++k) {
        lo[k] = any_vertex ? std::min(lo[k], c.lo[k]) : c.lo[k];
        hi[k] = any_vertex ? std::max(hi[k], c.hi[k]) : c.hi[k];
      }
    any_vertex = any_vertex || c.vertices > 0;
  }
  for (int k = 0; k < 3; ++k)
    if (!(hi[k] - lo[k] <= kMaxSpan)) return false;
  // Every index within the file's vertices (a face may name a vertex listed after it).
  if (mesh.F.maxCoeff() >= static_cast<int>(nv)) return false;
  soup.mesh = std::move(mesh);
  soup.direct_dropped = 0;
  soup.direct = true;
  return true;
}

}  // namespace msmesh::io_detail
