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

/// Parses a whole word as a number (strtod semantics: also nan/inf).
inline std::optional<double> parse_double(std::string_view word) {
  const std::string s(word);
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size()) return std::nullopt;
  return v;
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
