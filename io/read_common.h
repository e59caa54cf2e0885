// Shared pieces of the mesh readers (internal to msmesh_io): the polygon soup the readers
// fill, the file in memory as a stream, polygon triangulation, and one entry point per format
// (read_obj.cpp, read_off.cpp, read_ply.cpp, read_stl.cpp); read_mesh.cpp dispatches to them
// by format and turns the soup into a Mesh.
//
// OBJ, PLY and binary STL are parsed by our own code (read_text.h's tokenizer and strict
// number parsers for text; one pass, no allocation per line or per polygon: their polygons go
// to Soup::flat). OFF and ascii STL go through CGAL's readers, which trust their input more
// than a command-line tool can, so each is checked before CGAL sees it (found by reading CGAL
// 5.5's readers and by fuzzing them under AddressSanitizer); what each reader guards against
// is listed at the top of its file. read_off.cpp and read_stl.cpp are the only translation
// units that include CGAL's I/O headers. The whole file is in memory once (mapped from 64 KB on,
// read_mesh.cpp). Binary PLY and STL files of triangles skip the soup: their readers fill the
// mesh's own arrays (Soup::direct).
#pragma once
#include <CGAL/IO/Color.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <istream>
#include <streambuf>
#include <string>
#include <string_view>
#include <vector>

#include "msmesh/read_mesh.h"
#include "read_text.h"

// msmesh::io_detail rather than the core's msmesh::detail: names such as Polygon stay apart
// from the core's internals in one program.
namespace msmesh::io_detail {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;

// ---------------------------------------------------------------------------------------------
// Polygon soup with a guarded polygon type.

/// Thrown when a reader asks for a polygon with more corners than the file has bytes.
struct PolygonTooLarge {
  std::size_t size;
};

/// Upper bound on the corners of one polygon while a file is read (its size in bytes).
inline thread_local std::size_t t_polygon_limit = 0;

/// A polygon of the soup. Up to four corners are stored inline (no allocation per
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

/// Polygons stored flat: the corners of all polygons in order, and where each one starts
/// (8 bytes per corner and 8 per polygon, against sizeof(Polygon) = 64 and no allocation per
/// polygon). The readers that fill the soup themselves (OBJ, PLY, binary STL) use it.
struct FlatPolygons {
  std::vector<std::size_t> corners;
  std::vector<std::size_t> start = {0};  ///< polygon p: corners[start[p]] .. corners[start[p + 1] - 1]

  std::size_t size() const { return start.size() - 1; }
  std::size_t size_of(std::size_t p) const { return start[p + 1] - start[p]; }
  const std::size_t* corners_of(std::size_t p) const { return corners.data() + start[p]; }
  /// Ends the polygon whose corners were appended since the last one.
  void close() { start.push_back(corners.size()); }
};

/// One polygon of a soup, in either storage.
struct PolygonRef {
  const std::size_t* corners;
  std::size_t size;
  const std::size_t* begin() const { return corners; }
  const std::size_t* end() const { return corners + size; }
};

struct Soup {
  std::vector<Point> points;
  /// The polygons: in `polygons` (CGAL's readers and glTF) or in `flat` (our own readers);
  /// one of the two is empty. polygon_count() and polygon() read either.
  std::vector<Polygon> polygons;
  FlatPolygons flat;
  std::size_t polygon_count() const { return polygons.empty() ? flat.size() : polygons.size(); }
  PolygonRef polygon(std::size_t p) const {
    return polygons.empty() ? PolygonRef{flat.corners_of(p), flat.size_of(p)}
                            : PolygonRef{polygons[p].data(), polygons[p].size()};
  }
  std::vector<CGAL::IO::Color> vertex_colors;
  // Per-vertex attributes (empty when absent or not per-vertex).
  std::vector<std::array<double, 3>> rgb;  ///< OBJ "v x y z r g b" colours in [0,1]
  std::vector<std::array<double, 2>> uv;
  std::vector<std::array<double, 3>> normals;
  std::vector<double> alpha;  ///< per-vertex alpha in [0,1] (PLY `alpha`, glTF COLOR_0 vec4)
  // Per polygon (empty when absent): colours, material, group and object indices (−1 none).
  std::vector<std::array<double, 4>> face_rgba;
  int face_color_channels = 3;  ///< 3 or 4 (alpha) when face_rgba is filled
  std::vector<int> polygon_material, polygon_group, polygon_object;
  /// Per corner of the polygons, in order (flattened): index into texcoord_table, −1 none.
  /// Empty when the file has no per-corner texture coordinates (or they are per-vertex: uv).
  std::vector<long long> corner_texcoord;
  std::vector<std::array<double, 2>> texcoord_table;
  /// Document-level attributes the readers fill directly: material libraries and names, group
  /// and object names, extra vertex properties (#points values), position type, glTF document.
  Mesh extra;
  ReadNotes notes;
  /// The mesh itself, when the reader built it straight into its final arrays (binary PLY and
  /// STL whose faces are all triangles: read_ply.cpp, read_stl.cpp). Its V and F are checked as
  /// soup_to_mesh checks them (indices in range, finite coordinates within validate_mesh's span;
  /// triangles repeating a vertex left out and counted in `direct_dropped`), so soup_to_mesh
  /// is skipped; the rest of the soup is empty.
  bool direct = false;
  Mesh mesh;
  Eigen::Index direct_dropped = 0;
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

/// Appends the triangles of one polygon (`corners` index `points`, in order) to `triangles`,
/// keeping its orientation: a fan from the first corner when the polygon is convex in its
/// best-fit (Newell) plane, ear clipping in that plane otherwise, and the fan again when ear
/// clipping finds no ear (a degenerate or self-intersecting polygon). Always #corners − 2
/// triangles (none for fewer than 3 corners); they may repeat a vertex. triangulate_polygon.cpp.
void triangulate_polygon(const std::vector<Point>& points, const std::vector<int>& corners,
                         std::vector<std::array<int, 3>>& triangles);

// ---------------------------------------------------------------------------------------------
// One reader per format: parses `data` (the bytes of the file `path`, not empty) into `soup`;
// throws IoError naming `path` for malformed files (read_mesh.cpp maps CGAL's and the
// allocator's exceptions to IoError too).

void read_obj(const std::string& path, std::string_view data, Soup& soup);  // read_obj.cpp
void read_off(const std::string& path, std::string_view data, Soup& soup);  // read_off.cpp
void read_ply(const std::string& path, std::string_view data, Soup& soup);  // read_ply.cpp
void read_stl(const std::string& path, std::string_view data, Soup& soup);  // read_stl.cpp
/// glTF 2.0 (`glb` true: binary container); external buffers and images are found next to `path`.
void read_gltf(const std::string& path, std::string_view data, bool glb, Soup& soup);  // read_gltf.cpp

}  // namespace msmesh::io_detail
