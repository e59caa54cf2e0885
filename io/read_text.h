// Small text helpers for the readers' guards and diagnostics (internal to msmesh_io).
#pragma once
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
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

/// Splits `line` into `words` at any whitespace (space, \t, \r, \v, \f, \n); `words` is
/// reused so that a reader can split every line without allocating.
inline void split_words(std::string_view line, std::vector<std::string_view>& words) {
  words.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
}

inline std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  split_words(line, words);
  return words;
}

/// Parses a whole word as a number with `strto` (strtod semantics: also nan/inf), copying
/// short words to the stack rather than allocating.
template <typename T>
std::optional<T> parse_number(std::string_view word, T (*strto)(const char*, char**)) {
  if (word.empty()) return std::nullopt;
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
  char* end = nullptr;
  const T v = strto(s, &end);
  if (end != s + word.size()) return std::nullopt;
  return v;
}

inline std::optional<double> parse_double(std::string_view word) { return parse_number<double>(word, std::strtod); }

/// As parse_double, rounded to float first (as `istream >> float` reads a PLY float).
inline std::optional<double> parse_float(std::string_view word) {
  const auto x = parse_number<float>(word, std::strtof);
  return x ? std::optional<double>(*x) : std::nullopt;
}

inline std::optional<long long> parse_integer(std::string_view word) {
  const std::string s(word);
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE) return std::nullopt;
  return v;
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
  std::size_t i = !word.empty() && word[0] == '-' ? 1 : 0;
  if (i == word.size() || word.size() - i > 19) return std::nullopt;
  for (std::size_t k = i; k < word.size(); ++k)
    if (word[k] < '0' || word[k] > '9') return std::nullopt;
  const auto v = parse_integer(word);
  if (!v || *v < lo || *v > hi) return std::nullopt;
  return v;
}

inline std::string quote_word(std::string_view w) { return "'" + std::string(w.substr(0, 40)) + "'"; }

}  // namespace msmesh::io_detail
