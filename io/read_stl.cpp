// STL reader: binary files by our own loop (read_binary_stl), ascii ones by CGAL's read_STL
// behind guards. Both weld the triangle soup into shared vertices the same way: a vertex is
// numbered on its first appearance, equal coordinates (compared as numbers, so -0 = 0) are one
// vertex. CGAL does it through std::map<Point, int>, which NaN breaks (non-finite coordinates
// are refused first), at about 10 MB/s; the binary reader uses a hash table instead. CGAL
// parses a binary file whose header starts with "solid" as ascii first, and retries a failed
// ascii parse as binary, which "succeeds" on files shorter than 84 bytes.
#include <CGAL/IO/STL.h>

#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "msmesh/errors.h"
#include "read_common.h"

namespace msmesh::io_detail {
namespace {

/// Hash of a float triple, -0 and +0 alike (they are one vertex).
std::uint64_t point_hash(const float xyz[3]) {
  std::uint64_t h = 0x9E3779B97F4A7C15ULL;
  for (int c = 0; c < 3; ++c) {
    const float x = xyz[c] == 0.0f ? 0.0f : xyz[c];
    std::uint32_t u;
    std::memcpy(&u, &x, 4);
    h = (h ^ u) * 0xFF51AFD7ED558CCDULL;
    h ^= h >> 32;
  }
  return h;
}

/// A binary STL of `triangles` triangles (the size already checked, little-endian floats):
/// the points welded as CGAL's parse_binary_STL welds them (numbered on first appearance,
/// equal when their coordinates compare equal), through an open-addressing hash table.
void read_binary_stl(std::string_view data, std::uint32_t triangles, Soup& soup) {
  soup.flat.corners.resize(3 * std::size_t(triangles));
  soup.flat.start.resize(std::size_t(triangles) + 1);
  for (std::size_t t = 0; t <= triangles; ++t) soup.flat.start[t] = 3 * t;
  soup.points.reserve(triangles / 2 + 3);  // after welding a closed mesh has about F/2 vertices
  std::vector<float> coords;               // the points as read (floats), 3 per point
  coords.reserve(3 * (triangles / 2 + 3));
  std::size_t mask = 1023;
  while (mask + 1 < 2 * static_cast<std::size_t>(triangles / 2 + 3)) mask = 2 * mask + 1;
  std::vector<std::uint32_t> slots(mask + 1, UINT32_MAX);  // point number, UINT32_MAX empty
  auto insert = [&](const float xyz[3], std::uint32_t id) {
    std::size_t s = point_hash(xyz) & mask;
    while (slots[s] != UINT32_MAX) s = (s + 1) & mask;
    slots[s] = id;
  };
  const char* rec = data.data() + 84;
  for (std::uint32_t t = 0; t < triangles; ++t, rec += 50) {
    std::size_t* const poly = soup.flat.corners.data() + 3 * std::size_t(t);
    for (int k = 0; k < 3; ++k) {
      float xyz[3];
      std::memcpy(xyz, rec + 12 + 12 * k, 12);
      std::size_t s = point_hash(xyz) & mask;
      std::uint32_t id = UINT32_MAX;
      for (; slots[s] != UINT32_MAX; s = (s + 1) & mask) {
        const float* q = coords.data() + 3 * std::size_t(slots[s]);
        if (q[0] == xyz[0] && q[1] == xyz[1] && q[2] == xyz[2]) {
          id = slots[s];
          break;
        }
      }
      if (id == UINT32_MAX) {
        id = static_cast<std::uint32_t>(soup.points.size());
        slots[s] = id;
        coords.insert(coords.end(), xyz, xyz + 3);
        soup.points.emplace_back(xyz[0], xyz[1], xyz[2]);
        if (2 * soup.points.size() > mask) {  // keep the load under one half
          mask = 2 * mask + 1;
          slots.assign(mask + 1, UINT32_MAX);
          for (std::uint32_t i = 0; i < soup.points.size(); ++i) insert(coords.data() + 3 * std::size_t(i), i);
        }
      }
      poly[k] = id;
    }
  }
}

}  // namespace

void read_stl(const std::string& path, std::string_view data, Soup& soup) {
  // A byte-order mark before "solid" (ascii files only: a binary header may start with anything).
  const bool binary_size = data.size() >= 84 && [&] {
    std::uint32_t n;
    std::memcpy(&n, data.data() + 80, 4);
    return data.size() == 84 + 50 * static_cast<std::uint64_t>(n);
  }();
  if (!binary_size && without_utf8_bom(data).substr(0, 5) == "solid") data = without_utf8_bom(data);
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
  if (binary) {
    // CGAL merges equal points through std::map<Point, int>; NaN breaks its ordering.
    for (std::uint32_t t = 0; t < triangles; ++t)
      for (int c = 3; c < 12; ++c) {
        float x;
        std::memcpy(&x, data.data() + 84 + 50 * std::size_t(t) + 4 * c, 4);
        if (!std::isfinite(x))
          throw IoError(path + ": triangle " + std::to_string(t) + " has a non-finite vertex coordinate");
      }
    // (Many exporters start binary headers with "solid": the size decides, as above.)
    read_binary_stl(data, triangles, soup);
    return;
  }
  if (!binary && data.find("endsolid") == std::string_view::npos)
    throw IoError(path + ": truncated ascii STL (no 'endsolid')");
  MemoryStream in(data);
  bool ok = CGAL::IO::read_STL(in, soup.points, soup.polygons, CGAL::parameters::verbose(false));
  if (ok && !binary) {
    // When its ascii parse fails CGAL retries as binary, which "succeeds" on files shorter
    // than a binary header; the facet count tells.
    std::size_t facets = 0;
    for (std::size_t at = data.find("endfacet"); at != std::string_view::npos; at = data.find("endfacet", at + 8))
      ++facets;
    ok = facets == soup.polygons.size();
  }
  if (!ok) throw IoError(path + ": malformed or truncated ascii STL (CGAL's reader failed)");
}

}  // namespace msmesh::io_detail
