// Binary STL files read straight into the mesh (read_stl_binary.h): the points of each range of
// triangles welded through an open-addressing hash table, the ranges joined in file order.
#include "read_stl_binary.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <utility>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/threads.h"
#include "read_common.h"

namespace msmesh::io_detail {
namespace {

constexpr std::uint32_t kEmpty = UINT32_MAX;
constexpr std::size_t kNone = SIZE_MAX;

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

bool same_point(const float* p, const float* q) { return p[0] == q[0] && p[1] == q[1] && p[2] == q[2]; }

/// Point numbers by hash, linear probing, kept under half full; the points themselves (3 floats
/// each, by number) are the caller's.
class PointTable {
 public:
  explicit PointTable(std::size_t points_expected) {
    while (mask_ + 1 < 2 * points_expected) mask_ = 2 * mask_ + 1;
    slots_.assign(mask_ + 1, kEmpty);
  }
  void prefetch(std::uint64_t h) const { __builtin_prefetch(slots_.data() + (h & mask_)); }
  /// The number in the first slot of hash h (kEmpty if none): what a lookup compares first.
  std::uint32_t first(std::uint64_t h) const { return slots_[h & mask_]; }
  /// The number of the point equal to xyz (hash h) among `coords`, or kEmpty; `slot` ends at
  /// the free slot where it would go.
  std::uint32_t find(const float xyz[3], std::uint64_t h, const float* coords, std::size_t& slot) const {
    for (slot = h & mask_; slots_[slot] != kEmpty; slot = (slot + 1) & mask_)
      if (same_point(coords + 3 * std::size_t(slots_[slot]), xyz)) return slots_[slot];
    return kEmpty;
  }
  /// Puts number `id` into the free slot `slot` found by find(); then, past half full, doubles
  /// the table and puts back the `count` points of `coords`.
  void put(std::size_t slot, std::uint32_t id, const float* coords, std::size_t count) {
    slots_[slot] = id;
    if (2 * count <= mask_) return;
    mask_ = 2 * mask_ + 1;
    slots_.assign(mask_ + 1, kEmpty);
    for (std::size_t i = 0; i < count; ++i) {
      std::size_t s = point_hash(coords + 3 * i) & mask_;
      while (slots_[s] != kEmpty) s = (s + 1) & mask_;
      slots_[s] = static_cast<std::uint32_t>(i);
    }
  }

 private:
  std::size_t mask_ = 1023;
  std::vector<std::uint32_t> slots_;
};

/// Triangles [t0, t1) of the file, welded on their own.
struct Range {
  Range(std::size_t begin, std::size_t end) : t0(begin), t1(end), table((end - begin) / 2 + 3) {
    coords.reserve(3 * ((end - begin) / 2 + 3));  // a closed mesh has about F/2 vertices
  }
  std::size_t t0, t1;
  PointTable table;
  std::vector<float> coords;  // the range's points as read, in order of first appearance
  std::size_t kept = 0;       // triangles kept, in F's rows t0 .. t0 + kept (local numbers)
  std::size_t bad = kNone;    // the first triangle with a non-finite coordinate
  bool too_many = false;      // more than INT_MAX points
};

/// Welds one range into F's rows from r.t0 on, numbering its points 0, 1, ... Each corner's slot
/// is prefetched a few corners ahead (the table is larger than the caches: the loads overlap
/// instead of queuing), and the file's bytes 64 triangles ahead (3.2 KB: one read in four
/// crosses a page, where the hardware prefetcher stops; 2 threads 85 -> 72 ms at 1.3M faces).
/// Stops at the first non-finite coordinate.
void weld(const char* body, Range& r, int* f0, int* f1, int* f2) {
  auto corner = [body](std::size_t c) { return body + 50 * (c / 3) + 12 + 12 * (c % 3); };
  auto hash_corner = [&](std::size_t c) {
    float xyz[3];
    std::memcpy(xyz, corner(c), 12);
    return point_hash(xyz);
  };
  // Two-stage prefetch: the slot of corner c + 2 * kAhead, then the point that slot holds (the
  // comparison's load) for corner c + kAhead; the hashes wait in a ring.
  constexpr std::size_t kAhead = 16, kRing = 64;
  static_assert(kRing >= 2 * kAhead + 1 && (kRing & (kRing - 1)) == 0, "the ring holds the corners in flight");
  std::uint64_t ring[kRing];
  const std::size_t c_begin = 3 * r.t0, c_end = 3 * r.t1;
  for (std::size_t c = c_begin; c < std::min(c_end, c_begin + 2 * kAhead); ++c) ring[c % kRing] = hash_corner(c);
  std::size_t points = 0;
  for (std::size_t t = r.t0; t < r.t1; ++t) {
    __builtin_prefetch(body + 50 * (t + 64));  // the file's bytes: across pages, where the hardware stops
    std::uint32_t id[3];
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t c = 3 * t + k;
      if (c + 2 * kAhead < c_end) {
        const std::uint64_t h = hash_corner(c + 2 * kAhead);
        ring[(c + 2 * kAhead) % kRing] = h;
        r.table.prefetch(h);
      }
      if (c + kAhead < c_end) {
        const std::uint32_t first = r.table.first(ring[(c + kAhead) % kRing]);
        if (first != kEmpty) __builtin_prefetch(r.coords.data() + 3 * std::size_t(first));
      }
      float xyz[3];
      std::memcpy(xyz, corner(c), 12);
      if (!(std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2]))) {
        r.bad = t;
        return;
      }
      std::size_t slot;
      std::uint32_t found = r.table.find(xyz, ring[c % kRing], r.coords.data(), slot);
      if (found == kEmpty) {
        if (points == static_cast<std::size_t>(INT_MAX)) {
          r.too_many = true;
          return;
        }
        found = static_cast<std::uint32_t>(points++);
        r.coords.insert(r.coords.end(), xyz, xyz + 3);
        r.table.put(slot, found, r.coords.data(), points);
      }
      id[k] = found;
    }
    if (id[0] == id[1] || id[1] == id[2] || id[0] == id[2]) continue;
    const std::size_t row = r.t0 + r.kept++;
    f0[row] = static_cast<int>(id[0]);
    f1[row] = static_cast<int>(id[1]);
    f2[row] = static_cast<int>(id[2]);
  }
}

/// Joins range q to the points of the ranges before it (`all`, numbered by `table`): q's rows of
/// F moved down to `row` and renumbered; q's new points appended to `all` and, unless q is the
/// last range, put into `table`. Throws when the points pass INT_MAX.
void join(const std::string& path, Range& q, bool last, std::vector<float>& all, PointTable& table, int* f0, int* f1,
          int* f2, std::size_t row) {
  const std::size_t n = q.coords.size() / 3;
  std::vector<std::uint32_t> number(n);
  const float* const p = q.coords.data();
  const long count = static_cast<long>(n);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < count; ++i) {
    if (i + 16 < count) table.prefetch(point_hash(p + 3 * std::size_t(i + 16)));
    std::size_t slot;
    const float* xyz = p + 3 * std::size_t(i);
    number[std::size_t(i)] = table.find(xyz, point_hash(xyz), all.data(), slot);
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (number[i] != kEmpty) continue;
    const std::size_t points = all.size() / 3;
    if (points == static_cast<std::size_t>(INT_MAX))
      throw IoError(path + ": too many vertices (more than " + std::to_string(INT_MAX) + ")");
    number[i] = static_cast<std::uint32_t>(points);
    all.insert(all.end(), p + 3 * i, p + 3 * i + 3);
    if (!last) {
      std::size_t slot;
      table.find(p + 3 * i, point_hash(p + 3 * i), all.data(), slot);
      table.put(slot, number[i], all.data(), points + 1);
    }
  }
  int* const column[3] = {f0, f1, f2};
  for (int* f : column) {
    if (row != q.t0) std::memmove(f + row, f + q.t0, q.kept * sizeof(int));
    const long rows = static_cast<long>(q.kept);
#pragma omp parallel for schedule(static)
    for (long i = 0; i < rows; ++i)
      f[row + std::size_t(i)] = static_cast<int>(number[std::size_t(f[row + std::size_t(i)])]);
  }
}

}  // namespace

void read_binary_stl(const std::string& path, std::string_view data, std::uint32_t triangles, Soup& soup) {
  const std::size_t nt = triangles;
  if (nt == 0) return;  // soup_to_mesh: "the file contains no vertices"
  Mesh mesh;
  mesh.F.resize(static_cast<Eigen::Index>(nt), 3);
  int* const f0 = mesh.F.data();
  int* const f1 = f0 + nt;
  int* const f2 = f1 + nt;
  const char* const body = data.data() + 84;

  // A small file is welded without asking, or starting, the OpenMP runtime (plain_text.h).
  const std::size_t n_ranges =
      nt < 2 * std::size_t(kStlRangeTriangles)
          ? 1
          : std::min<std::size_t>(std::size_t(std::max(1, threads())), nt / kStlRangeTriangles);
  std::vector<Range> ranges;
  ranges.reserve(n_ranges);
  for (std::size_t k = 0; k < n_ranges; ++k) ranges.emplace_back(nt * k / n_ranges, nt * (k + 1) / n_ranges);
  if (n_ranges == 1) {
    weld(body, ranges[0], f0, f1, f2);
  } else {
    const long count = static_cast<long>(n_ranges);
    const int team = static_cast<int>(n_ranges);
#pragma omp parallel for schedule(static, 1) num_threads(team)
    for (long k = 0; k < count; ++k) weld(body, ranges[std::size_t(k)], f0, f1, f2);
  }
  for (const Range& r : ranges) {
    if (r.bad != kNone)
      throw IoError(path + ": triangle " + std::to_string(r.bad) + " has a non-finite vertex coordinate");
    if (r.too_many) throw IoError(path + ": too many vertices (more than " + std::to_string(INT_MAX) + ")");
  }

  std::vector<float>& all = ranges[0].coords;  // the first range's numbers are the file's
  std::size_t kept = ranges[0].kept;
  for (std::size_t k = 1; k < n_ranges; ++k) {
    join(path, ranges[k], k + 1 == n_ranges, all, ranges[0].table, f0, f1, f2, kept);
    kept += ranges[k].kept;
    ranges[k].coords = std::vector<float>();
  }
  const Eigen::Index dropped = static_cast<Eigen::Index>(nt - kept);
  if (kept == 0) throw IoError(path + ": all " + std::to_string(dropped) + " faces are degenerate (repeat a vertex)");
  if (kept < nt) mesh.F.conservativeResize(static_cast<Eigen::Index>(kept), 3);
  const std::size_t points = all.size() / 3;
  mesh.V.resize(static_cast<Eigen::Index>(points), 3);
  double* const x = mesh.V.data();
  double* const y = x + points;
  double* const z = y + points;
  auto to_double = [&](std::size_t j) {
    x[j] = all[3 * j];
    y[j] = all[3 * j + 1];
    z[j] = all[3 * j + 2];
  };
  if (n_ranges == 1) {
    for (std::size_t j = 0; j < points; ++j) to_double(j);
  } else {
    const long count = static_cast<long>(points);
#pragma omp parallel for schedule(static)
    for (long i = 0; i < count; ++i) to_double(std::size_t(i));
  }
  soup.mesh = std::move(mesh);
  soup.direct_dropped = dropped;
  soup.direct = true;
}

}  // namespace msmesh::io_detail
