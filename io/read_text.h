// Small text helpers for the readers' guards and diagnostics (internal to msmesh_io).
#pragma once
#include <fast_float/fast_float.h>

#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace msmesh::io_detail {

/// Splits `data` into lines (without the '\n', with a trailing '\r' removed).
inline std::vector<std::string_view> split_lines(std::string_view data) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start < data.size()) {
    std::size_t end = data.find('\n', start);
    if (end == std::string_view::npos) end = data.size();
    std::string_view line = data.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

/// The C locale's std::isspace (space, \t, \n, \v, \f, \r), without the locale lookup.
inline bool is_space(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }

/// Splits `line` into `words` at any whitespace (space, \t, \r, \v, \f, \n); `words` is
/// reused so that a reader can split every line without allocating.
inline void split_words(std::string_view line, std::vector<std::string_view>& words) {
  words.clear();
  const char* p = line.data();
  const char* const end = p + line.size();
  while (p < end) {
    while (p < end && is_space(*p)) ++p;
    const char* const start = p;
    while (p < end && !is_space(*p)) ++p;
    if (p > start) words.emplace_back(start, static_cast<std::size_t>(p - start));
  }
}

inline std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  split_words(line, words);
  return words;
}

/// Calls f(s) with `word` as a NUL-terminated string, copied to the stack when short (no
/// allocation on the readers' paths).
template <class F>
auto with_c_string(std::string_view word, F&& f) {
  char buf[64];
  std::string heap;
  const char* s = buf;
  if (word.size() < sizeof buf) {
    word.copy(buf, word.size());
    buf[word.size()] = '\0';
  } else {
    heap.assign(word);
    s = heap.c_str();
  }
  return f(s);
}

/// Parses a whole word as a number with `strto` (strtod semantics: also nan/inf).
template <typename T>
std::optional<T> parse_number(std::string_view word, T (*strto)(const char*, char**)) {
  if (word.empty()) return std::nullopt;
  return with_c_string(word, [&](const char* s) -> std::optional<T> {
    char* end = nullptr;
    const T v = strto(s, &end);
    if (end != s + word.size()) return std::nullopt;
    return v;
  });
}

/// A whole word as a double, correctly rounded (as strtod): fast_float for the usual decimal
/// forms, strtod itself for what fast_float leaves (hexadecimal, a leading '+', "nan(...)").
inline std::optional<double> parse_double(std::string_view word) {
  double v = 0;
  const auto r = fast_float::from_chars(word.data(), word.data() + word.size(), v);
  if (r.ec == std::errc() && r.ptr == word.data() + word.size() && !word.empty()) return v;
  return parse_number<double>(word, std::strtod);
}

/// As parse_double, rounded to float first (as `istream >> float` reads a PLY float).
inline std::optional<double> parse_float(std::string_view word) {
  float v = 0;
  const auto r = fast_float::from_chars(word.data(), word.data() + word.size(), v);
  if (r.ec == std::errc() && r.ptr == word.data() + word.size() && !word.empty()) return static_cast<double>(v);
  const auto x = parse_number<float>(word, std::strtof);
  return x ? std::optional<double>(*x) : std::nullopt;
}

inline std::optional<long long> parse_integer(std::string_view word) {
  if (word.empty()) return std::nullopt;
  return with_c_string(word, [&](const char* s) -> std::optional<long long> {
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(s, &end, 10);
    if (end != s + word.size() || errno == ERANGE) return std::nullopt;
    return v;
  });
}

/// Skips a UTF-8 byte-order mark at the start of a text file (some Windows exporters write one).
inline std::string_view without_utf8_bom(std::string_view data) {
  if (data.substr(0, 3) == "\xEF\xBB\xBF") data.remove_prefix(3);
  return data;
}

/// Parses a whole word as an integer in [lo, hi]: an optional '-' and decimal digits only
/// (no '+', point, exponent or spaces), so that "2.9", "1e3" or "99999999999" are refused
/// rather than read as a different number.
inline std::optional<long long> parse_strict_integer(std::string_view word, long long lo, long long hi) {
  const bool negative = !word.empty() && word[0] == '-';
  const std::size_t i = negative ? 1 : 0;
  if (i == word.size() || word.size() - i > 19) return std::nullopt;
  std::uint64_t u = 0;  // 19 digits fit in 64 bits unsigned
  for (std::size_t k = i; k < word.size(); ++k) {
    const unsigned d = static_cast<unsigned char>(word[k]) - unsigned('0');
    if (d > 9) return std::nullopt;
    u = u * 10 + d;
  }
  // The range of long long (as strtoll refuses with ERANGE), then [lo, hi].
  constexpr std::uint64_t kMax = static_cast<std::uint64_t>(LLONG_MAX);
  if (u > kMax + (negative ? 1 : 0)) return std::nullopt;
  const long long v = negative ? static_cast<long long>(0 - u) : static_cast<long long>(u);
  if (v < lo || v > hi) return std::nullopt;
  return v;
}

inline std::string quote_word(std::string_view w) { return "'" + std::string(w.substr(0, 40)) + "'"; }

}  // namespace msmesh::io_detail
