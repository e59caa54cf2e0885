// STL reader: binary files by our own loop (read_binary_stl), ascii ones by CGAL's read_STL
// behind guards. Both weld the triangle soup into shared vertices the same way: a vertex is
// numbered on its first appearance, equal coordinates (compared as numbers, so -0 = 0) are one
// vertex. CGAL does it through std::map<Point, int>, which NaN breaks (non-finite coordinates
// are refused first), at about 10 MB/s; the binary reader uses a hash table instead. CGAL
// parses a binary file whose header starts with "solid" as ascii first, and retries a failed
// ascii parse as binary, which "succeeds" on files shorter than 84 bytes.
#include <CGAL/IO/STL.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
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

/// A binary STL of `triangles` triangles (the size already checked, little-endian floats), read
/// straight into the mesh (soup.mesh, soup.direct): the points welded as CGAL's
/// parse_binary_STL welds them (numbered on first appearance, equal when their coordinates
/// compare equal) through an open-addressing hash table, each corner's slot prefetched a few
/// corners ahead (the table is larger than the caches: the loads overlap instead of queuing);
/// triangles repeating a vertex after welding are left out and counted, as soup_to_mesh does.
/// A non-finite coordinate is refused (CGAL merges through std::map<Point, int>, which NaN
/// breaks), naming the first triangle that has one.
void read_binary_stl(const std::string& path, std::string_view data, std::uint32_t triangles, Soup& soup) {
  const std::size_t nt = triangles;
  if (nt == 0) return;  // soup_to_mesh: "the file contains no vertices"
  Mesh mesh;
  mesh.F.resize(static_cast<Eigen::Index>(nt), 3);
  int* const f0 = mesh.F.data();
  int* const f1 = f0 + nt;
  int* const f2 = f1 + nt;
  std::vector<float> coords;         // the points as read (floats), 3 per point
  coords.reserve(3 * (nt / 2 + 3));  // after welding a closed mesh has about F/2 vertices
  std::size_t mask = 1023;
  while (mask + 1 < 2 * (nt / 2 + 3)) mask = 2 * mask + 1;
  std::vector<std::uint32_t> slots(mask + 1, UINT32_MAX);  // point number, UINT32_MAX empty
  auto insert = [&](const float xyz[3], std::uint32_t id) {
    std::size_t s = point_hash(xyz) & mask;
    while (slots[s] != UINT32_MAX) s = (s + 1) & mask;
    slots[s] = id;
  };
  const char* const body = data.data() + 84;
  auto corner = [body](std::size_t c) { return body + 50 * (c / 3) + 12 + 12 * (c % 3); };
  // Two-stage prefetch: the slot of corner c + 2 * kAhead, then the point that slot holds (the
  // comparison's load) for corner c + kAhead; the hashes wait in a ring.
  constexpr std::size_t kAhead = 16, kRing = 64;
  static_assert(kRing >= 2 * kAhead + 1 && (kRing & (kRing - 1)) == 0, "the ring holds the corners in flight");
  std::uint64_t ring[kRing];
  const std::size_t corners = 3 * nt;
  auto hash_corner = [&](std::size_t c) {
    float xyz[3];
    std::memcpy(xyz, corner(c), 12);
    return point_hash(xyz);
  };
  for (std::size_t c = 0; c < std::min(corners, 2 * kAhead); ++c) ring[c % kRing] = hash_corner(c);
  std::size_t kept = 0, points = 0;
  Eigen::Index dropped = 0;
  for (std::size_t t = 0; t < nt; ++t) {
    std::uint32_t id[3];
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t c = 3 * t + k;
      if (c + 2 * kAhead < corners) {
        const std::uint64_t h = hash_corner(c + 2 * kAhead);
        ring[(c + 2 * kAhead) % kRing] = h;
        __builtin_prefetch(slots.data() + (h & mask));
      }
      if (c + kAhead < corners) {
        const std::uint32_t first = slots[ring[(c + kAhead) % kRing] & mask];
        if (first != UINT32_MAX) __builtin_prefetch(coords.data() + 3 * std::size_t(first));
      }
      float xyz[3];
      std::memcpy(xyz, corner(c), 12);
      if (!(std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2])))
        throw IoError(path + ": triangle " + std::to_string(t) + " has a non-finite vertex coordinate");
      std::size_t s = ring[c % kRing] & mask;
      std::uint32_t found = UINT32_MAX;
      for (; slots[s] != UINT32_MAX; s = (s + 1) & mask) {
        const float* q = coords.data() + 3 * std::size_t(slots[s]);
        if (q[0] == xyz[0] && q[1] == xyz[1] && q[2] == xyz[2]) {
          found = slots[s];
          break;
        }
      }
      if (found == UINT32_MAX) {
        if (points == static_cast<std::size_t>(INT_MAX))
          throw IoError(path + ": too many vertices (more than " + std::to_string(INT_MAX) + ")");
        found = static_cast<std::uint32_t>(points++);
        slots[s] = found;
        coords.insert(coords.end(), xyz, xyz + 3);
        if (2 * points > mask) {  // keep the load under one half
          mask = 2 * mask + 1;
          slots.assign(mask + 1, UINT32_MAX);
          for (std::uint32_t i = 0; i < points; ++i) insert(coords.data() + 3 * std::size_t(i), i);
        }
      }
      id[k] = found;
    }
    if (id[0] == id[1] || id[1] == id[2] || id[0] == id[2]) {
      ++dropped;
      continue;
    }
    f0[kept] = static_cast<int>(id[0]);
    f1[kept] = static_cast<int>(id[1]);
    f2[kept] = static_cast<int>(id[2]);
    ++kept;
  }
  if (kept == 0) throw IoError(path + ": all " + std::to_string(dropped) + " faces are degenerate (repeat a vertex)");
  if (kept < nt) mesh.F.conservativeResize(static_cast<Eigen::Index>(kept), 3);
  mesh.V.resize(static_cast<Eigen::Index>(points), 3);
  double* const x = mesh.V.data();
  double* const y = x + points;
  double* const z = y + points;
  for (std::size_t i = 0; i < points; ++i) {
    x[i] = coords[3 * i];
    y[i] = coords[3 * i + 1];
    z[i] = coords[3 * i + 2];
  }
  soup.mesh = std::move(mesh);
  soup.direct_dropped = dropped;
  soup.direct = true;
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
    // (Many exporters start binary headers with "solid": the size decides, as above.)
    read_binary_stl(path, data, triangles, soup);
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
