// Plain OBJ files read on every core (read_obj_plain.h): the file cut into chunks of whole
// lines, each chunk's vertex and face lines counted, then each chunk parsed straight into its
// rows of the mesh. At 1.3M faces (a 70 MB file) the line-by-line reader took 0.27 s, its words
// split into a vector per line and the polygons gathered in a soup before the mesh was made;
// this one 0.09 s on two cores (docs/performance.md, "Issue 20, tenth round").
#include "read_obj_plain.h"

#include "plain_text.h"

namespace msmesh::io_detail {
namespace {

/// A chunk's vertex and face lines (counted first) and their rows in the mesh.
struct Chunk : PlainChunk {
  Eigen::Index vertices = 0, faces = 0;
  Eigen::Index first_vertex = 0, first_face = 0;
};

/// The lines of c whose first word is "v" or "f"; any line that is neither, blank nor a
/// comment ("vt", "vn", "g", "usemtl", ...) makes the file not plain before anything is parsed.
void count_records(Chunk& c) {
  for_each_line(c.text, [&](const char* p, const char* end) {
    if (p == end || *p == '\n' || *p == '#') return;
    const bool record = end - p >= 2 && is_space(p[1]) && (p[0] == 'v' || p[0] == 'f');
    c.plain = c.plain && record;
    c.vertices += record && p[0] == 'v';
    c.faces += record && p[0] == 'f';
  });
}

/// Parses chunk c into its rows of V and F; stops at the first line that is not plain.
void parse_chunk(Chunk& c, Eigen::MatrixXd& V, Eigen::MatrixXi& F) {
  PlainWords w(c.text);
  Eigen::Index v = c.first_vertex, f = c.first_face;
  const Eigen::Index v_end = v + c.vertices, f_end = f + c.faces;
  while (!w.done()) {
    const char first = w.peek();
    if (first == '\0') {  // a blank line (or a NUL byte: not plain)
      if (!w.line_ends(false)) break;
    } else if (first == '#') {
      w.skip_line();
    } else if (v < v_end && w.keyword("v")) {
      double x[3];
      // Three whole numbers, then the line's end or a comment (more values: colours).
      if (!w.number(x[0]) || !w.number(x[1]) || !w.number(x[2]) || !w.line_ends(true)) break;
      c.bounds.add(x);
      for (int k = 0; k < 3; ++k) V(v, k) = x[k];
      ++v;
    } else if (f < f_end && w.keyword("f")) {
      // Three positive plain indices (read_obj reads '-' as relative, '/' as texture or
      // normal indices and refuses 0), three distinct vertices, nothing after them.
      long long i[3];
      if (!w.index(1, INT_MAX, i[0]) || !w.index(1, INT_MAX, i[1]) || !w.index(1, INT_MAX, i[2]) ||
          !w.line_ends(true) || i[0] == i[1] || i[1] == i[2] || i[0] == i[2])
        break;
      for (int k = 0; k < 3; ++k) F(f, k) = static_cast<int>(i[k] - 1);
      ++f;
    } else {
      break;
    }
  }
  c.plain = c.plain && w.done() && v == v_end && f == f_end;
}

}  // namespace

bool read_plain_obj(std::string_view data, Soup& soup) {
  std::vector<Chunk> chunks = plain_chunks<Chunk>(data);
  // Counted first, so that every chunk is read straight into its rows of the mesh.
  for_each_chunk(chunks.size(), [&](std::size_t k) { count_records(chunks[k]); });
  Eigen::Index nv = 0, nf = 0;
  for (Chunk& c : chunks) {
    if (!c.plain) return false;
    c.first_vertex = nv;
    c.first_face = nf;
    nv += c.vertices;
    nf += c.faces;
  }
  if (nv == 0 || nf == 0 || nv > INT_MAX) return false;
  Mesh mesh;
  mesh.V.resize(nv, 3);
  mesh.F.resize(nf, 3);
  for_each_chunk(chunks.size(), [&](std::size_t k) { parse_chunk(chunks[k], mesh.V, mesh.F); });
  // Every index within the file's vertices (a face may name a vertex listed after it).
  if (!all_plain(chunks) || mesh.F.maxCoeff() >= nv) return false;
  take_direct(std::move(mesh), soup);
  return true;
}

}  // namespace msmesh::io_detail
