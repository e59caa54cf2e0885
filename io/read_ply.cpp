// PLY reader (CGAL's read_PLY behind guards). CGAL loops over the declared element counts and
// allocates each list from its count before reading it (a 32-bit count of 2^31 allocates
// gigabytes); integer-typed x/y/z or halfedge source/target make it dereference a null
// pointer; 'property' before any 'element' indexes an empty vector; unknown property types
// are skipped silently, which misaligns binary data. Texture coordinates and normals, which
// CGAL's soup reader skips, are read here too.
#include <CGAL/IO/PLY.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "msmesh/errors.h"
#include "read_common.h"

namespace msmesh::io_detail {
namespace {

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

}  // namespace

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

}  // namespace msmesh::io_detail
