// Plain ascii OFF files read on every core (read_off_plain.h): the body cut into chunks of
// whole lines, each chunk's records (non-blank lines) counted, then each chunk parsed straight
// into its rows of the mesh: the first `vertices` records are vertices, the rest triangles.
// CGAL's reader, which reads the rest, takes ~40 MB/s (docs/performance.md, "Reading and
// writing").
#include "read_off_plain.h"

#include "plain_text.h"

namespace msmesh::io_detail {
namespace {

/// A chunk's records (non-blank lines) and the file's record number of its first.
struct Chunk : PlainChunk {
  long long records = 0, first_record = 0;
};

/// The non-blank lines of c; any comment makes the file not plain.
void count_records(Chunk& c) {
  for_each_line(c.text, [&](const char* p, const char* end) {
    if (p == end || *p == '\n') return;
    c.plain = c.plain && *p != '#';
    ++c.records;
  });
}

/// Parses chunk c's records into V (records before nv) and F (the next nf); stops at the
/// first record that is not plain.
void parse_chunk(Chunk& c, long long nv, long long nf, Eigen::MatrixXd& V, Eigen::MatrixXi& F) {
  PlainWords w(c.text);
  long long r = c.first_record;
  const long long r_end = r + c.records;
  while (!w.done()) {
    if (w.peek() == '\0') {  // a blank line (or a NUL byte: not plain)
      if (!w.line_ends(false)) break;
      continue;
    }
    if (r < nv) {
      double x[3];
      if (!w.number(x[0]) || !w.number(x[1]) || !w.number(x[2]) || !w.line_ends(false)) break;
      c.bounds.add(x);
      for (int k = 0; k < 3; ++k) V(r, k) = x[k];
    } else if (r < nv + nf) {
      long long count = 0, i[3];
      if (!w.index(3, 3, count) || !w.index(0, nv - 1, i[0]) || !w.index(0, nv - 1, i[1]) ||
          !w.index(0, nv - 1, i[2]) || !w.line_ends(false) || i[0] == i[1] || i[1] == i[2] || i[0] == i[2])
        break;
      for (int k = 0; k < 3; ++k) F(r - nv, k) = static_cast<int>(i[k]);
    } else {
      break;
    }
    ++r;
  }
  c.plain = c.plain && w.done() && r == r_end;
}

}  // namespace

bool read_plain_off(std::string_view body, long long vertices, long long faces, Soup& soup) {
  if (vertices <= 0 || faces <= 0 || vertices > INT_MAX || faces > INT_MAX) return false;
  std::vector<Chunk> chunks = plain_chunks<Chunk>(body);
  for_each_chunk(chunks.size(), [&](std::size_t k) { count_records(chunks[k]); });
  long long records = 0;
  for (Chunk& c : chunks) {
    if (!c.plain) return false;
    c.first_record = records;
    records += c.records;
  }
  if (records != vertices + faces) return false;  // CGAL ignores what follows; the general reader
  Mesh mesh;
  mesh.V.resize(vertices, 3);
  mesh.F.resize(faces, 3);
  for_each_chunk(chunks.size(), [&](std::size_t k) { parse_chunk(chunks[k], vertices, faces, mesh.V, mesh.F); });
  if (!all_plain(chunks)) return false;
  take_direct(std::move(mesh), soup);
  return true;
}

}  // namespace msmesh::io_detail
