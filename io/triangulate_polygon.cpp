// Triangulation of the polygons of OBJ, OFF and PLY files: a fan for convex polygons (the
// triangles earlier versions gave, so meshes of triangles and convex polygons read as before),
// ear clipping in the polygon's best-fit plane for the others (an L-shaped CAD face, a star),
// where a fan would overlap itself and invert triangles.
#include <array>
#include <cmath>
#include <vector>

#include "read_common.h"

namespace msmesh::io_detail {
namespace {

struct P2 {
  double x, y;
};
double cross(const P2& o, const P2& a, const P2& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

void fan(const std::vector<int>& corners, std::vector<std::array<int, 3>>& triangles) {
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) triangles.push_back({corners[0], corners[k], corners[k + 1]});
}

/// The corners projected onto the plane through their centroid orthogonal to the Newell
/// normal, with axes (u, v) such that u × v = n: a simple polygon winds counter-clockwise.
/// Empty when the normal is zero or not finite (a degenerate polygon).
std::vector<P2> project_to_best_fit_plane(const std::vector<Point>& points, const std::vector<int>& corners) {
  const std::size_t n = corners.size();
  double c[3] = {0, 0, 0};
  for (int i : corners)
    for (int d = 0; d < 3; ++d) c[d] += points[static_cast<std::size_t>(i)][d] / static_cast<double>(n);
  auto rel = [&](std::size_t k, int d) { return points[static_cast<std::size_t>(corners[k])][d] - c[d]; };
  double N[3] = {0, 0, 0};  // Newell's normal: twice the vector area
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t j = (k + 1) % n;
    N[0] += (rel(k, 1) - rel(j, 1)) * (rel(k, 2) + rel(j, 2));
    N[1] += (rel(k, 2) - rel(j, 2)) * (rel(k, 0) + rel(j, 0));
    N[2] += (rel(k, 0) - rel(j, 0)) * (rel(k, 1) + rel(j, 1));
  }
  const double len = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
  if (!(len > 0) || !std::isfinite(len)) return {};
  for (double& x : N) x /= len;
  // u: orthogonal to n, built from the axis n is least aligned with; v = n × u.
  const int a = std::fabs(N[0]) <= std::fabs(N[1]) && std::fabs(N[0]) <= std::fabs(N[2]) ? 0
                : std::fabs(N[1]) <= std::fabs(N[2])                                     ? 1
                                                                                         : 2;
  double e[3] = {0, 0, 0};
  e[a] = 1;
  double u[3] = {N[1] * e[2] - N[2] * e[1], N[2] * e[0] - N[0] * e[2], N[0] * e[1] - N[1] * e[0]};
  const double ulen = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (double& x : u) x /= ulen;
  const double v[3] = {N[1] * u[2] - N[2] * u[1], N[2] * u[0] - N[0] * u[2], N[0] * u[1] - N[1] * u[0]};
  std::vector<P2> q(n);
  for (std::size_t k = 0; k < n; ++k)
    q[k] = {rel(k, 0) * u[0] + rel(k, 1) * u[1] + rel(k, 2) * u[2],
            rel(k, 0) * v[0] + rel(k, 1) * v[1] + rel(k, 2) * v[2]};
  return q;
}

/// Convex: no corner turns clockwise (beyond rounding) and the turns add up to one full turn
/// (a pentagram turns one way only, but twice).
bool is_convex(const std::vector<P2>& q, double eps) {
  const std::size_t n = q.size();
  double turning = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const P2& a = q[(k + n - 1) % n];
    const P2& b = q[k];
    const P2& c = q[(k + 1) % n];
    const P2 e1{b.x - a.x, b.y - a.y}, e2{c.x - b.x, c.y - b.y};
    if ((e1.x == 0 && e1.y == 0) || (e2.x == 0 && e2.y == 0)) continue;
    const double z = e1.x * e2.y - e1.y * e2.x;
    if (z < -eps) return false;
    turning += std::atan2(z, e1.x * e2.x + e1.y * e2.y);
  }
  return std::fabs(turning - 2 * M_PI) < 0.5;
}

}  // namespace

void triangulate_polygon(const std::vector<Point>& points, const std::vector<int>& corners,
                         std::vector<std::array<int, 3>>& triangles) {
  const std::size_t n = corners.size();
  if (n < 3) return;
  if (n == 3) return fan(corners, triangles);
  const std::vector<P2> q = project_to_best_fit_plane(points, corners);
  if (q.empty()) return fan(corners, triangles);
  double extent = 0;
  for (const P2& p : q) extent = std::fmax(extent, std::fmax(std::fabs(p.x), std::fabs(p.y)));
  const double eps = 1e-12 * extent * extent;
  if (is_convex(q, eps)) return fan(corners, triangles);

  // Ear clipping. An ear is a strictly convex corner whose triangle holds no other remaining
  // corner (on its edges included), except copies of its own corners. After a clip the walk
  // steps back one corner, whose ear status may have changed (so a polygon of n corners
  // usually takes O(n) ear tests of O(n) each).
  std::vector<std::size_t> left(n);
  for (std::size_t k = 0; k < n; ++k) left[k] = k;
  auto same = [&](std::size_t r, std::size_t s) { return q[r].x == q[s].x && q[r].y == q[s].y; };
  auto is_ear = [&](std::size_t a, std::size_t b, std::size_t c) {
    if (!(cross(q[a], q[b], q[c]) > eps)) return false;
    for (std::size_t r : left) {
      if (r == a || r == b || r == c || same(r, a) || same(r, b) || same(r, c)) continue;
      if (cross(q[a], q[b], q[r]) >= -eps && cross(q[b], q[c], q[r]) >= -eps && cross(q[c], q[a], q[r]) >= -eps)
        return false;
    }
    return true;
  };
  const std::size_t first = triangles.size();
  std::size_t k = 1, misses = 0;
  while (left.size() > 3) {
    const std::size_t m = left.size();
    k %= m;
    const std::size_t a = left[(k + m - 1) % m], b = left[k], c = left[(k + 1) % m];
    if (is_ear(a, b, c)) {
      triangles.push_back({corners[a], corners[b], corners[c]});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
      misses = 0;
      k = k == 0 ? left.size() - 1 : k - 1;
    } else if (++misses > m) {
      // No ear left (degenerate: self-intersecting or collinear): the fan it always was.
      triangles.resize(first);
      return fan(corners, triangles);
    } else {
      ++k;
    }
  }
  triangles.push_back({corners[left[0]], corners[left[1]], corners[left[2]]});
}

}  // namespace msmesh::io_detail
