// Plain OBJ files read on every core (read_obj_plain.h): the file cut into chunks of whole
// lines, each chunk's vertex and face lines counted, then each chunk parsed straight into its
// rows of the mesh. At 1.3M faces (a 70 MB file) the line-by-line reader took 0.27 s, its words
// split into a vector per line and the polygons gathered in a soup before the mesh was made;
// this one 0.09 s on two cores (docs/performance.md, "Issue 20, tenth round").
#include "read_obj_plain.h"

#include "plain_text.h"

namespace msmesh::io_detail {
namespace {

/// One chunk of whole lines: its vertex and face lines (counted first) and their rows in the
/// mesh, the coordinates' bounds; plain = false at the first thing that is not plain.
struct Chunk {
  std::string_view text;
  Eigen::Index vertices = 0, faces = 0;
  Eigen::Index first_vertex = 0, first_face = 0;
  PlainBounds bounds;
  bool plain = true;
};

/// The lines of c whose first word is "v" or "f" (a letter, then a space); no other line of a
/// plain file has either.
void count_records(Chunk& c) {
  const char* const end = c.text.data() + c.text.size();
  for (const char* p = c.text.data(); p < end;) {
    while (p < end && *p != '\n' && is_space(*p)) ++p;
    if (end - p >= 2 && is_space(p[1])) {
      c.vertices += p[0] == 'v';
      c.faces += p[0] == 'f';
    }
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
    p = nl ? static_cast<const char*>(nl) + 1 : end;
  }
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
  c.plain = w.done() && v == v_end && f == f_end;
}

}  // namespace

bool read_plain_obj(std::string_view data, Soup& soup) {
  std::vector<Chunk> chunks;
  for (const std::string_view text : line_chunks(data)) {
    chunks.emplace_back();
    chunks.back().text = text;
  }
  // Counted first, so that every chunk is read straight into its rows of the mesh.
  for_each_chunk(chunks.size(), [&](std::size_t k) { count_records(chunks[k]); });
  Eigen::Index nv = 0, nf = 0;
  for (Chunk& c : chunks) {
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
  PlainBounds bounds;
  for (const Chunk& c : chunks) {
    if (!c.plain) return false;
    bounds.add(c.bounds);
  }
  // Coordinates within validate_mesh's span, every index within the file's vertices (a face
  // may name a vertex listed after it).
  if (!bounds.within_span() || mesh.F.maxCoeff() >= nv) return false;
  soup.mesh = std::move(mesh);
  soup.direct_dropped = 0;
  soup.direct = true;
  return true;
}

}  // namespace msmesh::io_detail
