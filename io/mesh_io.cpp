// Mesh reading through CGAL's polygon-soup readers (OBJ, OFF, PLY, STL). The only
// translation unit that includes CGAL's I/O headers.
//
// CGAL's readers trust their input more than a command-line tool can, so each format is
// checked here before CGAL sees it (found by reading CGAL 5.5's readers and by fuzzing them
// under AddressSanitizer):
//  - PLY: CGAL loops over the declared element counts and allocates each list from its
//    count before reading it (a 32-bit count of 2^31 allocates gigabytes); integer-typed
//    x/y/z or halfedge source/target make it dereference a null pointer; 'property' before
//    any 'element' indexes an empty vector; unknown property types are skipped silently,
//    which misaligns binary data.
//  - OFF: CGAL resizes its point and polygon arrays to the header counts before reading;
//    in ascii C/N files it reads colour entries without bounds checks (short lines, a line
//    without colour after one with, negative colour-map indices); ST files read texture
//    entries through uninitialised indices (refused); it doubles the edge count in an int.
//  - STL: CGAL merges identical points through std::map<Point, int>, which NaN breaks; a
//    binary file whose header starts with "solid" is first parsed as ascii, and a failed
//    ascii parse is retried as binary, which "succeeds" on files shorter than 84 bytes.
//  - OBJ: CGAL refuses any record it does not know (e.g. 'l') and lets index #V+1 and 0
//    through its own range check; it only says "false", so failures are diagnosed here.
// The whole file is read into memory once; CGAL parses it from there.
#include <CGAL/IO/Color.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <istream>
#include <optional>
#include <sstream>
#include <streambuf>
#include <string>
#include <string_view>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/io.h"
#include "msmesh/memory.h"

namespace msmesh {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;

// ---------------------------------------------------------------------------------------------
// Polygon soup with a guarded polygon type.

/// Thrown when a reader asks for a polygon with more corners than the file has bytes.
struct PolygonTooLarge {
  std::size_t size;
};

/// Upper bound on the corners of one polygon while a file is read (its size in bytes).
thread_local std::size_t t_polygon_limit = 0;

/// A polygon for CGAL's readers. Up to four corners are stored inline (no allocation per
/// face); longer polygons spill to the heap. CGAL sizes polygons from counts in the file (OFF)
/// before reading the indices, so resize refuses counts that cannot be genuine.
class Polygon {
 public:
  using value_type = std::size_t;
  using iterator = std::size_t*;
  using const_iterator = const std::size_t*;
  using size_type = std::size_t;
  using reference = std::size_t&;
  using const_reference = const std::size_t&;

  void resize(std::size_t n) {
    if (n > t_polygon_limit) throw PolygonTooLarge{n};
    if (n > kInline) {
      if (size_ <= kInline) heap_.assign(inline_, inline_ + size_);
      heap_.resize(n);
    } else if (size_ > kInline) {
      std::copy(heap_.begin(), heap_.begin() + static_cast<std::ptrdiff_t>(n), inline_);
      heap_.clear();
    }
    for (std::size_t i = size_; i < std::min(n, kInline); ++i) inline_[i] = 0;
    size_ = n;
  }
  void push_back(std::size_t v) {
    resize(size_ + 1);
    data()[size_ - 1] = v;
  }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::size_t* data() { return size_ > kInline ? heap_.data() : inline_; }
  const std::size_t* data() const { return size_ > kInline ? heap_.data() : inline_; }
  std::size_t& operator[](std::size_t i) { return data()[i]; }
  const std::size_t& operator[](std::size_t i) const { return data()[i]; }
  iterator begin() { return data(); }
  iterator end() { return data() + size_; }
  const_iterator begin() const { return data(); }
  const_iterator end() const { return data() + size_; }

 private:
  static constexpr std::size_t kInline = 4;
  std::size_t inline_[kInline] = {0, 0, 0, 0};
  std::size_t size_ = 0;
  std::vector<std::size_t> heap_;
};

struct Soup {
  std::vector<Point> points;
  std::vector<Polygon> polygons;
  std::vector<CGAL::IO::Color> vertex_colors;
  // Per-vertex attributes CGAL's soup readers drop, read by read_obj_attributes and
  // read_ply_attributes (empty when absent or not per-vertex).
  std::vector<std::array<double, 3>> rgb;      ///< OBJ "v x y z r g b" colours in [0,1]
  std::vector<std::array<double, 2>> uv;
  std::vector<std::array<double, 3>> normals;
  ReadNotes notes;
};

// ---------------------------------------------------------------------------------------------
// The file in memory, as an std::istream for CGAL.

class MemoryBuf : public std::streambuf {
 public:
  MemoryBuf(const char* data, std::size_t size) {
    char* p = const_cast<char*>(data);  // never written through: no put area
    setg(p, p, p + size);
  }

 protected:
  pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode which) override {
    if (!(which & std::ios_base::in)) return pos_type(off_type(-1));
    char* base = dir == std::ios_base::beg ? eback() : dir == std::ios_base::cur ? gptr() : egptr();
    const off_type target = (base - eback()) + off;
    if (target < 0 || target > egptr() - eback()) return pos_type(off_type(-1));
    setg(eback(), eback() + target, egptr());
    return pos_type(target);
  }
  pos_type seekpos(pos_type pos, std::ios_base::openmode which) override {
    return seekoff(off_type(pos), std::ios_base::beg, which);
  }
};

class MemoryStream : public std::istream {
 public:
  explicit MemoryStream(std::string_view data) : std::istream(nullptr), buf_(data.data(), data.size()) { rdbuf(&buf_); }

 private:
  MemoryBuf buf_;
};

std::string read_whole_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (!fs::exists(st)) throw IoError(path + ": no such file");
  if (fs::is_directory(st)) throw IoError(path + ": is a directory, not a mesh file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": cannot open file for reading: " + std::strerror(errno));
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw IoError(path + ": cannot determine the file size");
  in.seekg(0, std::ios::beg);
  // The file, CGAL's polygon soup and the mesh: about four times the size of a binary file.
  check_memory(4.0 * static_cast<double>(size), path + ": reading a " + std::to_string(size) + "-byte file");
  std::string data(static_cast<std::size_t>(size), '\0');
  if (size > 0 && !in.read(data.data(), size)) throw IoError(path + ": read error");
  return data;
}

// ---------------------------------------------------------------------------------------------
// Small text helpers for the guards and diagnostics.

/// Splits `data` into lines (without the '\n', with a trailing '\r' removed).
std::vector<std::string_view> split_lines(std::string_view data) {
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

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

/// Parses a whole word as a number (strtod semantics: also nan/inf).
std::optional<double> parse_double(std::string_view word) {
  const std::string s(word);
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size()) return std::nullopt;
  return v;
}

std::optional<long long> parse_integer(std::string_view word) {
  const std::string s(word);
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(s.c_str(), &end, 10);
  if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE) return std::nullopt;
  return v;
}

std::string quote_word(std::string_view w) { return "'" + std::string(w.substr(0, 40)) + "'"; }

std::string fmt_number(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

// ---------------------------------------------------------------------------------------------
// OBJ

bool obj_keyword_known_to_cgal(std::string_view s) {
  static const char* const known[] = {
      "v",     "vt",    "vn",     "f",        "vp",         "bevel",      "lod",      "ctech",   "c_interp",
      "usemap", "usemtl", "stech", "d_interp", "mtllib",     "shadow_obj", "trace_obj", "o",      "g",
      "s",     "p",     "cstype", "deg",      "step",       "bmat",       "con",      "curv",    "curv2",
      "surf",  "parm",  "trim",   "hole",     "scrv",       "sp",         "end",      "surf_1",  "q0_1",
      "q1_1",  "curv2d_1", "surf_2", "q0_2",  "q1_2",       "curv2d_2",   "bsp",      "bzp",     "cdc",
      "cdp",   "res"};
  for (const char* k : known)
    if (s == k) return true;
  return !s.empty() && s.front() == '#';
}

/// Why CGAL's OBJ reader refused the file (it only says false).
std::string diagnose_obj(std::string_view data) {
  const auto lines = split_lines(data);
  long long vertices = 0, faces = 0;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const auto w = split_words(lines[n]);
    if (w.empty()) continue;
    const std::string where = "line " + std::to_string(n + 1) + ": ";
    if (w[0] == "v") {
      if (w.size() < 4) return where + "vertex record with fewer than 3 coordinates";
      for (int c = 1; c <= 3; ++c) {
        const auto x = parse_double(w[c]);
        if (!x) return where + "cannot read vertex coordinate " + quote_word(w[c]);
        if (!std::isfinite(*x)) return where + "non-finite vertex coordinate " + quote_word(w[c]);
      }
      ++vertices;
    } else if (w[0] == "f") {
      ++faces;
    } else if (!obj_keyword_known_to_cgal(w[0])) {
      return where + "unsupported OBJ record " + quote_word(w[0]) +
             " (CGAL's OBJ reader accepts v, vt, vn, f, o, g, s, usemtl, mtllib and free-form records)";
    }
  }
  if (vertices == 0) return "no vertices ('v' records)";
  if (faces == 0) return "no faces ('f' records)";
  // Face indices: CGAL rejects those beyond the vertex count (1-based, negative = relative).
  long long seen = 0;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const auto w = split_words(lines[n]);
    if (w.empty()) continue;
    if (w[0] == "v") ++seen;
    if (w[0] != "f") continue;
    for (std::size_t k = 1; k < w.size(); ++k) {
      const auto idx = parse_integer(w[k].substr(0, w[k].find('/')));
      if (!idx) break;
      if (*idx > vertices || *idx == 0 || *idx < -seen)
        return "line " + std::to_string(n + 1) + ": face refers to vertex " + std::to_string(*idx) +
               ", but the file has " + std::to_string(vertices) + " vertices (indices are 1-based)";
    }
  }
  return "malformed OBJ file (CGAL's reader failed)";
}

/// `data` without the lines whose record CGAL's OBJ reader refuses (e.g. 'l' polylines).
std::string without_unknown_obj_records(std::string_view data) {
  std::string kept;
  kept.reserve(data.size());
  for (const std::string_view line : split_lines(data)) {
    const auto w = split_words(line);
    if (w.empty() || obj_keyword_known_to_cgal(w[0])) kept.append(line).push_back('\n');
  }
  return kept;
}

/// Vertex colours ("v x y z r g b"), texture coordinates and normals of an OBJ file as
/// per-vertex arrays. Per-corner values ("f v/vt/vn") become per-vertex when every corner of a
/// vertex names the same value; otherwise (seams) they are dropped and noted.
void read_obj_attributes(std::string_view data, Soup& soup) {
  const std::size_t nv = soup.points.size();
  std::vector<std::array<double, 3>> rgb, vn;
  std::vector<std::array<double, 2>> vt;
  bool all_rgb = true;
  std::size_t vertices = 0;
  // Per vertex: the vt / vn index its corners name (-1 none yet, -2 conflicting).
  std::vector<long long> vertex_vt(nv, -1), vertex_vn(nv, -1);
  bool corners_without_vt = false, corners_without_vn = false, any_vt = false, any_vn = false;
  auto resolve = [](long long idx, std::size_t count) -> long long {  // 1-based / negative -> 0-based
    if (idx > 0) return idx - 1;
    if (idx < 0) return static_cast<long long>(count) + idx;
    return -1;
  };
  auto assign = [](std::vector<long long>& slot, std::size_t v, long long idx) {
    if (slot[v] == -1) slot[v] = idx;
    else if (slot[v] != idx) slot[v] = -2;
  };
  for (const std::string_view line : split_lines(data)) {
    const auto w = split_words(line);
    if (w.empty()) continue;
    if (w[0] == "v") {
      ++vertices;
      if (w.size() >= 7) {
        std::array<double, 3> c{};
        for (int k = 0; k < 3; ++k) {
          const auto x = parse_double(w[4 + k]);
          if (!x || !std::isfinite(*x)) all_rgb = false;
          c[k] = x ? *x : 0.0;
        }
        rgb.push_back(c);
      } else {
        all_rgb = false;
      }
    } else if (w[0] == "vt" && w.size() >= 2) {
      const auto u = parse_double(w[1]);
      const auto v = w.size() >= 3 ? parse_double(w[2]) : std::optional<double>(0.0);
      vt.push_back({u ? *u : 0.0, v ? *v : 0.0});
    } else if (w[0] == "vn" && w.size() >= 4) {
      std::array<double, 3> n{};
      for (int k = 0; k < 3; ++k) {
        const auto x = parse_double(w[1 + k]);
        n[k] = x ? *x : 0.0;
      }
      vn.push_back(n);
    } else if (w[0] == "f") {
      for (std::size_t k = 1; k < w.size(); ++k) {
        const std::string_view corner = w[k];
        const std::size_t s1 = corner.find('/');
        const auto vi = parse_integer(corner.substr(0, s1));
        if (!vi) continue;
        const long long v = resolve(*vi, vertices);
        if (v < 0 || static_cast<std::size_t>(v) >= nv) continue;
        std::string_view t, n;
        if (s1 != std::string_view::npos) {
          const std::size_t s2 = corner.find('/', s1 + 1);
          t = corner.substr(s1 + 1, s2 == std::string_view::npos ? std::string_view::npos : s2 - s1 - 1);
          if (s2 != std::string_view::npos) n = corner.substr(s2 + 1);
        }
        const auto ti = t.empty() ? std::nullopt : parse_integer(t);
        const auto ni = n.empty() ? std::nullopt : parse_integer(n);
        if (ti) {
          any_vt = true;
          const long long r = resolve(*ti, vt.size());
          assign(vertex_vt, static_cast<std::size_t>(v), r >= 0 && static_cast<std::size_t>(r) < vt.size() ? r : -2);
        } else {
          corners_without_vt = true;
        }
        if (ni) {
          any_vn = true;
          const long long r = resolve(*ni, vn.size());
          assign(vertex_vn, static_cast<std::size_t>(v), r >= 0 && static_cast<std::size_t>(r) < vn.size() ? r : -2);
        } else {
          corners_without_vn = true;
        }
      }
    }
  }
  if (all_rgb && rgb.size() == nv && nv > 0) {
    double top = 0;
    for (const auto& c : rgb)
      for (double x : c) top = std::max(top, x);
    const double scale = top > 1.0 ? 1.0 / 255.0 : 1.0;  // some exporters write 0..255
    for (auto& c : rgb)
      for (double& x : c) x = std::clamp(x * scale, 0.0, 1.0);
    soup.rgb = std::move(rgb);
  }
  // A vertex no face refers to takes the texture coordinate / normal of the same index when
  // there is one (files that list them in step with the vertices), else 0.
  auto per_vertex = [&](std::vector<long long>& slot, std::size_t count) {
    for (std::size_t v = 0; v < nv; ++v)
      if (slot[v] == -1) slot[v] = v < count ? static_cast<long long>(v) : -3;
    return std::none_of(slot.begin(), slot.end(), [](long long x) { return x == -2; });
  };
  if (any_vt) {
    if (corners_without_vt || !per_vertex(vertex_vt, vt.size())) {
      soup.notes.uv_dropped = true;
    } else {
      soup.uv.resize(nv, {0.0, 0.0});
      for (std::size_t v = 0; v < nv; ++v)
        if (vertex_vt[v] >= 0) soup.uv[v] = vt[static_cast<std::size_t>(vertex_vt[v])];
      // Non-finite values (e.g. "vt 1e999 0") drop the attribute, as for PLY.
      for (const auto& t : soup.uv)
        if (!std::isfinite(t[0]) || !std::isfinite(t[1])) {
          soup.uv.clear();
          break;
        }
    }
  }
  if (any_vn) {
    soup.notes.had_normals = true;
    if (!corners_without_vn && per_vertex(vertex_vn, vn.size())) {
      soup.normals.resize(nv, {0.0, 0.0, 0.0});
      for (std::size_t v = 0; v < nv; ++v)
        if (vertex_vn[v] >= 0) soup.normals[v] = vn[static_cast<std::size_t>(vertex_vn[v])];
      // Non-finite normals are recomputed instead (libFuzzer found them passed through).
      for (const auto& n : soup.normals)
        if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2])) {
          soup.normals.clear();
          break;
        }
    }
  }
}

void read_obj(const std::string& path, std::string_view data, Soup& soup) {
  {
    std::size_t v = 0, f = 0;
    for (std::size_t at = 0; at < data.size();) {
      if (data.compare(at, 2, "v ") == 0) ++v;
      if (data.compare(at, 2, "f ") == 0) ++f;
      const std::size_t nl = data.find('\n', at);
      at = nl == std::string_view::npos ? data.size() : nl + 1;
    }
    soup.points.reserve(v);
    soup.polygons.reserve(f);
  }
  bool ok;
  {
    MemoryStream in(data);
    ok = CGAL::IO::read_OBJ(in, soup.points, soup.polygons, CGAL::parameters::verbose(false));
  }
  std::string filtered;
  if (!ok && diagnose_obj(data).find("unsupported OBJ record") != std::string::npos) {
    // Records that are not part of a surface (lines 'l', vertex colours 'vc', ...) are skipped.
    filtered = without_unknown_obj_records(data);
    data = filtered;
    soup = Soup();
    MemoryStream in(data);
    ok = CGAL::IO::read_OBJ(in, soup.points, soup.polygons, CGAL::parameters::verbose(false));
  }
  if (!ok) throw IoError(path + ": " + diagnose_obj(data));
  // CGAL's own index check lets index #V + 1 and index 0 through; report those 1-based.
  for (const Polygon& poly : soup.polygons)
    for (std::size_t idx : poly)
      if (idx >= soup.points.size()) throw IoError(path + ": " + diagnose_obj(data));
  read_obj_attributes(data, soup);
}

// ---------------------------------------------------------------------------------------------
// OFF

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
    throw IoError(path + ": unsupported OFF variant " + quote_word(key) + " (n-dimensional and other variants are not read)");
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
      throw IoError(path + ": malformed OFF header: expected the vertex, face and edge counts after " + quote_word(key));
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
  if (std::all_of(line.begin(), line.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || std::isspace(static_cast<unsigned char>(c)); })) {
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
std::string check_ascii_off(std::string_view data, const OffHeader& h, bool strict_entries, bool parse_vertices = true) {
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
      return "truncated OFF file: it ends after " + std::to_string(v) + " of " + std::to_string(h.vertices) + " vertices";
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
    for (std::size_t k = 1; k <= n; ++k)
      if (!(e[k] >= 0 && e[k] < static_cast<double>(h.vertices)))
        return where("face", f) + "refers to vertex " + fmt_number(e[k]) + ", out of range [0, " +
               std::to_string(h.vertices) + ")";
    if (strict_entries && h.colors) {
      if (!valid_color_entries(e, n + 1, e.size() - n - 1))
        return where("face", f) + "a colour needs 3 or 4 entries in 0..255 or 0..1 (or one colour-map index)";
      if (mixed(e.size() > n + 1)) return where("face", f) + "some faces have a colour, others not";
    }
  }
  return "";
}

void read_off(const std::string& path, std::string_view data, Soup& soup) {
  const OffHeader h = parse_off_header(path, data);
  const bool has_extras = h.colors || h.normals || h.homogeneous;
  if (!h.binary) {
    // CGAL reads face records as doubles and converts the vertex count and the indices to
    // size_t unchecked (undefined behaviour for negative, huge or NaN entries; found by
    // libFuzzer), so the faces are always checked first; with extras, the vertices too.
    const std::string problem = check_ascii_off(data, h, has_extras, has_extras);
    if (!problem.empty()) throw IoError(path + ": " + problem);
  }
  MemoryStream in(data);
  std::vector<CGAL::IO::Color> colors;
  const bool ok = CGAL::IO::read_OFF(
      in, soup.points, soup.polygons,
      CGAL::parameters::vertex_color_output_iterator(std::back_inserter(colors)).verbose(false));
  if (!ok) {
    std::string problem = h.binary ? "" : check_ascii_off(data, h, false);
    if (problem.empty()) problem = h.binary ? "malformed or truncated binary OFF file" : "malformed OFF file (CGAL's reader failed)";
    throw IoError(path + ": " + problem);
  }
  soup.vertex_colors = std::move(colors);
  soup.notes.had_normals = h.normals;  // NOFF: recomputed (OFF output has no normals)
}

// ---------------------------------------------------------------------------------------------
// PLY

struct PlyProperty {
  std::string name, type;  ///< scalar type, or the item type of a list
  bool is_list = false;
  std::string count_type;
  int size = 0;        ///< bytes of the scalar / of one list item
  int count_size = 0;  ///< bytes of a list's count
};

struct PlyElement {
  std::string name;
  unsigned long long count = 0;
  std::vector<PlyProperty> properties;
  const PlyProperty* find(const std::string& n) const {
    for (const auto& p : properties)
      if (p.name == n) return &p;
    return nullptr;
  }
};

struct PlyHeader {
  enum Format { Ascii, BinaryLittleEndian, BinaryBigEndian } format = Ascii;
  std::vector<PlyElement> elements;
  std::size_t body_offset = 0;
};

/// Byte size of a PLY scalar type, 0 when CGAL does not know it.
int ply_type_size(const std::string& t) {
  if (t == "char" || t == "int8" || t == "uchar" || t == "uint8") return 1;
  if (t == "short" || t == "int16" || t == "ushort" || t == "uint16") return 2;
  if (t == "int" || t == "int32" || t == "uint" || t == "uint32" || t == "float" || t == "float32") return 4;
  if (t == "double" || t == "float64") return 8;
  return 0;
}
bool ply_is_float(const std::string& t) { return t == "float" || t == "float32" || t == "double" || t == "float64"; }
bool ply_is_int32(const std::string& t) { return t == "int" || t == "int32" || t == "uint" || t == "uint32"; }

PlyHeader parse_ply_header(const std::string& path, std::string_view data) {
  auto fail = [&path](const std::string& what) { throw IoError(path + ": " + what); };
  PlyHeader h;
  std::size_t pos = 0, line_no = 0;
  bool ended = false;
  while (pos < data.size()) {
    std::size_t end = data.find('\n', pos);
    if (end == std::string_view::npos) end = data.size();
    const std::string_view line = data.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    const auto w = split_words(line);
    const std::string where = "PLY header line " + std::to_string(line_no) + ": ";
    if (line_no == 1) {
      if (w.empty() || w[0] != "ply") fail("not a PLY file (it does not start with 'ply')");
      continue;
    }
    if (line_no == 2) {
      if (w.size() < 3 || w[0] != "format") fail(where + "expected 'format <type> 1.0'");
      if (w[1] == "ascii")
        h.format = PlyHeader::Ascii;
      else if (w[1] == "binary_little_endian")
        h.format = PlyHeader::BinaryLittleEndian;
      else if (w[1] == "binary_big_endian")
        h.format = PlyHeader::BinaryBigEndian;
      else
        fail(where + "unknown format " + quote_word(w[1]));
      continue;
    }
    if (w.empty()) fail(where + "empty line");
    if (w[0] == "end_header") {
      ended = true;
      break;
    }
    if (w[0] == "element") {
      if (w.size() < 3) fail(where + "expected 'element <name> <count>'");
      const auto n = parse_integer(w[2]);
      if (!n || *n < 0) fail(where + "invalid element count " + quote_word(w[2]));
      h.elements.push_back({std::string(w[1]), static_cast<unsigned long long>(*n), {}});
    } else if (w[0] == "property") {
      if (h.elements.empty()) fail(where + "property before any element");
      PlyProperty p;
      if (w.size() >= 2 && w[1] == "list") {
        if (w.size() < 5) fail(where + "expected 'property list <count type> <item type> <name>'");
        p.is_list = true;
        p.count_type = std::string(w[2]);
        p.type = std::string(w[3]);
        p.name = std::string(w[4]);
        p.count_size = ply_type_size(p.count_type);
        p.size = ply_type_size(p.type);
        if (p.count_size == 0 || ply_is_float(p.count_type))
          fail(where + "unsupported list count type " + quote_word(p.count_type));
        if (p.size == 0) fail(where + "unsupported list item type " + quote_word(p.type));
      } else {
        if (w.size() < 3) fail(where + "expected 'property <type> <name>'");
        p.type = std::string(w[1]);
        p.name = std::string(w[2]);
        p.size = ply_type_size(p.type);
        if (p.size == 0) fail(where + "unsupported property type " + quote_word(p.type));
      }
      h.elements.back().properties.push_back(std::move(p));
    }
    // comment, obj_info and unknown keywords are ignored, as CGAL does
  }
  if (!ended) fail("truncated PLY header (no end_header line)");
  h.body_offset = std::min(pos, data.size());

  // What CGAL's reader assumes without checking.
  for (const PlyElement& e : h.elements) {
    if (e.name == "vertex" || e.name == "vertices") {
      for (const char* c : {"x", "y", "z"}) {
        const PlyProperty* p = e.find(c);
        if (!p) fail("PLY vertex element has no '" + std::string(c) + "' property");
        if (p->is_list || !ply_is_float(p->type))
          fail("PLY vertex property '" + std::string(c) + "' has type " + quote_word(p->type) +
               "; only float and double coordinates are read");
      }
    } else if (e.name == "face" || e.name == "faces") {
      const PlyProperty* p = e.find("vertex_indices");
      if (!p) p = e.find("vertex_index");
      if (!p || !p->is_list || !ply_is_int32(p->type))
        fail("PLY face element has no 'vertex_indices' list of int or uint");
    } else if (e.name == "halfedge") {
      for (const char* c : {"source", "target"}) {
        const PlyProperty* p = e.find(c);
        if (p && (p->is_list || (p->type != "uint" && p->type != "uint32")))
          fail("PLY halfedge property '" + std::string(c) + "' must be uint");
      }
    }
  }
  // The declared counts must fit in the bytes present: CGAL loops over them, and an element
  // without properties would make it loop (and, for vertices, allocate) without reading.
  const double body = static_cast<double>(data.size() - h.body_offset);
  double needed = 0;
  for (const PlyElement& e : h.elements) {
    double item = 0;
    for (const PlyProperty& p : e.properties)
      item += h.format == PlyHeader::Ascii ? 1.0 : (p.is_list ? p.count_size : p.size);
    needed += static_cast<double>(e.count) * std::max(item, 1.0);
  }
  if (needed > body) {
    std::ostringstream os;
    os << "truncated PLY file: the header declares";
    for (std::size_t k = 0; k < h.elements.size(); ++k)
      os << (k ? ", " : " ") << h.elements[k].count << " " << h.elements[k].name;
    os << " elements (at least " << static_cast<unsigned long long>(std::min(needed, 1e19)) << " bytes), but only "
       << data.size() - h.body_offset << " bytes follow the header";
    fail(os.str());
  }
  return h;
}

/// With 32-bit list counts CGAL allocates each list before reading it; walk the body and
/// check every count against the bytes that remain.
void check_ply_list_counts(const std::string& path, std::string_view data, const PlyHeader& h) {
  bool wide = false;
  for (const auto& e : h.elements)
    for (const auto& p : e.properties) wide = wide || (p.is_list && p.count_size == 4);
  if (!wide) return;
  auto fail = [&](const PlyElement& e, unsigned long long item, const std::string& what) {
    throw IoError(path + ": PLY " + e.name + " " + std::to_string(item) + ": " + what);
  };
  std::size_t pos = h.body_offset;
  const std::size_t size = data.size();
  if (h.format == PlyHeader::Ascii) {
    auto next_word = [&]() -> std::string_view {
      while (pos < size && std::isspace(static_cast<unsigned char>(data[pos]))) ++pos;
      const std::size_t start = pos;
      while (pos < size && !std::isspace(static_cast<unsigned char>(data[pos]))) ++pos;
      return data.substr(start, pos - start);
    };
    for (const auto& e : h.elements)
      for (unsigned long long j = 0; j < e.count; ++j)
        for (const auto& p : e.properties) {
          const std::string_view w = next_word();
          if (w.empty()) fail(e, j, "file ends early (truncated)");
          if (!p.is_list) continue;
          const auto n = parse_integer(w);
          if (!n || *n < 0 || static_cast<unsigned long long>(*n) > (size - pos) / 2 + 1)
            fail(e, j, "invalid list count " + quote_word(w));
          for (long long k = 0; k < *n; ++k)
            if (next_word().empty()) fail(e, j, "file ends early (truncated)");
        }
    return;
  }
  const bool big = h.format == PlyHeader::BinaryBigEndian;
  auto read_count = [&](int bytes) -> long long {
    unsigned long long v = 0;
    for (int b = 0; b < bytes; ++b) {
      const unsigned long long byte = static_cast<unsigned char>(data[pos + b]);
      v |= byte << (8 * (big ? bytes - 1 - b : b));
    }
    pos += bytes;
    return static_cast<long long>(v);  // signed types: a negative count only makes CGAL throw
  };
  for (const auto& e : h.elements)
    for (unsigned long long j = 0; j < e.count; ++j)
      for (const auto& p : e.properties) {
        if (!p.is_list) {
          if (size - pos < static_cast<std::size_t>(p.size)) fail(e, j, "file ends early (truncated)");
          pos += p.size;
          continue;
        }
        if (size - pos < static_cast<std::size_t>(p.count_size)) fail(e, j, "file ends early (truncated)");
        const long long n = read_count(p.count_size);
        const bool is_signed = p.count_type == "int" || p.count_type == "int32";
        const long long value = is_signed ? static_cast<std::int32_t>(n) : n;
        if (value < 0 || static_cast<unsigned long long>(value) > (size - pos) / static_cast<std::size_t>(p.size))
          fail(e, j, "list count " + std::to_string(value) + " exceeds the rest of the file (corrupt or truncated)");
        pos += static_cast<std::size_t>(value) * p.size;
      }
}

/// Texture coordinates (texture_u/texture_v, u/v, s/t, texture_s/texture_t) and normals
/// (nx/ny/nz) of the PLY vertex element, which CGAL's soup reader skips. Walks the body up to
/// the end of the vertex element; gives up silently (no attributes) if it runs out of data.
void read_ply_attributes(std::string_view data, const PlyHeader& h, Soup& soup) {
  std::size_t vertex_element = h.elements.size();
  for (std::size_t k = 0; k < h.elements.size(); ++k)
    if (h.elements[k].name == "vertex" || h.elements[k].name == "vertices") {
      vertex_element = k;
      break;
    }
  if (vertex_element == h.elements.size()) return;
  const PlyElement& ve = h.elements[vertex_element];
  static const char* const uv_names[][2] = {{"texture_u", "texture_v"}, {"u", "v"}, {"s", "t"}, {"texture_s", "texture_t"}};
  int iu = -1, iv = -1, inx = -1, iny = -1, inz = -1;
  for (const auto& names : uv_names) {
    int a = -1, b = -1;
    for (std::size_t p = 0; p < ve.properties.size(); ++p) {
      if (ve.properties[p].is_list) continue;
      if (ve.properties[p].name == names[0]) a = static_cast<int>(p);
      if (ve.properties[p].name == names[1]) b = static_cast<int>(p);
    }
    if (a >= 0 && b >= 0) {
      iu = a, iv = b;
      break;
    }
  }
  for (std::size_t p = 0; p < ve.properties.size(); ++p) {
    if (ve.properties[p].is_list) continue;
    if (ve.properties[p].name == "nx") inx = static_cast<int>(p);
    if (ve.properties[p].name == "ny") iny = static_cast<int>(p);
    if (ve.properties[p].name == "nz") inz = static_cast<int>(p);
  }
  const bool want_uv = iu >= 0, want_n = inx >= 0 && iny >= 0 && inz >= 0;
  if (!want_uv && !want_n) return;
  if (ve.count != soup.points.size()) return;

  const std::size_t size = data.size();
  std::size_t pos = h.body_offset;
  const bool ascii = h.format == PlyHeader::Ascii, big = h.format == PlyHeader::BinaryBigEndian;
  bool ok = true;
  auto next_word = [&]() -> std::string_view {
    while (pos < size && std::isspace(static_cast<unsigned char>(data[pos]))) ++pos;
    const std::size_t start = pos;
    while (pos < size && !std::isspace(static_cast<unsigned char>(data[pos]))) ++pos;
    return data.substr(start, pos - start);
  };
  auto read_value = [&](const std::string& type, int bytes) -> double {
    if (!ok) return 0;
    if (ascii) {
      const std::string_view w = next_word();
      const auto x = parse_double(w);
      if (!x) ok = false;
      return x ? *x : 0.0;
    }
    if (size - pos < static_cast<std::size_t>(bytes) || pos > size) {
      ok = false;
      return 0;
    }
    unsigned char b[8];
    for (int i = 0; i < bytes; ++i) b[big ? bytes - 1 - i : i] = static_cast<unsigned char>(data[pos + i]);
    pos += bytes;
    // b holds the value in little-endian order; assemble it for this (little-endian) host.
    std::uint64_t u = 0;
    for (int i = 0; i < bytes; ++i) u |= std::uint64_t(b[i]) << (8 * i);
    if (type == "float" || type == "float32") {
      float f;
      const std::uint32_t u32 = static_cast<std::uint32_t>(u);
      std::memcpy(&f, &u32, 4);
      return f;
    }
    if (type == "double" || type == "float64") {
      double d;
      std::memcpy(&d, &u, 8);
      return d;
    }
    const bool is_signed = type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" ||
                           type == "int32";
    if (is_signed) {
      const int shift = 64 - 8 * bytes;
      return static_cast<double>(static_cast<std::int64_t>(u << shift) >> shift);
    }
    return static_cast<double>(u);
  };
  std::vector<std::array<double, 2>> uv;
  std::vector<std::array<double, 3>> normals;
  if (want_uv) uv.resize(ve.count);
  if (want_n) normals.resize(ve.count);
  for (std::size_t k = 0; k <= vertex_element && ok; ++k) {
    const PlyElement& e = h.elements[k];
    for (unsigned long long j = 0; j < e.count && ok; ++j)
      for (std::size_t p = 0; p < e.properties.size() && ok; ++p) {
        const PlyProperty& prop = e.properties[p];
        if (prop.is_list) {
          const double n = read_value(prop.count_type, prop.count_size);
          if (!(n >= 0) || n > double(size)) ok = false;
          for (long long i = 0; ok && i < static_cast<long long>(n); ++i) read_value(prop.type, prop.size);
          continue;
        }
        const double x = read_value(prop.type, prop.size);
        if (k != vertex_element) continue;
        const int pi = static_cast<int>(p);
        if (pi == iu) uv[j][0] = x;
        if (pi == iv) uv[j][1] = x;
        if (want_n && pi == inx) normals[j][0] = x;  // nx alone (no ny, nz): no normals
        if (want_n && pi == iny) normals[j][1] = x;
        if (want_n && pi == inz) normals[j][2] = x;
      }
  }
  if (!ok) return;
  auto finite2 = [](const std::array<double, 2>& a) { return std::isfinite(a[0]) && std::isfinite(a[1]); };
  auto finite3 = [](const std::array<double, 3>& a) {
    return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
  };
  if (want_uv && std::all_of(uv.begin(), uv.end(), finite2)) soup.uv = std::move(uv);
  if (want_n) {
    soup.notes.had_normals = true;
    if (std::all_of(normals.begin(), normals.end(), finite3)) soup.normals = std::move(normals);
  }
}

void read_ply(const std::string& path, std::string_view data, Soup& soup) {
  const PlyHeader h = parse_ply_header(path, data);
  check_ply_list_counts(path, data, h);
  for (const PlyElement& e : h.elements) {  // counts are bounded by the file size (checked)
    if (e.name == "vertex" || e.name == "vertices") soup.points.reserve(soup.points.size() + e.count);
    if (e.name == "face" || e.name == "faces") soup.polygons.reserve(soup.polygons.size() + e.count);
  }
  MemoryStream in(data);
  // CGAL needs the vertex and face colour outputs to be of one type.
  std::vector<CGAL::IO::Color> colors, face_colors;
  const bool ok = CGAL::IO::read_PLY(in, soup.points, soup.polygons,
                                     CGAL::parameters::vertex_color_output_iterator(std::back_inserter(colors))
                                         .face_color_output_iterator(std::back_inserter(face_colors))
                                         .verbose(false));
  if (!ok && h.format == PlyHeader::Ascii) {
    // CGAL's ascii parse stops at words like "nan" or "inf"; say so.
    const auto words = split_words(data.substr(h.body_offset));
    for (const std::string_view w : words) {
      const auto x = parse_double(w);
      if (x && !std::isfinite(*x)) throw IoError(path + ": non-finite value " + quote_word(w) + " in the ascii PLY body");
    }
  }
  if (!ok)
    throw IoError(path + (h.format == PlyHeader::Ascii ? ": malformed or truncated ascii PLY body (CGAL's reader failed)"
                                                       : ": malformed or truncated binary PLY body (CGAL's reader failed)"));
  soup.vertex_colors = std::move(colors);
  read_ply_attributes(data, h, soup);
}

// ---------------------------------------------------------------------------------------------
// STL

void read_stl(const std::string& path, std::string_view data, Soup& soup) {
  std::size_t first = 0;
  while (first < data.size() && std::isspace(static_cast<unsigned char>(data[first]))) ++first;
  const bool says_solid = data.substr(first, 5) == "solid";
  bool binary = false;
  std::uint32_t triangles = 0;
  if (data.size() >= 84) {
    std::memcpy(&triangles, data.data() + 80, 4);  // little-endian on the hosts we build for
    binary = data.size() == 84 + 50 * static_cast<std::uint64_t>(triangles);
  }
  if (!binary && !says_solid) {
    if (data.size() < 84)
      throw IoError(path + ": not an STL file: no 'solid' keyword and too short (" + std::to_string(data.size()) +
                    " bytes) for a binary STL");
    throw IoError(path + ": truncated or corrupt binary STL: the header declares " + std::to_string(triangles) +
                  " triangles (" + std::to_string(84 + 50 * static_cast<std::uint64_t>(triangles)) +
                  " bytes), the file has " + std::to_string(data.size()) + " bytes");
  }
  std::string patched;
  if (binary) {
    // CGAL merges equal points through std::map<Point, int>; NaN breaks its ordering.
    for (std::uint32_t t = 0; t < triangles; ++t)
      for (int c = 3; c < 12; ++c) {
        float x;
        std::memcpy(&x, data.data() + 84 + 50 * std::size_t(t) + 4 * c, 4);
        if (!std::isfinite(x))
          throw IoError(path + ": triangle " + std::to_string(t) + " has a non-finite vertex coordinate");
      }
    if (says_solid) {
      // Many exporters start binary headers with "solid"; CGAL would parse them as ascii
      // first. Hide the keyword so that it reads the file as binary directly.
      patched.assign(data);
      patched[first] = 'S';
      data = patched;
    }
  }
  if (binary) {
    soup.polygons.reserve(triangles);
    soup.points.reserve(triangles / 2 + 3);  // after welding a closed mesh has about F/2 vertices
  }
  if (!binary && data.find("endsolid") == std::string_view::npos)
    throw IoError(path + ": truncated ascii STL (no 'endsolid')");
  MemoryStream in(data);
  bool ok = CGAL::IO::read_STL(in, soup.points, soup.polygons, CGAL::parameters::verbose(false));
  if (ok && !binary) {
    // When its ascii parse fails CGAL retries as binary, which "succeeds" on files shorter
    // than a binary header; the facet count tells.
    std::size_t facets = 0;
    for (std::size_t at = data.find("endfacet"); at != std::string_view::npos; at = data.find("endfacet", at + 8)) ++facets;
    ok = facets == soup.polygons.size();
  }
  if (!ok)
    throw IoError(path + (binary ? ": malformed binary STL (CGAL's reader failed)"
                                 : ": malformed or truncated ascii STL (CGAL's reader failed)"));
}

// ---------------------------------------------------------------------------------------------
// Soup to mesh

Mesh soup_to_mesh(const std::string& path, const Soup& soup, Eigen::Index* dropped_degenerate) {
  const std::size_t nv = soup.points.size();
  if (nv == 0) throw IoError(path + ": the file contains no vertices");
  if (nv > static_cast<std::size_t>(INT_MAX)) throw IoError(path + ": too many vertices (" + std::to_string(nv) + ")");
  Mesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(nv), 3);
  for (std::size_t i = 0; i < nv; ++i)
    for (int c = 0; c < 3; ++c) mesh.V(static_cast<Eigen::Index>(i), c) = soup.points[i][c];

  std::size_t triangles = 0;
  for (std::size_t p = 0; p < soup.polygons.size(); ++p) {
    const Polygon& poly = soup.polygons[p];
    for (std::size_t idx : poly)
      if (idx >= nv)
        throw IoError(path + ": face " + std::to_string(p) + " refers to vertex " + std::to_string(idx) +
                      " (0-based), out of range [0, " + std::to_string(nv) + ")");
    if (poly.size() >= 3) triangles += poly.size() - 2;
  }
  // Polygons are fan-triangulated; triangles repeating a vertex are dropped.
  Eigen::Index dropped = 0;
  mesh.F.resize(static_cast<Eigen::Index>(triangles), 3);
  Eigen::Index f = 0;
  for (const Polygon& poly : soup.polygons) {
    if (poly.size() < 3) {
      ++dropped;
      continue;
    }
    for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
      const int a = static_cast<int>(poly[0]), b = static_cast<int>(poly[k]), c = static_cast<int>(poly[k + 1]);
      if (a == b || b == c || a == c) {
        ++dropped;
        continue;
      }
      mesh.F.row(f++) << a, b, c;
    }
  }
  mesh.F.conservativeResize(f, 3);
  if (f == 0)
    throw IoError(path + (dropped > 0 ? ": all " + std::to_string(dropped) + " faces are degenerate (repeat a vertex)"
                                      : std::string(": the file contains no faces")));
  try {
    validate_mesh(mesh.V, mesh.F, path);
  } catch (const InvalidInput& e) {
    throw IoError(e.what());
  }
  if (soup.vertex_colors.size() == nv) {
    mesh.vertex_colors.resize(static_cast<Eigen::Index>(nv), 3);
    for (std::size_t i = 0; i < nv; ++i) {
      const auto& col = soup.vertex_colors[i];
      mesh.vertex_colors.row(static_cast<Eigen::Index>(i)) << col.red() / 255.0, col.green() / 255.0, col.blue() / 255.0;
    }
  }
  auto fill = [&](Eigen::MatrixXd& M, const auto& rows) {
    if (rows.size() != nv) return;
    const Eigen::Index cols = static_cast<Eigen::Index>(rows.front().size());
    M.resize(static_cast<Eigen::Index>(nv), cols);
    for (std::size_t i = 0; i < nv; ++i)
      for (Eigen::Index c = 0; c < cols; ++c) M(static_cast<Eigen::Index>(i), c) = rows[i][static_cast<std::size_t>(c)];
  };
  if (mesh.vertex_colors.size() == 0) fill(mesh.vertex_colors, soup.rgb);
  fill(mesh.uv, soup.uv);
  fill(mesh.vertex_normals, soup.normals);
  // Normals that are not per-vertex (split at creases) are replaced by recomputed ones.
  if (soup.notes.had_normals && mesh.vertex_normals.size() == 0 && soup.normals.empty()) {
    mesh.vertex_normals = vertex_normals(mesh.V, mesh.F);
    // Coordinates near the double range (e.g. 1e308, found by libFuzzer) overflow the cross
    // products: no normals rather than non-finite ones.
    if (!mesh.vertex_normals.allFinite()) mesh.vertex_normals.resize(0, 3);
  }
  if (dropped_degenerate) *dropped_degenerate = dropped;
  return mesh;
}

}  // namespace

std::string mesh_format_from_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl") return ext.substr(1);
  throw IoError(path + ": unknown mesh format " + (ext.empty() ? std::string("(no extension)") : quote_word(ext)) +
                "; expected .obj, .off, .ply or .stl");
}

Mesh read_mesh(const std::string& path, Eigen::Index* dropped_degenerate) {
  ReadNotes notes;
  Mesh mesh = read_mesh(path, notes);
  if (dropped_degenerate) *dropped_degenerate = notes.dropped_degenerate;
  return mesh;
}

Mesh read_mesh(const std::string& path, ReadNotes& notes) {
  const std::string format = mesh_format_from_path(path);
  const std::string data = read_whole_file(path);
  return read_mesh_from_memory(data, format, path, notes);
}

Mesh read_mesh_from_memory(std::string_view data, const std::string& format, const std::string& path,
                           Eigen::Index* dropped_degenerate) {
  ReadNotes notes;
  Mesh mesh = read_mesh_from_memory(data, format, path, notes);
  if (dropped_degenerate) *dropped_degenerate = notes.dropped_degenerate;
  return mesh;
}

Mesh read_mesh_from_memory(std::string_view data, const std::string& format, const std::string& path,
                           ReadNotes& notes) {
  if (format != "obj" && format != "off" && format != "ply" && format != "stl")
    throw IoError(path + ": unknown mesh format " + quote_word(format) + "; expected obj, off, ply or stl");
  if (data.empty()) throw IoError(path + ": empty file");
  Soup soup;
  t_polygon_limit = data.size();
  try {
    if (format == "obj")
      read_obj(path, data, soup);
    else if (format == "off")
      read_off(path, data, soup);
    else if (format == "ply")
      read_ply(path, data, soup);
    else
      read_stl(path, data, soup);
  } catch (const IoError&) {
    throw;
  } catch (const PolygonTooLarge& e) {
    throw IoError(path + ": a face declares " + std::to_string(e.size) +
                  " vertices, more than the file can hold (corrupt file)");
  } catch (const std::bad_alloc&) {
    throw IoError(path + ": out of memory while reading (corrupt counts in the file?)");
  } catch (const std::length_error&) {
    throw IoError(path + ": corrupt file (a count in it is out of range)");
  } catch (const std::exception& e) {
    throw IoError(path + ": reading failed: " + e.what());
  }
  Mesh mesh = soup_to_mesh(path, soup, &notes.dropped_degenerate);
  notes.had_normals = soup.notes.had_normals;
  notes.uv_dropped = soup.notes.uv_dropped;
  return mesh;
}

}  // namespace msmesh
