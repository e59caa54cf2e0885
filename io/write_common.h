// Shared pieces of the mesh writers (internal to msmesh_io): the output buffer every writer
// formats into, the checks before writing, and one writer per format (write_obj.cpp,
// write_off.cpp, write_ply.cpp, write_stl.cpp); write_mesh.cpp dispatches to them by format.
// The writers are short enough to write directly (no CGAL): coordinates are printed with the
// shortest representation that reads back to the same double (std::to_chars), binary files are
// little-endian, and everything goes through write_file_atomically so a failed write leaves no
// partial file.
#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "msmesh/mesh.h"

// msmesh::io_detail rather than the core's msmesh::detail (see read_common.h).
namespace msmesh::io_detail {

inline bool host_is_little_endian() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

/// Shortest decimal form that reads back to exactly `x` (a double, or a float), appended to `s`.
template <class Real>
inline void append_real(std::string& s, Real x) {
  char tmp[32];
  const auto r = std::to_chars(tmp, tmp + sizeof tmp, x);
  s.append(tmp, r.ptr);
}

inline void append_integer(std::string& s, long long v) {
  char tmp[24];
  const auto r = std::to_chars(tmp, tmp + sizeof tmp, v);
  s.append(tmp, r.ptr);
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
    append_real(buf_, x);
    return maybe_flush();
  }
  /// Shortest decimal form that reads back to exactly the float `x`.
  OutBuffer& real32(float x) {
    append_real(buf_, x);
    return maybe_flush();
  }
  OutBuffer& integer(long long v) {
    append_integer(buf_, v);
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

/// Lines 0..n-1, each formatted by line(s, i) appending to s, written in order: formatted in
/// parallel blocks (shortest round-trip decimals are most of the writing time), a batch of
/// blocks at a time so that the text held at once stays small.
template <class Line>
void write_lines(OutBuffer& o, Eigen::Index n, Line&& line) {
  constexpr Eigen::Index kLines = 4096, kBatch = 16;
  const Eigen::Index nb = (n + kLines - 1) / kLines;
  std::vector<std::string> block(static_cast<std::size_t>(std::min(nb, kBatch)));
  for (Eigen::Index b0 = 0; b0 < nb; b0 += kBatch) {
    const Eigen::Index b1 = std::min(nb, b0 + kBatch);
    const auto format = [&](Eigen::Index b) {
      std::string& s = block[static_cast<std::size_t>(b - b0)];
      s.clear();
      for (Eigen::Index i = b * kLines; i < std::min(n, (b + 1) * kLines); ++i) line(s, i);
    };
    if (b1 - b0 > 1) {
#pragma omp parallel for schedule(static)
      for (Eigen::Index b = b0; b < b1; ++b) format(b);
    } else {
      // One block: no parallel construct at all. (The first one starts the OpenMP runtime, and
      // LLVM's registers itself in a shared-memory file, which a file-size limit refuses: the
      // sanitizer build crashed instead of reporting the limit on `msmesh shape cube -o`.)
      format(b0);
    }
    for (Eigen::Index b = b0; b < b1; ++b) o.text(block[static_cast<std::size_t>(b - b0)]);
  }
}

/// Shapes, index ranges and finiteness; writing a file we could not read back is refused.
/// Throws InvalidInput naming `path` (write_mesh.cpp).
void check_for_writing(const std::string& path, const Mesh& mesh);

inline std::uint8_t color_byte(double c) {
  if (!(c > 0)) return 0;  // also NaN
  if (c >= 1) return 255;
  return static_cast<std::uint8_t>(std::lround(c * 255.0));
}

// One writer per format: formats `m` (checked by check_for_writing) into `o`.

/// OBJ; `path` (the output) is needed to rewrite the material libraries' paths relative to it.
void write_obj(OutBuffer& o, const Mesh& m, const std::string& path);  // write_obj.cpp
void write_off(OutBuffer& o, const Mesh& m);                           // write_off.cpp

/// PLY with double coordinates (float when m.position_type is Float32), optional vertex normals,
/// colours (with alpha), uv, extra properties (each with its type), per-face colours
/// (`face_colors` when given, else m.face_colors) and per-corner texture coordinates.
void write_ply(OutBuffer& o, const Mesh& m, bool binary, const Eigen::MatrixXd* face_colors);  // write_ply.cpp

/// glTF 2.0 (`glb`: the binary container) of the mesh, with m.gltf_document's scene when it
/// has one; `path` names the output in errors and for external image references.
void write_gltf(OutBuffer& o, const Mesh& m, bool glb, const std::string& path);  // write_gltf.cpp

/// Binary STL is float32; throws InvalidInput naming `path` when it cannot hold the faces.
void write_stl(OutBuffer& o, const Mesh& m, bool binary, const std::string& path);  // write_stl.cpp

}  // namespace msmesh::io_detail
