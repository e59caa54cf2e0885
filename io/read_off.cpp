// OFF reader: plain ascii files of vertices and triangles on every core (read_off_plain.h),
// the rest by CGAL's read_OFF behind guards. CGAL resizes its point and polygon arrays to the
// header counts before reading; in ascii C/N files it reads colour entries without bounds
// checks (short lines, a line without colour after one with, negative colour-map indices); ST
// files read texture entries through uninitialised indices (refused); it doubles the edge
// count in an int.
#include <CGAL/IO/OFF.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "msmesh/errors.h"
#include "read_common.h"
#include "read_off_plain.h"

namespace msmesh::io_detail {
namespace {

std::string fmt_number(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

struct OffHeader {
  bool binary = false, colors = false, normals = false, homogeneous = false;
  long long vertices = 0, faces = 0, edges = 0;
  std::size_t body_offset = 0;  ///< where CGAL's scanner continues after the header
};

/// Reads the OFF header exactly as CGAL's File_header_OFF does, so that `body_offset` is
/// where CGAL's scanner continues: keyword (after '#' comment lines), then either BINARY and
/// three big-endian int32 counts, or three integers read like `istream >> int`.
OffHeader parse_off_header(const std::string& path, std::string_view data) {
  std::size_t i = 0;
  auto skip_space = [&] {
    while (i < data.size() && std::isspace(static_cast<unsigned char>(data[i]))) ++i;
  };
  auto skip_space_and_comments = [&] {
    for (skip_space(); i < data.size() && data[i] == '#'; skip_space())
      while (i < data.size() && data[i] != '\n') ++i;
  };
  auto stream_integer = [&]() -> std::optional<long long> {  // istream >> int
    skip_space();
    const std::size_t start = i;
    if (i < data.size() && (data[i] == '-' || data[i] == '+')) ++i;
    const std::size_t digits = i;
    while (i < data.size() && std::isdigit(static_cast<unsigned char>(data[i]))) ++i;
    if (i == digits) return std::nullopt;
    const auto v = parse_integer(data.substr(start, i - start));
    if (!v || *v < INT_MIN || *v > INT_MAX) return std::nullopt;
    return v;
  };
  OffHeader h;
  skip_space_and_comments();
  const std::size_t key_start = i;
  while (i < data.size() && std::isalnum(static_cast<unsigned char>(data[i]))) ++i;
  const std::string_view key = data.substr(key_start, i - key_start);
  // CGAL's keyword loop (in.get(c) while alnum) also consumes the character after the
  // keyword: in "COFF#4 0 0" the '#' starts no comment and 4 is the vertex count (libFuzzer
  // found the difference, which let CGAL read colours past the end of short records).
  if (i < data.size()) ++i;
  if (key.size() < 3 || key.substr(key.size() - 3) != "OFF")
    throw IoError(path + ": not an OFF file (it starts with " + quote_word(data.substr(key_start, 12)) +
                  ", expected OFF, COFF, NOFF...)");
  std::string_view flags = key.substr(0, key.size() - 3);
  if (flags.substr(0, 2) == "ST")
    throw IoError(path + ": unsupported OFF variant " + quote_word(key) + " (texture coordinates are not read)");
  if (!flags.empty() && flags.front() == 'C') h.colors = true, flags.remove_prefix(1);
  if (!flags.empty() && flags.front() == 'N') h.normals = true, flags.remove_prefix(1);
  if (!flags.empty() && flags.front() == '4') h.homogeneous = true, flags.remove_prefix(1);
  if (!flags.empty())
    throw IoError(path + ": unsupported OFF variant " + quote_word(key) +
                  " (n-dimensional and other variants are not read)");
  skip_space_and_comments();
  if (data.substr(i, 6) == "BINARY") {
    h.binary = true;
    while (i < data.size() && data[i] != '\n') ++i;
    ++i;
    if (i + 12 > data.size()) throw IoError(path + ": truncated binary OFF header");
    auto be32 = [&](std::size_t at) {
      const auto* b = reinterpret_cast<const unsigned char*>(data.data() + at);
      return static_cast<std::int32_t>((std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) |
                                       (std::uint32_t(b[2]) << 8) | std::uint32_t(b[3]));
    };
    h.vertices = be32(i);
    h.faces = be32(i + 4);
    h.edges = be32(i + 8);
    h.body_offset = i + 12;
  } else {
    const auto nv = stream_integer(), nf = stream_integer(), ne = stream_integer();
    if (!nv || !nf || !ne)
      throw IoError(path + ": malformed OFF header: expected the vertex, face and edge counts after " +
                    quote_word(key));
    h.vertices = *nv;
    h.faces = *nf;
    h.edges = *ne;
    h.body_offset = i;
  }
  // CGAL doubles the edge count in an int.
  if (h.edges < 0 || h.edges > INT_MAX / 2)
    throw IoError(path + ": OFF header declares an invalid number of edges (" + std::to_string(h.edges) + ")");
  if (h.vertices < 0 || h.faces < 0)
    throw IoError(path + ": OFF header declares a negative number of vertices (" + std::to_string(h.vertices) +
                  ") or faces (" + std::to_string(h.faces) + ")");
  // CGAL resizes its arrays to these counts before reading: check them against the bytes
  // present (ascii: a vertex needs at least "0 0 0", a face at least one character).
  const double body = static_cast<double>(data.size() - h.body_offset);
  const double needed = h.binary ? 12.0 * h.vertices + 4.0 * h.faces : 5.0 * h.vertices + 1.0 * h.faces;
  if (needed > body)
    throw IoError(path + ": truncated OFF file: the header declares " + std::to_string(h.vertices) + " vertices and " +
                  std::to_string(h.faces) + " faces, but only " + std::to_string(data.size() - h.body_offset) +
                  " bytes follow it");
  return h;
}

/// The numbers CGAL's OFF scanner takes from one record: it reads `IO::iformat(double)`,
/// which is `istream >> double` here, until one fails (so "1-2" gives 1 and -2, and "nan"
/// or "1e999" end the record).
std::vector<double> cgal_off_entries(std::string_view line) {
  std::vector<double> entries;
  // Fast path for the usual records of plain digits (no sign, point or exponent), where
  // strtod and `istream >> double` agree.
  if (std::all_of(line.begin(), line.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) || std::isspace(static_cast<unsigned char>(c));
      })) {
    for (const std::string_view w : split_words(line)) entries.push_back(std::strtod(std::string(w).c_str(), nullptr));
    return entries;
  }
  std::istringstream in{std::string(line)};
  double d;
  while (in >> d) entries.push_back(d);
  return entries;
}

/// CGAL reads a colour as 3 or 4 entries or as an index into its 149-entry colour map, which
/// it clamps above but not below. It converts the components to unsigned char: integers as
/// they are, fractions times 255 (undefined behaviour outside [0, 256); found by libFuzzer).
bool valid_color_entries(const std::vector<double>& e, std::size_t first, std::size_t count) {
  if (count == 0) return true;
  if (count == 1) return e[first] >= 0 && e[first] < 1e9;
  if (count != 3 && count != 4) return false;
  bool integers = true;
  for (std::size_t c = 0; c < 3; ++c) integers = integers && std::floor(e[first + c]) == e[first + c];
  for (std::size_t c = 0; c < 3; ++c) {
    const double v = integers ? e[first + c] : e[first + c] * 255;
    if (!(v > -1 && v < 256)) return false;
  }
  return true;
}

/// Walks the body of an ascii OFF file record by record exactly as CGAL's scanner does (skip
/// whitespace and '#' lines, take the rest of the line up to '#') and returns the first
/// problem, or "". With `strict_entries` it also checks the colour and normal entries that
/// CGAL reads without bounds checks (a short line, or a line without colour after one with,
/// makes it read past the end of its entry array). Without `parse_vertices` the vertex
/// records are only counted, not checked.
std::string check_ascii_off(std::string_view data, const OffHeader& h, bool strict_entries,
                            bool parse_vertices = true) {
  std::size_t i = h.body_offset;
  std::size_t record_start = i;
  auto next_record = [&](std::string_view& line) {
    for (;;) {
      while (i < data.size() && std::isspace(static_cast<unsigned char>(data[i]))) ++i;
      if (i == data.size()) return false;
      if (data[i] != '#') break;
      while (i < data.size() && data[i] != '\n') ++i;
    }
    record_start = i;
    std::size_t end = data.find('\n', i);
    if (end == std::string_view::npos) end = data.size();
    line = data.substr(i, end - i);
    line = line.substr(0, line.find('#'));
    i = std::min(end + 1, data.size());
    return true;
  };
  auto where = [&](const char* what, long long k) {
    const auto line_no = std::count(data.begin(), data.begin() + static_cast<std::ptrdiff_t>(record_start), '\n') + 1;
    return std::string(what) + " " + std::to_string(k) + " (line " + std::to_string(line_no) + "): ";
  };
  const std::size_t H = h.homogeneous ? 1 : 0;
  const std::size_t base = 3 + H + (h.normals ? 3 + H : 0);
  // Once one record has a colour CGAL reads a colour from every later record.
  bool colored = false, plain = false;
  auto mixed = [&](bool has_color) {
    (has_color ? colored : plain) = true;
    return colored && plain;
  };
  std::string_view line;
  for (long long v = 0; v < h.vertices; ++v) {
    if (!next_record(line))
      return "truncated OFF file: it ends after " + std::to_string(v) + " of " + std::to_string(h.vertices) +
             " vertices";
    if (!parse_vertices) continue;
    const std::vector<double> e = cgal_off_entries(line);
    if (e.size() < 3) {
      const auto words = split_words(line);
      if (words.size() <= e.size()) return where("vertex", v) + "fewer than 3 coordinates";
      const auto x = parse_double(words[e.size()]);
      return where("vertex", v) + (x && !std::isfinite(*x) ? "non-finite coordinate " : "cannot read coordinate ") +
             quote_word(words[e.size()]);
    }
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(e[c])) return where("vertex", v) + "non-finite coordinate";
    if (strict_entries) {
      if (e.size() < base) return where("vertex", v) + "fewer entries than the OFF variant requires";
      if (h.colors && !valid_color_entries(e, base, e.size() - base))
        return where("vertex", v) + "a colour needs 3 or 4 entries in 0..255 or 0..1 (or one colour-map index)";
      if (h.colors && mixed(e.size() > base)) return where("vertex", v) + "some vertices have a colour, others not";
    }
  }
  colored = plain = false;
  for (long long f = 0; f < h.faces; ++f) {
    if (!next_record(line))
      return "truncated OFF file: it ends after " + std::to_string(f) + " of " + std::to_string(h.faces) + " faces";
    const std::vector<double> e = cgal_off_entries(line);
    if (e.empty() || !(e[0] >= 0) || e[0] != std::floor(e[0])) return where("face", f) + "invalid vertex count";
    const double count = e[0];
    if (static_cast<double>(e.size()) - 1 < count)
      return where("face", f) + "lists fewer than " + fmt_number(count) + " vertex indices";
    const std::size_t n = static_cast<std::size_t>(count);
    for (std::size_t k = 1; k <= n; ++k) {
      if (e[k] != std::floor(e[k]))  // CGAL would truncate 2.9 to 2
        return where("face", f) + "vertex index " + fmt_number(e[k]) + " is not an integer";
      if (!(e[k] >= 0 && e[k] < static_cast<double>(h.vertices)))
        return where("face", f) + "refers to vertex " + fmt_number(e[k]) + ", out of range [0, " +
               std::to_string(h.vertices) + ")";
    }
    if (strict_entries && h.colors) {
      if (!valid_color_entries(e, n + 1, e.size() - n - 1))
        return where("face", f) + "a colour needs 3 or 4 entries in 0..255 or 0..1 (or one colour-map index)";
      if (mixed(e.size() > n + 1)) return where("face", f) + "some faces have a colour, others not";
    }
  }
  return "";
}

}  // namespace

void read_off(const std::string& path, std::string_view data, Soup& soup) {
  data = without_utf8_bom(data);
  const OffHeader h = parse_off_header(path, data);
  const bool has_extras = h.colors || h.normals || h.homogeneous;
  // Vertices and triangles only, one per line: on every core, without CGAL.
  if (!h.binary && !has_extras && read_plain_off(data.substr(h.body_offset), h.vertices, h.faces, soup)) return;
  if (!h.binary) {
    // CGAL reads face records as doubles and converts the vertex count and the indices to
    // size_t unchecked (undefined behaviour for negative, huge or NaN entries; found by
    // libFuzzer), so the faces are always checked first; with extras, the vertices too.
    const std::string problem = check_ascii_off(data, h, has_extras, has_extras);
    if (!problem.empty()) throw IoError(path + ": " + problem);
  }
  MemoryStream in(data);
  std::vector<CGAL::IO::Color> colors;
  const bool ok =
      CGAL::IO::read_OFF(in, soup.points, soup.polygons,
                         CGAL::parameters::vertex_color_output_iterator(std::back_inserter(colors)).verbose(false));
  if (!ok) {
    std::string problem = h.binary ? "" : check_ascii_off(data, h, false);
    if (problem.empty())
      problem = h.binary ? "malformed or truncated binary OFF file" : "malformed OFF file (CGAL's reader failed)";
    throw IoError(path + ": " + problem);
  }
  soup.vertex_colors = std::move(colors);
  soup.notes.had_normals = h.normals;  // NOFF: recomputed (OFF output has no normals)
}

}  // namespace msmesh::io_detail
