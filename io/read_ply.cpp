// PLY reader (our own): the header parsed and checked (element counts against the bytes
// present, known property types, float or double x/y/z, a vertex_indices list of integers),
// then the body read value by value as its declared type (PlyBodyReader): ascii, binary little
// and big endian alike; list count and index types char, uchar, short, ushort, int, uint; an
// ascii value must be a number of its type (a uchar colour of 300 is refused, not wrapped to
// 44). Vertex colours (uchar red/green/blue or r/g/b), texture coordinates and normals are read
// with the points. A UTF-8 byte-order mark before "ply" is skipped.
//
// Until this reader, CGAL's read_PLY was used behind guards: it read faces only with int or
// uint indices, wrapped ascii colours to a byte and allocated lists from their counts.
#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "msmesh/errors.h"
#include "read_common.h"

namespace msmesh::io_detail {
namespace {

/// A PLY scalar type as the body reader needs it (decoded once from its name).
struct PlyType {
  std::string name;
  int bytes = 0;
  bool is_float = false;
  long long lo = 0, hi = 0;  ///< range of an integer type
};

struct PlyProperty {
  std::string name, type;  ///< scalar type, or the item type of a list
  bool is_list = false;
  std::string count_type;
  int size = 0;        ///< bytes of the scalar / of one list item
  int count_size = 0;  ///< bytes of a list's count
  PlyType item, count;
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

PlyType ply_type(const std::string& t) {
  PlyType r;
  r.name = t;
  r.bytes = ply_type_size(t);
  r.is_float = ply_is_float(t);
  const bool is_signed = t == "char" || t == "int8" || t == "short" || t == "int16" || t == "int" || t == "int32";
  if (!r.is_float && r.bytes > 0) {
    r.hi = is_signed ? (1LL << (8 * r.bytes - 1)) - 1 : (1LL << (8 * r.bytes)) - 1;
    r.lo = is_signed ? -r.hi - 1 : 0;
  }
  return r;
}

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
      p.item = ply_type(p.type);
      p.count = ply_type(p.count_type);
      h.elements.back().properties.push_back(std::move(p));
    }
    // comment, obj_info and unknown keywords are ignored, as CGAL does
  }
  if (!ended) fail("truncated PLY header (no end_header line)");
  h.body_offset = std::min(pos, data.size());

  // What the body reader needs.
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
      if (!p || !p->is_list || ply_is_float(p->type)) fail("PLY face element has no 'vertex_indices' list of integers");
    }
  }
  // The declared counts must fit in the bytes present (the body reader reserves from them, and
  // an element without properties would be looped over without reading).
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

/// Reads the values of a PLY body one at a time, each as its declared type: binary values
/// from their bytes in the file's byte order, ascii words through read_text.h's strict
/// parsers (an integer type takes a whole integer in its range, so 300 is no uchar and 2.9 no
/// int; float takes the nearest float, as CGAL read it). Errors name the element, its number
/// and, for ascii, the line.
class PlyBodyReader {
 public:
  PlyBodyReader(const std::string& path, std::string_view data, const PlyHeader& h)
      : path_(path), data_(data), pos_(h.body_offset), format_(h.format) {
    line_ =
        1 + static_cast<std::size_t>(std::count(data.begin(), data.begin() + static_cast<std::ptrdiff_t>(pos_), '\n'));
  }

  void at(const PlyElement& e, unsigned long long item) { element_ = &e, item_ = item; }

  /// The next `n` bytes of a binary body as they are, or nullptr (nothing consumed) when fewer remain.
  const char* take(std::size_t n) {
    if (data_.size() - pos_ < n) return nullptr;
    pos_ += n;
    return data_.data() + pos_ - n;
  }
  /// Whether binary values can be taken as they are (a little-endian file on a little-endian host).
  bool native() const { return format_ == PlyHeader::BinaryLittleEndian && little_host_; }

  [[noreturn]] void fail(const std::string& what) const {
    std::string where = "PLY " + element_->name + " " + std::to_string(item_);
    if (format_ == PlyHeader::Ascii) where += " (line " + std::to_string(line_) + ")";
    throw IoError(path_ + ": " + where + ": " + what);
  }

  /// A value of integer type `t` (list counts and indices, colours, other properties).
  long long integer(const PlyType& t, const std::string& name) {
    if (t.is_float) return static_cast<long long>(real(t, name));
    if (format_ == PlyHeader::Ascii) return ascii_integer(t, name);
    const std::uint64_t u = bytes(t.bytes);
    const int shift = 64 - 8 * t.bytes;
    return t.lo < 0 ? static_cast<std::int64_t>(u << shift) >> shift : static_cast<long long>(u);
  }

  /// A value of any type as a double.
  double real(const PlyType& t, const std::string& name) {
    if (!t.is_float) return static_cast<double>(integer(t, name));
    if (format_ == PlyHeader::Ascii) return ascii_real(t, name);
    if (t.bytes == 4) {
      float f;
      const std::uint32_t u32 = static_cast<std::uint32_t>(bytes(4));
      std::memcpy(&f, &u32, 4);
      return f;
    }
    const std::uint64_t u = bytes(8);
    double d;
    std::memcpy(&d, &u, 8);
    return d;
  }

  /// A list's count, checked against the bytes that remain (each item needs at least one).
  std::size_t list_count(const PlyProperty& p) {
    const long long n = integer(p.count, p.name);
    const std::size_t item = format_ == PlyHeader::Ascii ? 2 : static_cast<std::size_t>(p.size);
    if (n < 0 || static_cast<unsigned long long>(n) > (data_.size() - pos_) / item + 1)
      fail("list count " + std::to_string(n) + " exceeds the rest of the file (corrupt or truncated)");
    return static_cast<std::size_t>(n);
  }

 private:
  // The ascii values and the failures out of line, so that the binary paths above stay small
  // enough to be inlined into the reader's loop.
  [[gnu::noinline]] long long ascii_integer(const PlyType& t, const std::string& name) {
    const std::string_view w = word();
    const auto v = parse_strict_integer(w, t.lo, t.hi);
    if (!v)
      fail(quote_word(name) + " value " + quote_word(w) + " is not a " + t.name + " (an integer in " +
           std::to_string(t.lo) + ".." + std::to_string(t.hi) + ")");
    return *v;
  }
  [[gnu::noinline]] double ascii_real(const PlyType& t, const std::string& name) {
    const std::string_view w = word();
    const auto x = t.bytes == 4 ? parse_float(w) : parse_double(w);
    if (!x) fail("cannot read " + quote_word(name) + " value " + quote_word(w));
    return *x;
  }
  [[noreturn, gnu::noinline]] void truncated() const { fail("the file ends early (truncated PLY file)"); }

  std::string_view word() {
    while (pos_ < data_.size() && is_space(data_[pos_])) line_ += data_[pos_++] == '\n';
    const std::size_t start = pos_;
    while (pos_ < data_.size() && !is_space(data_[pos_])) ++pos_;
    if (pos_ == start) truncated();
    return data_.substr(start, pos_ - start);
  }
  std::uint64_t bytes(int n) {
    if (data_.size() - pos_ < static_cast<std::size_t>(n)) truncated();
    std::uint64_t u = 0;
    const bool big = format_ == PlyHeader::BinaryBigEndian;
    if (!big && little_host_) {  // the usual case: the bytes as they are
      std::memcpy(&u, data_.data() + pos_, static_cast<std::size_t>(n));
      pos_ += static_cast<std::size_t>(n);
      return u;
    }
    for (int i = 0; i < n; ++i)
      u |= std::uint64_t(static_cast<unsigned char>(data_[pos_ + static_cast<std::size_t>(i)]))
           << (8 * (big ? n - 1 - i : i));
    pos_ += static_cast<std::size_t>(n);
    return u;
  }

  const std::string& path_;
  std::string_view data_;
  std::size_t pos_, line_ = 1;
  PlyHeader::Format format_;
  const bool little_host_ = [] {
    const std::uint16_t one = 1;
    unsigned char first = 0;
    std::memcpy(&first, &one, 1);
    return first == 1;
  }();
  const PlyElement* element_ = nullptr;
  unsigned long long item_ = 0;
};

ScalarType scalar_type_of(const std::string& t) {
  if (t == "char" || t == "int8") return ScalarType::Int8;
  if (t == "uchar" || t == "uint8") return ScalarType::UInt8;
  if (t == "short" || t == "int16") return ScalarType::Int16;
  if (t == "ushort" || t == "uint16") return ScalarType::UInt16;
  if (t == "int" || t == "int32") return ScalarType::Int32;
  if (t == "uint" || t == "uint32") return ScalarType::UInt32;
  if (t == "float" || t == "float32") return ScalarType::Float32;
  return ScalarType::Float64;
}

/// Index of the property named `name` (not a list) in `e`, or -1.
int find_scalar(const PlyElement& e, const char* name) {
  for (std::size_t p = 0; p < e.properties.size(); ++p)
    if (!e.properties[p].is_list && e.properties[p].name == name) return static_cast<int>(p);
  return -1;
}

/// The usual binary file read straight into the mesh (soup.mesh, soup.direct): binary little
/// endian on a little-endian host, one vertex element of x, y, z only (float or double) followed
/// by one face element of a vertex_indices list only (uchar or char count, int or uint items),
/// every face a triangle of three distinct vertices in range, every coordinate finite and within
/// validate_mesh's span. One pass over each element, fixed records decoded by offset, the checks
/// accumulated without branches. Returns false, `soup` unchanged, for any other file: the general
/// reader below reads it, with its errors and notes.
bool read_binary_triangles(std::string_view data, const PlyHeader& h, bool native, Soup& soup) {
  if (!native || h.elements.size() != 2) return false;
  const PlyElement& ve = h.elements[0];
  const PlyElement& fe = h.elements[1];
  if (!(ve.name == "vertex" || ve.name == "vertices") || !(fe.name == "face" || fe.name == "faces")) return false;
  if (ve.properties.size() != 3 || fe.properties.size() != 1) return false;
  std::size_t offset[3] = {0, 0, 0}, record = 0;
  bool single[3] = {false, false, false};
  for (const PlyProperty& p : ve.properties) {  // x, y and z each once (parse_ply_header checked)
    const int c = p.name == "x" ? 0 : p.name == "y" ? 1 : p.name == "z" ? 2 : -1;
    if (c < 0 || p.is_list) return false;
    offset[c] = record;
    single[c] = p.size == 4;
    record += static_cast<std::size_t>(p.size);
  }
  const PlyProperty& list = fe.properties[0];
  if (!list.is_list || list.count_size != 1 || list.size != 4 || list.item.is_float) return false;
  const std::size_t nv = ve.count, nf = fe.count;
  if (nv == 0 || nf == 0 || nv > static_cast<std::size_t>(INT_MAX)) return false;
  constexpr std::size_t kFaceRecord = 1 + 3 * 4;
  if ((data.size() - h.body_offset) / kFaceRecord < nf ||
      (data.size() - h.body_offset - kFaceRecord * nf) / record < nv)
    return false;
  Mesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(nv), 3);
  double* const col[3] = {mesh.V.data(), mesh.V.data() + nv, mesh.V.data() + 2 * nv};
  const char* b = data.data() + h.body_offset;
  bool finite = true;
  double lo[3], hi[3];
  for (int c = 0; c < 3; ++c) lo[c] = hi[c] = 0;
  auto vertices = [&](auto as_float) {
    constexpr std::size_t kBytes = decltype(as_float)::value ? 4 : 8;
    for (int c = 0; c < 3; ++c) {
      // The first value starts the range, so that it need not hold 0.
      double v0;
      if constexpr (kBytes == 4) {
        float f;
        std::memcpy(&f, b + offset[c], 4);
        v0 = f;
      } else {
        std::memcpy(&v0, b + offset[c], 8);
      }
      lo[c] = hi[c] = v0;
    }
    for (std::size_t i = 0; i < nv; ++i, b += record)
      for (int c = 0; c < 3; ++c) {
        double v;
        if constexpr (kBytes == 4) {
          float f;
          std::memcpy(&f, b + offset[c], 4);
          v = f;
        } else {
          std::memcpy(&v, b + offset[c], 8);
        }
        col[c][i] = v;
        finite &= v - v == 0;  // false for NaN and infinities
        lo[c] = std::min(lo[c], v);
        hi[c] = std::max(hi[c], v);
      }
  };
  if (single[0] && single[1] && single[2])
    vertices(std::true_type{});
  else if (!single[0] && !single[1] && !single[2])
    vertices(std::false_type{});
  else
    return false;                     // mixed float and double coordinates: the general reader
  constexpr double kMaxSpan = 1e150;  // validate_mesh's bound (src/mesh.cpp)
  if (!finite || !(hi[0] - lo[0] <= kMaxSpan && hi[1] - lo[1] <= kMaxSpan && hi[2] - lo[2] <= kMaxSpan)) return false;
  mesh.F.resize(static_cast<Eigen::Index>(nf), 3);
  int* const f0 = mesh.F.data();
  int* const f1 = f0 + nf;
  int* const f2 = f1 + nf;
  const auto n = static_cast<std::uint32_t>(nv);
  bool bad = false;
  for (std::size_t f = 0; f < nf; ++f, b += kFaceRecord) {
    std::uint32_t i[3];
    std::memcpy(i, b + 1, 12);
    bad |= (static_cast<unsigned char>(b[0]) != 3) | (i[0] >= n) | (i[1] >= n) | (i[2] >= n) | (i[0] == i[1]) |
           (i[1] == i[2]) | (i[0] == i[2]);
    f0[f] = static_cast<int>(i[0]);
    f1[f] = static_cast<int>(i[1]);
    f2[f] = static_cast<int>(i[2]);
  }
  if (bad) return false;
  if (single[0]) mesh.position_type = ScalarType::Float32;
  soup.mesh = std::move(mesh);
  soup.direct = true;
  return true;
}

}  // namespace

void read_ply(const std::string& path, std::string_view data, Soup& soup) {
  data = without_utf8_bom(data);
  const PlyHeader h = parse_ply_header(path, data);
  PlyBodyReader in(path, data, h);
  if (read_binary_triangles(data, h, in.native(), soup)) return;
  bool all_uv = true, all_normals = true;
  bool float_positions = true;
  std::vector<std::string> dropped_face_properties, dropped_elements, dropped_vertex_lists;
  for (const PlyElement& e : h.elements) {
    const bool vertex = e.name == "vertex" || e.name == "vertices", face = e.name == "face" || e.name == "faces";
    if (!vertex && !face && e.count > 0) dropped_elements.push_back(e.name);
    // Vertex: x, y, z; a colour from red/green/blue (else r/g/b) when all three are uchar,
    // as CGAL read them, and uchar alpha; texture coordinates and normals; every other scalar
    // property as an extra vertex property. Face: the vertex_indices list (else vertex_index)
    // of any integer type, uchar red/green/blue[/alpha], MeshLab's per-corner `texcoord` list.
    // Everything else is read and skipped (named in the notes).
    int x = -1, y = -1, z = -1, col[3] = {-1, -1, -1}, alpha = -1, iu = -1, iv = -1, nx = -1, ny = -1, nz = -1;
    int idx = -1, tex = -1;
    std::vector<int> extra_slot(e.properties.size(), -1);  // vertex property -> soup.extra.vertex_properties
    const std::size_t first_extra = soup.extra.vertex_properties.size();
    std::vector<std::vector<double>> extra_values;
    const std::size_t first_point = soup.points.size();
    auto uchar_colour = [&](int c[3], int& a) {
      const char* const names[3][2] = {{"red", "r"}, {"green", "g"}, {"blue", "b"}};
      bool uchar = true;
      for (int k = 0; k < 3; ++k) {
        c[k] = find_scalar(e, names[k][0]);
        if (c[k] < 0) c[k] = find_scalar(e, names[k][1]);
        const std::string t = c[k] < 0 ? "" : e.properties[static_cast<std::size_t>(c[k])].type;
        uchar = uchar && (t == "uchar" || t == "uint8");
      }
      if (!uchar) c[0] = c[1] = c[2] = -1;
      a = find_scalar(e, "alpha");
      if (a < 0) a = find_scalar(e, "a");
      const std::string at = a < 0 ? "" : e.properties[static_cast<std::size_t>(a)].type;
      if (c[0] < 0 || (at != "uchar" && at != "uint8")) a = -1;
    };
    if (vertex) {
      x = find_scalar(e, "x"), y = find_scalar(e, "y"), z = find_scalar(e, "z");
      for (int k : {x, y, z})
        float_positions = float_positions && ply_type_size(e.properties[static_cast<std::size_t>(k)].type) == 4;
      uchar_colour(col, alpha);
      static const char* const uv_names[][2] = {
          {"texture_u", "texture_v"}, {"u", "v"}, {"s", "t"}, {"texture_s", "texture_t"}};
      for (const auto& names : uv_names)
        if (iu < 0 && find_scalar(e, names[0]) >= 0 && find_scalar(e, names[1]) >= 0)
          iu = find_scalar(e, names[0]), iv = find_scalar(e, names[1]);
      nx = find_scalar(e, "nx"), ny = find_scalar(e, "ny"), nz = find_scalar(e, "nz");
      if (ny < 0 || nz < 0) nx = -1;  // nx alone (no ny, nz): no normals
      if (nx >= 0) soup.notes.had_normals = true;
      soup.points.reserve(soup.points.size() + e.count);  // counts are bounded by the file size (checked)
      for (std::size_t p = 0; p < e.properties.size(); ++p) {
        const int pi = static_cast<int>(p);
        const PlyProperty& prop = e.properties[p];
        if (prop.is_list) {
          dropped_vertex_lists.push_back(prop.name);
          continue;
        }
        if (pi == x || pi == y || pi == z || pi == col[0] || pi == col[1] || pi == col[2] || pi == alpha || pi == iu ||
            pi == iv || (nx >= 0 && (pi == nx || pi == ny || pi == nz)))
          continue;
        extra_slot[p] = static_cast<int>(extra_values.size());
        extra_values.emplace_back();
        extra_values.back().reserve(static_cast<std::size_t>(e.count));
        soup.extra.vertex_properties.push_back({prop.name, Eigen::VectorXd(), scalar_type_of(prop.type)});
      }
    }
    if (face) {
      for (const char* name : {"vertex_indices", "vertex_index"})
        for (std::size_t p = 0; p < e.properties.size() && idx < 0; ++p)
          if (e.properties[p].is_list && e.properties[p].name == name) idx = static_cast<int>(p);
      for (std::size_t p = 0; p < e.properties.size(); ++p)
        if (e.properties[p].is_list && e.properties[p].name == "texcoord" && ply_is_float(e.properties[p].type))
          tex = static_cast<int>(p);
      uchar_colour(col, alpha);
      for (std::size_t p = 0; p < e.properties.size(); ++p) {
        const int pi = static_cast<int>(p);
        if (pi != idx && pi != tex && pi != col[0] && pi != col[1] && pi != col[2] && pi != alpha)
          dropped_face_properties.push_back(e.properties[p].name);
      }
      soup.flat.start.reserve(soup.flat.start.size() + e.count);
      soup.flat.corners.reserve(soup.flat.corners.size() + 3 * e.count);
    }
    double value[3] = {0, 0, 0}, uv[2] = {0, 0}, normal[3] = {0, 0, 0};
    int rgb[4] = {0, 0, 0, 255};
    std::vector<double> corner_uv;
    // Binary little-endian vertices on a little-endian host: records of fixed size, decoded
    // from their bytes by the offset and type of each property (the same values as the
    // generic loop below, which reads the records it cannot take whole, with its errors).
    struct Slot {
      std::size_t offset;
      const PlyType* type;
      double* target;  // x, y, z, uv, normal, or nullptr
      int rgb = -1;    // colour channel 0..3, or -1
      int extra = -1;  // extra vertex property, or -1
    };
    std::vector<Slot> slots;
    std::size_t record = 0;
    bool fixed = vertex && in.native();
    for (std::size_t p = 0; p < e.properties.size() && fixed; ++p) {
      const PlyProperty& prop = e.properties[p];
      const int pi = static_cast<int>(p);
      fixed = !prop.is_list;
      Slot slot{record, &prop.item, nullptr};
      double* const targets[] = {value, value + 1, value + 2, uv, uv + 1, normal, normal + 1, normal + 2};
      const int roles[] = {x, y, z, iu, iv, nx, nx >= 0 ? ny : -1, nx >= 0 ? nz : -1};
      for (int r = 0; r < 8; ++r)
        if (pi == roles[r]) slot.target = targets[r];
      for (int c = 0; c < 3; ++c)
        if (pi == col[c]) slot.rgb = c;
      if (pi == alpha) slot.rgb = 3;
      slot.extra = extra_slot[p];
      slots.push_back(slot);
      record += static_cast<std::size_t>(prop.size);
    }
    auto decode = [](const char* b, const PlyType& t) -> double {
      switch (t.bytes) {
        case 1:
          return t.lo < 0 ? static_cast<double>(static_cast<signed char>(*b)) : static_cast<unsigned char>(*b);
        case 2: {
          std::uint16_t u;
          std::memcpy(&u, b, 2);
          return t.lo < 0 ? static_cast<double>(static_cast<std::int16_t>(u)) : u;
        }
        case 4: {
          if (t.is_float) {
            float f;
            std::memcpy(&f, b, 4);
            return f;
          }
          std::uint32_t u;
          std::memcpy(&u, b, 4);
          return t.lo < 0 ? static_cast<double>(static_cast<std::int32_t>(u)) : u;
        }
        default: {
          double d;
          std::memcpy(&d, b, 8);
          return d;
        }
      }
    };
    for (unsigned long long j = 0; j < e.count; ++j) {
      in.at(e, j);
      if (const char* b = fixed ? in.take(record) : nullptr) {
        for (const Slot& slot : slots) {
          const double v = decode(b + slot.offset, *slot.type);
          if (slot.rgb >= 0) {
            rgb[slot.rgb] = static_cast<int>(v);
            continue;
          }
          if (slot.extra >= 0) extra_values[static_cast<std::size_t>(slot.extra)].push_back(v);
          if (slot.target) *slot.target = v;
        }
      } else {
        for (std::size_t p = 0; p < e.properties.size(); ++p) {
          const PlyProperty& prop = e.properties[p];
          const int pi = static_cast<int>(p);
          if (prop.is_list) {
            const std::size_t n = in.list_count(prop);
            if (pi == idx) {
              // A negative index wraps to a huge one here; soup_to_mesh reports it signed.
              for (std::size_t k = 0; k < n; ++k)
                soup.flat.corners.push_back(static_cast<std::size_t>(in.integer(prop.item, prop.name)));
              soup.flat.close();
            } else if (pi == tex) {
              corner_uv.resize(n);
              for (std::size_t k = 0; k < n; ++k) corner_uv[k] = in.real(prop.item, prop.name);
            } else {
              for (std::size_t k = 0; k < n; ++k) in.real(prop.item, prop.name);
            }
            continue;
          }
          if (pi == col[0] || pi == col[1] || pi == col[2] || pi == alpha) {
            rgb[pi == col[0]   ? 0
                : pi == col[1] ? 1
                : pi == col[2] ? 2
                               : 3] = static_cast<int>(in.integer(prop.item, prop.name));
            continue;
          }
          const double v = in.real(prop.item, prop.name);
          if (vertex && extra_slot[p] >= 0) extra_values[static_cast<std::size_t>(extra_slot[p])].push_back(v);
          if (pi == x) value[0] = v;
          if (pi == y) value[1] = v;
          if (pi == z) value[2] = v;
          if (pi == iu) uv[0] = v;
          if (pi == iv) uv[1] = v;
          if (pi == nx) normal[0] = v;
          if (pi == ny) normal[1] = v;
          if (pi == nz) normal[2] = v;
        }
      }
      if (face) {
        if (col[0] >= 0) soup.face_rgba.push_back({rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0, rgb[3] / 255.0});
        if (tex >= 0 && idx >= 0) {
          // Per-corner texture coordinates (2 per corner); a face without them (or with a
          // different count) has none.
          const std::size_t nc = soup.flat.size_of(soup.flat.size() - 1);
          const bool ok = corner_uv.size() == 2 * nc;
          for (std::size_t k = 0; k < nc; ++k) {
            if (ok && std::isfinite(corner_uv[2 * k]) && std::isfinite(corner_uv[2 * k + 1])) {
              soup.corner_texcoord.push_back(static_cast<long long>(soup.texcoord_table.size()));
              soup.texcoord_table.push_back({corner_uv[2 * k], corner_uv[2 * k + 1]});
            } else {
              soup.corner_texcoord.push_back(-1);
            }
          }
          corner_uv.clear();
        }
        continue;
      }
      if (!vertex) continue;
      soup.points.emplace_back(value[0], value[1], value[2]);
      if (col[0] >= 0) soup.vertex_colors.emplace_back(rgb[0], rgb[1], rgb[2]);
      if (alpha >= 0) soup.alpha.push_back(rgb[3] / 255.0);
      if (iu >= 0) {
        all_uv = all_uv && std::isfinite(uv[0]) && std::isfinite(uv[1]);
        soup.uv.push_back({uv[0], uv[1]});
      }
      if (nx >= 0) {
        all_normals = all_normals && std::isfinite(normal[0]) && std::isfinite(normal[1]) && std::isfinite(normal[2]);
        soup.normals.push_back({normal[0], normal[1], normal[2]});
      }
    }
    if (vertex) {
      for (std::size_t k = 0; k < extra_values.size(); ++k) {
        VertexProperty& vp = soup.extra.vertex_properties[first_extra + k];
        vp.values = Eigen::Map<const Eigen::VectorXd>(extra_values[k].data(),
                                                      static_cast<Eigen::Index>(extra_values[k].size()));
      }
      if (first_point != 0 && !extra_values.empty()) soup.extra.vertex_properties.resize(first_extra);
    }
  }
  if (float_positions && !soup.points.empty()) soup.extra.position_type = ScalarType::Float32;
  // Attributes with a non-finite value, or missing on some vertex element, are dropped.
  if (!all_uv || soup.uv.size() != soup.points.size()) soup.uv.clear();
  if (!all_normals || soup.normals.size() != soup.points.size()) soup.normals.clear();
  if (soup.vertex_colors.size() != soup.points.size()) soup.vertex_colors.clear();
  if (soup.alpha.size() != soup.points.size()) soup.alpha.clear();
  if (soup.face_rgba.size() != soup.flat.size()) soup.face_rgba.clear();
  soup.face_color_channels = 3;
  for (const auto& c : soup.face_rgba)
    if (c[3] != 1.0) soup.face_color_channels = 4;
  if (!soup.face_rgba.empty()) {
    // Alpha declared on the faces is kept even when every face is opaque.
    for (const PlyElement& e : h.elements)
      if ((e.name == "face" || e.name == "faces") && (find_scalar(e, "alpha") >= 0 || find_scalar(e, "a") >= 0))
        soup.face_color_channels = 4;
  }
  const std::size_t corners = soup.flat.corners.size();
  if (soup.corner_texcoord.size() != corners) soup.corner_texcoord.clear(), soup.texcoord_table.clear();
  auto list = [](const std::vector<std::string>& names) {
    std::string s;
    for (std::size_t k = 0; k < names.size() && k < 8; ++k) s += (k ? ", '" : "'") + names[k].substr(0, 40) + "'";
    if (names.size() > 8) s += ", ...";
    return s;
  };
  if (!dropped_vertex_lists.empty())
    soup.notes.dropped.push_back("PLY vertex list properties are not kept: " + list(dropped_vertex_lists));
  if (!dropped_face_properties.empty())
    soup.notes.dropped.push_back("PLY face properties are not kept: " + list(dropped_face_properties));
  if (!dropped_elements.empty()) soup.notes.dropped.push_back("PLY elements are not kept: " + list(dropped_elements));
}

}  // namespace msmesh::io_detail
