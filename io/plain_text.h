// Internal: what the parallel readers of plain text files (read_obj_plain.cpp,
// read_off_plain.cpp) share: the file cut into chunks of whole lines, one per thread, and a
// cursor over a chunk's words that takes only the plainest forms (whole decimal numbers that
// fast_float reads, indices of digits only); anything else is for the general reader.
#pragma once
#include <algorithm>
#include <climits>
#include <cstring>
#include <string_view>
#include <vector>

#include "read_common.h"
#include "read_text.h"

namespace msmesh::io_detail {

/// [begin, end) of each chunk of whole lines of `data`: one per thread, each at least
/// `min_bytes` (a small file is one chunk).
std::vector<std::string_view> line_chunks(std::string_view data, std::size_t min_bytes = std::size_t(1) << 20);

/// The bounds of the coordinates read, for validate_mesh's check of their span.
struct PlainBounds {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool any = false;
  void add(const double* x) {
    for (int k = 0; k < 3; ++k) {
      lo[k] = any ? std::min(lo[k], x[k]) : x[k];
      hi[k] = any ? std::max(hi[k], x[k]) : x[k];
    }
    any = true;
  }
  void add(const PlainBounds& b) {
    if (!b.any) return;
    add(b.lo);
    add(b.hi);
  }
  /// Within validate_mesh's bound (src/mesh.cpp): squared distances do not overflow.
  bool within_span() const {
    for (int k = 0; k < 3; ++k)
      if (!(hi[k] - lo[k] <= 1e150)) return false;
    return true;
  }
};

/// What every chunk of a plain reader holds: its text, the bounds of the coordinates read from
/// it, and whether everything in it was plain. Each reader adds its counts.
struct PlainChunk {
  std::string_view text;
  PlainBounds bounds;
  bool plain = true;
};

/// The chunks of line_chunks(data) as C (a PlainChunk).
template <class C>
std::vector<C> plain_chunks(std::string_view data) {
  std::vector<C> chunks;
  for (const std::string_view text : line_chunks(data)) {
    chunks.emplace_back();
    chunks.back().text = text;
  }
  return chunks;
}

/// Every chunk plain and the coordinates of all of them within validate_mesh's span.
template <class C>
bool all_plain(const std::vector<C>& chunks) {
  PlainBounds bounds;
  for (const C& c : chunks) {
    if (!c.plain) return false;
    bounds.add(c.bounds);
  }
  return bounds.within_span();
}

/// The mesh as the soup's, read straight into its arrays (soup.direct; nothing dropped).
inline void take_direct(Mesh&& mesh, Soup& soup) {
  soup.mesh = std::move(mesh);
  soup.direct_dropped = 0;
  soup.direct = true;
}

/// Calls f(p, end) at each line of `text`, p its first character that is not a space (the
/// line's '\n', or end, for a blank line).
template <class F>
void for_each_line(std::string_view text, F&& f) {
  const char* const end = text.data() + text.size();
  for (const char* p = text.data(); p < end;) {
    while (p < end && *p != '\n' && is_space(*p)) ++p;
    f(p, end);
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
    p = nl ? static_cast<const char*>(nl) + 1 : end;
  }
}

/// Runs body(k) for the n chunks, on every core when there are several. One chunk (a small
/// file) runs without touching the OpenMP runtime: its start-up may create a shared-memory file
/// (LLVM's libomp, in the sanitizer build), which a file-size limit turns into an abort
/// (bench/robustness, class 4) where a reader should only ever fail with an error.
template <class Body>
void for_each_chunk(std::size_t n, Body&& body) {
  if (n == 1) {
    body(std::size_t(0));
    return;
  }
  const auto count = static_cast<long>(n);
#pragma omp parallel for schedule(static, 1)
  for (long k = 0; k < count; ++k) body(static_cast<std::size_t>(k));
}

/// A cursor over the words of a chunk of lines; no allocation.
class PlainWords {
 public:
  explicit PlainWords(std::string_view text) : p_(text.data()), end_(text.data() + text.size()) {}
  bool done() const { return p_ >= end_; }
  /// Skips spaces up to the end of the line (not past it).
  void skip_spaces() {
    while (p_ < end_ && *p_ != '\n' && is_space(*p_)) ++p_;
  }
  /// At the end of a line ('\n' or the chunk's end) after spaces? Then moves past it. With
  /// `comments`, a '#' and what follows it count as the end of the line too.
  bool line_ends(bool comments) {
    skip_spaces();
    if (comments && p_ < end_ && *p_ == '#')
      skip_line();
    else if (p_ < end_ && *p_ != '\n')
      return false;
    else if (p_ < end_)
      ++p_;
    return true;
  }
  /// Moves past the rest of the line.
  void skip_line() {
    const void* nl = std::memchr(p_, '\n', static_cast<std::size_t>(end_ - p_));
    p_ = nl ? static_cast<const char*>(nl) + 1 : end_;
  }
  /// The next character of the line after spaces ('\0' at its end, and for a NUL byte).
  char peek() {
    skip_spaces();
    return p_ < end_ && *p_ != '\n' ? *p_ : '\0';
  }
  /// The next word as `key` (a word of that exact text)? Then moves past it.
  bool keyword(std::string_view key) {
    skip_spaces();
    const char* we = word_end();
    if (std::string_view(p_, static_cast<std::size_t>(we - p_)) != key) return false;
    p_ = we;
    return true;
  }
  /// The next word as a finite double, the whole word read by fast_float (what the general
  /// readers' parse_double gives it first; the forms it leaves to strtod are not plain).
  bool number(double& x) {
    skip_spaces();
    const char* const we = word_end();
    const auto r = fast_float::from_chars(p_, we, x);
    if (p_ == we || r.ec != std::errc() || r.ptr != we || !(x - x == 0)) return false;
    p_ = we;
    return true;
  }
  /// The next word as decimal digits only (at most 10) of a value in [lo, hi].
  bool index(long long lo, long long hi, long long& v) {
    skip_spaces();
    const char* const we = word_end();
    if (p_ == we || we - p_ > 10) return false;
    v = 0;
    for (const char* q = p_; q < we; ++q) {
      const unsigned d = static_cast<unsigned char>(*q) - unsigned('0');
      if (d > 9) return false;
      v = v * 10 + d;
    }
    if (v < lo || v > hi) return false;
    p_ = we;
    return true;
  }

 private:
  const char* word_end() const {
    const char* q = p_;
    while (q < end_ && !is_space(*q)) ++q;
    return q;
  }
  const char* p_;
  const char* end_;
};

}  // namespace msmesh::io_detail
