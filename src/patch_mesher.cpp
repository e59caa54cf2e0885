// Patch meshing (patch_mesher.h): sampling of curves, interior points, constrained Delaunay
// triangulation of each developed patch.
#include "patch_mesher.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <utility>

namespace msmesh::detail {

namespace {

/// Axis-aligned bucket grid over a planar box, each cell listing the items that touch it.
class BucketGrid {
 public:
  BucketGrid(const Vec2& lo, const Vec2& hi, double cell) : lo_(lo), cell_(cell) {
    nx_ = std::max(1, static_cast<int>(std::ceil((hi.x() - lo.x()) / cell)) + 1);
    ny_ = std::max(1, static_cast<int>(std::ceil((hi.y() - lo.y()) / cell)) + 1);
    cells_.resize(static_cast<size_t>(nx_) * ny_);
  }
  /// Adds item `id` to every cell meeting the box [a, b].
  void add(int id, const Vec2& a, const Vec2& b) {
    int x0, y0, x1, y1;
    range(a, b, x0, y0, x1, y1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) cells_[static_cast<size_t>(y) * nx_ + x].push_back(id);
  }
  /// Calls visit(id) for the items of every cell meeting the box [a, b] (possibly repeated).
  template <class Visit>
  void visit(const Vec2& a, const Vec2& b, Visit&& visit) const {
    int x0, y0, x1, y1;
    range(a, b, x0, y0, x1, y1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        for (int id : cells_[static_cast<size_t>(y) * nx_ + x]) visit(id);
  }

 private:
  void range(const Vec2& a, const Vec2& b, int& x0, int& y0, int& x1, int& y1) const {
    auto clampi = [](double v, int n) { return std::clamp(static_cast<int>(std::floor(v)), 0, n - 1); };
    x0 = clampi((a.x() - lo_.x()) / cell_, nx_);
    x1 = clampi((b.x() - lo_.x()) / cell_, nx_);
    y0 = clampi((a.y() - lo_.y()) / cell_, ny_);
    y1 = clampi((b.y() - lo_.y()) / cell_, ny_);
  }
  Vec2 lo_;
  double cell_;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> cells_;
};

double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

/// x coordinates where the horizontal line at height y crosses the closed polygon q, sorted:
/// the polygon's inside on that line is [x0,x1] ∪ [x2,x3] ∪ …
std::vector<double> row_crossings(const std::vector<Vec2>& q, double y) {
  std::vector<double> xs;
  const size_t n = q.size();
  for (size_t i = 0; i < n; ++i) {
    const Vec2& a = q[i];
    const Vec2& b = q[(i + 1) % n];
    if ((a.y() > y) != (b.y() > y)) xs.push_back(a.x() + (y - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
  }
  std::sort(xs.begin(), xs.end());
  return xs;
}

using CdtKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CdtVertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, CdtKernel>;
using CdtFaceInfo = CGAL::Triangulation_face_base_with_info_2<int, CdtKernel>;
using CdtFaceBase = CGAL::Constrained_triangulation_face_base_2<CdtKernel, CdtFaceInfo>;
using CdtTds = CGAL::Triangulation_data_structure_2<CdtVertexBase, CdtFaceBase>;
// The patch boundary is a simple polygon: constraints never cross.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<CdtKernel, CdtTds,
                                                       CGAL::No_constraint_intersection_requiring_constructions_tag>;

/// Face info = number of constraints crossed from the outside (odd: inside the patch).
void mark_nesting_levels(Cdt& cdt) {
  for (auto f : cdt.all_face_handles()) f->info() = -1;
  std::deque<std::pair<Cdt::Face_handle, int>> seeds{{cdt.infinite_face(), 0}};
  while (!seeds.empty()) {
    auto [start, level] = seeds.front();
    seeds.pop_front();
    if (start->info() != -1) continue;
    start->info() = level;
    std::vector<Cdt::Face_handle> stack{start};
    while (!stack.empty()) {
      const Cdt::Face_handle f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const Cdt::Face_handle g = f->neighbor(i);
        if (g->info() != -1) continue;
        if (cdt.is_constrained(Cdt::Edge(f, i))) {
          seeds.emplace_back(g, level + 1);
        } else {
          g->info() = level;
          stack.push_back(g);
        }
      }
    }
  }
}

}  // namespace

/// Samples `curve` (curve(0) at corner a, curve(1) at corner b) with edges of about the
/// target size. Returns the vertex ids along it, a first and b last.
std::vector<int> PatchMesher::add_curve(int a, int b, const Curve& curve) {
  // Cumulative ∫ ds / size on a fine polyline; samples divide it evenly.
  constexpr int kSteps = 256;
  std::vector<double> w(kSteps + 1, 0.0);
  Vec3 prev = curve(0.0);
  for (int k = 1; k <= kSteps; ++k) {
    const Vec3 p = curve(double(k) / kSteps);
    w[k] = w[k - 1] + (p - prev).norm() / size_(0.5 * (p + prev));
    prev = p;
  }
  const int n = std::max(1, static_cast<int>(std::lround(w.back())));
  std::vector<double> t(static_cast<size_t>(n) + 1, 0.0);
  t[n] = 1.0;
  for (int i = 1, k = 0; i < n; ++i) {
    const double target = w.back() * i / n;
    while (w[k + 1] < target) ++k;
    t[i] = (k + (target - w[k]) / (w[k + 1] - w[k])) / kSteps;
  }
  if (curve_jitter_ > 0) {
    const std::vector<double> t0 = t;
    for (int i = 1; i < n; ++i) {
      const double u = rng_.uniform(-curve_jitter_, curve_jitter_);
      t[i] = t0[i] + u * (u < 0 ? t0[i] - t0[i - 1] : t0[i + 1] - t0[i]);
    }
  }
  std::vector<int> ids{a};
  for (int i = 1; i < n; ++i) ids.push_back(mesh_.add_vertex(curve(t[i])));
  ids.push_back(b);
  return ids;
}

/// Triangulates the patch bounded by `loop` (vertex ids, counter-clockwise seen from
/// outside), developed into the plane by to_plane and mapped back by to_surface.
void PatchMesher::add_patch(const std::vector<int>& loop, const Develop& to_plane, const Embed& to_surface) {
  const size_t nb = loop.size();
  std::vector<Vec2> q(nb);
  for (size_t i = 0; i < nb; ++i) q[i] = to_plane(mesh_.V[loop[i]]);
  double twice_area = 0;
  for (size_t i = 0; i < nb; ++i) {
    const Vec2& a = q[i];
    const Vec2& b = q[(i + 1) % nb];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  const std::vector<Vec2> inner = interior_points(q, to_surface);

  std::vector<std::pair<Cdt::Point, int>> points;
  points.reserve(nb + inner.size());
  for (size_t i = 0; i < nb; ++i) points.emplace_back(Cdt::Point(q[i].x(), q[i].y()), static_cast<int>(i));
  for (size_t j = 0; j < inner.size(); ++j)
    points.emplace_back(Cdt::Point(inner[j].x(), inner[j].y()), static_cast<int>(nb + j));
  Cdt cdt;
  cdt.insert(points.begin(), points.end());
  if (cdt.number_of_vertices() != points.size())
    throw std::logic_error("shapes: coincident points in a patch triangulation");
  std::vector<Cdt::Vertex_handle> handle(points.size());
  for (auto v : cdt.finite_vertex_handles()) handle[v->info()] = v;
  for (size_t i = 0; i < nb; ++i) cdt.insert_constraint(handle[i], handle[(i + 1) % nb]);
  if (cdt.number_of_vertices() != points.size()) throw std::logic_error("shapes: a patch boundary intersects itself");
  mark_nesting_levels(cdt);

  std::vector<int> id(points.size());
  for (size_t i = 0; i < nb; ++i) id[i] = loop[i];
  for (size_t j = 0; j < inner.size(); ++j) id[nb + j] = mesh_.add_vertex(to_surface(inner[j]));
  for (auto f : cdt.finite_face_handles()) {
    if (f->info() % 2 != 1) continue;  // outside the patch
    const int a = id[f->vertex(0)->info()], b = id[f->vertex(1)->info()], c = id[f->vertex(2)->info()];
    // CGAL faces are counter-clockwise in the plane; the loop fixes the outside.
    twice_area > 0 ? mesh_.add_triangle(a, b, c) : mesh_.add_triangle(a, c, b);
  }
}

/// A planar patch bounded by `loop` (counter-clockwise seen from outside).
void PatchMesher::add_planar_patch(const std::vector<int>& loop) {
  Vec3 n = Vec3::Zero(), o = Vec3::Zero();
  for (size_t i = 0; i < loop.size(); ++i) {
    n += position(loop[i]).cross(position(loop[(i + 1) % loop.size()]));
    o += position(loop[i]);
  }
  n.normalize();
  o /= static_cast<double>(loop.size());
  const Vec3 d = position(loop[1]) - position(loop[0]);
  const Vec3 e1 = (d - d.dot(n) * n).normalized();
  const Vec3 e2 = n.cross(e1);  // (e1, e2, n) right-handed: the loop is counter-clockwise in 2D
  add_patch(
      loop, [=](const Vec3& p) { return Vec2((p - o).dot(e1), (p - o).dot(e2)); },
      [=](const Vec2& u) -> Vec3 { return o + u.x() * e1 + u.y() * e2; });
}

/// Points strictly inside the polygon q (#q by 2, either orientation), away from its edges.
std::vector<Vec2> PatchMesher::interior_points(const std::vector<Vec2>& q, const Embed& to_surface) {
  Vec2 lo = q[0], hi = q[0];
  double h_min = std::numeric_limits<double>::infinity();
  for (const Vec2& p : q) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  for (const Vec2& p : q) h_min = std::min(h_min, size_(to_surface(p)));
  // Interior points keep half a target edge from the boundary: no sliver along it.
  constexpr double kBoundaryGap = 0.5;
  BucketGrid segments(lo, hi, h_min);
  for (size_t i = 0; i < q.size(); ++i) {
    const Vec2& a = q[i];
    const Vec2& b = q[(i + 1) % q.size()];
    segments.add(static_cast<int>(i), a.cwiseMin(b), a.cwiseMax(b));
  }
  auto far_from_boundary = [&](const Vec2& p, double gap) {
    bool far = true;
    segments.visit(p - Vec2::Constant(gap), p + Vec2::Constant(gap), [&](int i) {
      if (far && point_segment_distance(p, q[i], q[(i + 1) % q.size()]) < gap) far = false;
    });
    return far;
  };
  // Calls visit(p) for points on rows `dy` apart inside q; x from x_of(row, i).
  auto scan_rows = [&](double dy, double dx, auto&& x_of, auto&& visit) {
    const int rows = std::max(1, static_cast<int>(std::floor((hi.y() - lo.y()) / dy)));
    const double y0 = lo.y() + 0.5 * (hi.y() - lo.y() - (rows - 1) * dy);
    for (int r = 0; r < rows; ++r) {
      const double y = y0 + r * dy;
      const std::vector<double> xs = row_crossings(q, y);
      for (size_t k = 0; k + 1 < xs.size(); k += 2) {
        const int i0 = static_cast<int>(std::floor((xs[k] - lo.x()) / dx)) - 2;
        const int i1 = static_cast<int>(std::ceil((xs[k + 1] - lo.x()) / dx)) + 2;
        for (int i = i0; i <= i1; ++i) {
          const double x = x_of(r, i);
          if (x > xs[k] && x < xs[k + 1]) visit(Vec2(x, y));
        }
      }
    }
  };

  std::vector<Vec2> out;
  if (sampling_ == InteriorSampling::Lattice) {
    const double h = h_min, dy = h * std::sqrt(3.0) / 2;
    const int cols = std::max(1, static_cast<int>(std::floor((hi.x() - lo.x()) / h)));
    const double x0 = lo.x() + 0.5 * (hi.x() - lo.x() - (cols - 1) * h);
    scan_rows(
        dy, h, [&](int r, int i) { return x0 + (i + 0.5 * (r % 2)) * h; },
        [&](const Vec2& p) {
          if (far_from_boundary(p, kBoundaryGap * h)) out.push_back(p);
        });
    return out;
  }

  // Poisson disk: dense jittered candidates in random order; a candidate is kept when no
  // kept point (boundary samples included) lies within kSpacing × its target size.
  constexpr double kSpacing = 0.8;
  const double c = 0.25 * h_min;
  struct Candidate {
    Vec2 p;
    double h;
  };
  std::vector<Candidate> candidates;
  scan_rows(
      c, c, [&](int, int i) { return lo.x() + (i + rng_.uniform()) * c; },
      [&](const Vec2& p) {
        const double h = size_(to_surface(p));
        if (far_from_boundary(p, kBoundaryGap * h)) candidates.push_back({p, h});
      });
  rng_.shuffle(candidates);
  std::vector<Vec2> kept(q.begin(), q.end());
  BucketGrid near(lo, hi, kSpacing * h_min);
  for (size_t i = 0; i < kept.size(); ++i) near.add(static_cast<int>(i), kept[i], kept[i]);
  for (const Candidate& cand : candidates) {
    const double r = kSpacing * cand.h;
    bool free = true;
    near.visit(cand.p - Vec2::Constant(r), cand.p + Vec2::Constant(r), [&](int i) {
      if (free && (kept[i] - cand.p).norm() < r) free = false;
    });
    if (!free) continue;
    near.add(static_cast<int>(kept.size()), cand.p, cand.p);
    kept.push_back(cand.p);
    out.push_back(cand.p);
  }
  return out;
}

}  // namespace msmesh::detail
