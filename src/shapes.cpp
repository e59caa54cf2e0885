// Procedural test shapes (shapes.h).
//
// Watertightness is built in rather than repaired: every curve shared by two patches (a cube
// edge, a crease of the CAD part, a cylinder rim) is sampled once and both patches use those
// vertices. Faces are listed counter-clockwise seen from outside.
//
// The CAD-like part and the pyramid are meshed patch by patch: each patch is developed into
// the plane, filled with interior points (a triangular lattice, or Poisson-disk samples for
// irregular meshes), triangulated by a constrained Delaunay triangulation whose constraints
// are the patch boundary, and mapped back onto the surface.
#include "msmesh/shapes.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/topology.h"

namespace msmesh {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;

void require(bool ok, const std::string& what) {
  if (!ok) throw InvalidInput(what);
}

std::string int_message(const char* function, const char* param, const char* rule, long long value) {
  std::ostringstream os;
  os << function << ": " << param << " must be " << rule << ", got " << value;
  return os.str();
}

// ---------------------------------------------------------------------------------------------
// Deterministic random numbers: splitmix64 (Steele, Lea, Flood 2014). Unlike the standard
// distributions, its output is the same with every compiler and library.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1).
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  /// Uniform in [a, b).
  double uniform(double a, double b) { return a + (b - a) * uniform(); }
  /// Fisher–Yates shuffle.
  template <class T>
  void shuffle(std::vector<T>& v) {
    for (size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[next() % i]);
  }

 private:
  std::uint64_t state_;
};

// ---------------------------------------------------------------------------------------------
/// Growing vertex and face lists.
struct MeshBuilder {
  std::vector<Vec3> V;
  std::vector<Eigen::Vector3i> F;

  int add_vertex(const Vec3& p) {
    V.push_back(p);
    return static_cast<int>(V.size()) - 1;
  }
  void add_triangle(int a, int b, int c) { F.emplace_back(a, b, c); }
  /// Quad a, b, c, d (counter-clockwise seen from outside), split along a–c.
  void add_quad(int a, int b, int c, int d) {
    add_triangle(a, b, c);
    add_triangle(a, c, d);
  }
  Mesh to_mesh() const {
    Mesh m;
    m.V.resize(static_cast<Eigen::Index>(V.size()), 3);
    for (size_t i = 0; i < V.size(); ++i) m.V.row(static_cast<Eigen::Index>(i)) = V[i].transpose();
    m.F.resize(static_cast<Eigen::Index>(F.size()), 3);
    for (size_t i = 0; i < F.size(); ++i) m.F.row(static_cast<Eigen::Index>(i)) = F[i].transpose();
    return m;
  }
};

/// Translates V (#V by 3) so that its bounding box is centred at the origin.
void centre_bounding_box(Eigen::MatrixXd& V) {
  const Eigen::RowVector3d c = 0.5 * (V.colwise().minCoeff() + V.colwise().maxCoeff());
  V.rowwise() -= c;
}

/// Keeps the faces of F (#F by 3) with keep[f] and the vertices they use, re-indexed in
/// their original order.
Mesh submesh(const Mesh& m, const std::vector<bool>& keep) {
  std::vector<int> new_index(static_cast<size_t>(m.V.rows()), -1);
  Eigen::Index nf = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    if (keep[f]) {
      ++nf;
      for (int k = 0; k < 3; ++k) new_index[m.F(f, k)] = 0;
    }
  int nv = 0;
  for (int& i : new_index)
    if (i == 0) i = nv++;
  Mesh out;
  out.V.resize(nv, 3);
  for (Eigen::Index v = 0; v < m.V.rows(); ++v)
    if (new_index[v] >= 0) out.V.row(new_index[v]) = m.V.row(v);
  out.F.resize(nf, 3);
  Eigen::Index g = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    if (keep[f]) {
      for (int k = 0; k < 3; ++k) out.F(g, k) = new_index[m.F(f, k)];
      ++g;
    }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Disk caps of the cylinder: concentric rings whose vertex counts grow linearly with the
// radius, so that triangles stay near-equilateral from the centre to the rim.

/// Triangulates the annulus between two closed rings (vertex ids with their polar angles,
/// increasing, each ring starting near angle 0). `up`: counter-clockwise seen from +z.
void zip_rings(MeshBuilder& b, const std::vector<int>& inner, double inner_offset, const std::vector<int>& outer,
               double outer_offset, bool up) {
  const int ni = static_cast<int>(inner.size()), no = static_cast<int>(outer.size());
  auto emit = [&](int a, int c, int d) { up ? b.add_triangle(a, c, d) : b.add_triangle(a, d, c); };
  int i = 0, o = 0;
  while (i < ni || o < no) {
    const double next_inner = inner_offset + 2 * kPi * (i + 1) / ni;
    const double next_outer = outer_offset + 2 * kPi * (o + 1) / no;
    if (o < no && (i == ni || next_outer <= next_inner)) {
      emit(inner[i % ni], outer[o % no], outer[(o + 1) % no]);
      ++o;
    } else {
      emit(inner[i % ni], outer[o % no], inner[(i + 1) % ni]);
      ++i;
    }
  }
}

/// Adds a flat disk of radius 1 at height z whose rim is `rim` (vertex i at angle 2πi/#rim).
void add_disk_cap(MeshBuilder& b, const std::vector<int>& rim, double z, bool up) {
  const int n = static_cast<int>(rim.size());
  // Radial spacing 1/m matches the rim spacing 2π/n.
  const int m = std::max(1, static_cast<int>(std::lround(n / (2 * kPi))));
  std::vector<int> outer = rim;
  double outer_offset = 0;
  for (int k = m - 1; k >= 1; --k) {
    const int count = std::max(3, static_cast<int>(std::lround(double(n) * k / m)));
    // Alternate rings are turned by half a step so that vertices of neighbouring rings interleave.
    const double offset = ((m - k) % 2) ? kPi / count : 0.0;
    const double r = double(k) / m;
    std::vector<int> ring(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
      const double a = offset + 2 * kPi * i / count;
      ring[i] = b.add_vertex(Vec3(r * std::cos(a), r * std::sin(a), z));
    }
    zip_rings(b, ring, offset, outer, outer_offset, up);
    outer = std::move(ring);
    outer_offset = offset;
  }
  const int centre = b.add_vertex(Vec3(0, 0, z));
  const int no = static_cast<int>(outer.size());
  for (int i = 0; i < no; ++i) {
    if (up)
      b.add_triangle(centre, outer[i], outer[(i + 1) % no]);
    else
      b.add_triangle(centre, outer[(i + 1) % no], outer[i]);
  }
}

// ---------------------------------------------------------------------------------------------
// Patch meshing for the CAD-like part and the pyramid.

/// Target edge length at a point of the surface.
using SizeField = std::function<double(const Vec3&)>;
/// A curve t ∈ [0,1] ↦ R³.
using Curve = std::function<Vec3(double)>;
/// Isometric development of a patch into the plane, and its inverse.
using Develop = std::function<Vec2(const Vec3&)>;
using Embed = std::function<Vec3(const Vec2&)>;

enum class InteriorSampling {
  Lattice,      ///< equilateral triangular lattice (regular meshes; constant size field)
  PoissonDisk,  ///< randomised maximal Poisson-disk samples (irregular meshes; any size field)
};

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

/// Builds a mesh patch by patch. Corners and curves are created first; each patch is then
/// bounded by a loop of curve vertices, so patches sharing a curve share its vertices.
class PatchMesher {
 public:
  /// size: target edge length; sampling: how patch interiors are filled; seed: random
  /// numbers (Poisson-disk sampling and curve jitter); curve_jitter in [0, 0.4]: curve
  /// samples move by up to this fraction of the gap to their neighbour.
  PatchMesher(SizeField size, InteriorSampling sampling, std::uint64_t seed = 0, double curve_jitter = 0)
      : size_(std::move(size)), sampling_(sampling), rng_(seed), curve_jitter_(curve_jitter) {}

  int add_corner(const Vec3& p) { return mesh_.add_vertex(p); }
  const Vec3& position(int v) const { return mesh_.V[v]; }

  /// Samples `curve` (curve(0) at corner a, curve(1) at corner b) with edges of about the
  /// target size. Returns the vertex ids along it, a first and b last.
  std::vector<int> add_curve(int a, int b, const Curve& curve) {
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
  void add_patch(const std::vector<int>& loop, const Develop& to_plane, const Embed& to_surface) {
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
    if (cdt.number_of_vertices() != points.size())
      throw std::logic_error("shapes: a patch boundary intersects itself");
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
  void add_planar_patch(const std::vector<int>& loop) {
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

  Mesh to_mesh() const { return mesh_.to_mesh(); }

 private:
  /// Points strictly inside the polygon q (#q by 2, either orientation), away from its edges.
  std::vector<Vec2> interior_points(const std::vector<Vec2>& q, const Embed& to_surface) {
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

  /// Face info = number of constraints crossed from the outside (odd: inside the patch).
  static void mark_nesting_levels(Cdt& cdt) {
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

  MeshBuilder mesh_;
  SizeField size_;
  InteriorSampling sampling_;
  SplitMix64 rng_;
  double curve_jitter_;
};

/// Appends a curve's vertex ids to a patch loop, without its last one (the next curve's first).
void append_curve(std::vector<int>& loop, const std::vector<int>& curve, bool reversed = false) {
  if (reversed)
    loop.insert(loop.end(), curve.rbegin(), curve.rend() - 1);
  else
    loop.insert(loop.end(), curve.begin(), curve.end() - 1);
}

// ---------------------------------------------------------------------------------------------
// The CAD-like part: a planar profile of lines and arcs, extruded along z.

/// A straight segment or circular arc of a planar profile, parametrised by t ∈ [0,1].
struct ProfileSegment {
  Vec2 a, b;  ///< end points
  bool is_arc = false;
  Vec2 centre = Vec2::Zero();  ///< arc: centre + radius (cos, sin)(angle0 + t sweep)
  double radius = 0, angle0 = 0, sweep = 0;

  double length() const { return is_arc ? radius * std::abs(sweep) : (b - a).norm(); }
  Vec2 at(double t) const {
    if (!is_arc) return a + t * (b - a);
    const double angle = angle0 + t * sweep;
    return centre + radius * Vec2(std::cos(angle), std::sin(angle));
  }
  /// Arc length from a to p, for p on the segment.
  double arclength(const Vec2& p) const {
    if (!is_arc) return (p - a).dot((b - a).normalized());
    const Vec2 d = p - centre;
    const double turned = std::remainder(std::atan2(d.y(), d.x()) - angle0, 2 * kPi);
    return length() * turned / sweep;
  }
};

/// Draws a profile as a turtle: lines, turns and tangent arcs (degrees, positive = left).
class Turtle {
 public:
  Vec2 position() const { return position_; }
  void turn(double degrees) { heading_ += degrees * kPi / 180; }
  void line(double length) {
    ProfileSegment s;
    s.a = position_;
    s.b = position_ + length * Vec2(std::cos(heading_), std::sin(heading_));
    segments_.push_back(s);
    position_ = s.b;
  }
  /// An arc tangent to the current heading, turning by `degrees` (left when positive).
  void arc(double radius, double degrees) {
    const double sweep = degrees * kPi / 180, side = sweep > 0 ? 1.0 : -1.0;
    ProfileSegment s;
    s.is_arc = true;
    s.a = position_;
    s.radius = radius;
    s.centre = position_ + side * radius * Vec2(-std::sin(heading_), std::cos(heading_));
    s.angle0 = heading_ - side * kPi / 2;
    s.sweep = sweep;
    s.b = s.at(1.0);
    segments_.push_back(s);
    position_ = s.b;
    heading_ += sweep;
  }
  /// Ends the last segment exactly at the first segment's start.
  std::vector<ProfileSegment> close() {
    segments_.back().b = segments_.front().a;
    return segments_;
  }

 private:
  Vec2 position_ = Vec2::Zero();
  double heading_ = 0;
  std::vector<ProfileSegment> segments_;
};

/// The profile of the CAD-like part, counter-clockwise, in [0,2] × [0,0.7]. Crease angles
/// (between outward normals) at its corners are noted on each turn.
std::vector<ProfileSegment> fandisk_profile() {
  Turtle t;
  t.line(2.0);       // bottom
  t.turn(90);        // 90°
  t.line(0.4);       // right wall
  t.turn(45);        // 45°
  t.line(0.35);      // chamfer
  t.turn(30);        // 30°
  t.arc(1.5, 40);    // cylindrical roof …
  t.line(0.3);       // … blending tangentially into a flat slope (one smooth patch)
  t.turn(-115);      // 115°, concave
  t.line(0.25);      // step wall
  t.turn(90);        // 90°
  t.line(t.position().x());  // tower top
  t.turn(90);        // 90°
  t.line(t.position().y());  // left wall, back down to the start (90° with the bottom)
  return t.close();
}

/// Height of the slanted front cap above the back cap z = 0 (creases of 68°–112° with the walls).
double fandisk_front_z(const Vec2& p) { return 0.6 + 0.4 * p.x(); }

/// Surface patches of the part: bottom, right wall, chamfer, roof + slope, step wall, tower
/// top, left wall, back cap, front cap.
constexpr int kFandiskPatches = 9;
/// Target edge length times the resolution n.
constexpr double kFandiskEdge = 1.25;

// ---------------------------------------------------------------------------------------------
// Holes of make_cube_with_holes.

/// Hole centres: an edge midpoint, a face centre, then the remaining edge midpoints, face
/// centres and corners of [-1,1]^3, each the farthest from those already chosen.
std::vector<Vec3> hole_centres(int count) {
  std::vector<Vec3> sites;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x != 0 || y != 0 || z != 0) sites.emplace_back(x, y, z);
  std::vector<Vec3> chosen{Vec3(1, 0, 1), Vec3(-1, 0, 0)};
  chosen.resize(std::min<size_t>(chosen.size(), static_cast<size_t>(count)));
  while (static_cast<int>(chosen.size()) < count) {
    double best = -1;
    Vec3 pick = Vec3::Zero();
    for (const Vec3& s : sites) {
      double d = std::numeric_limits<double>::infinity();
      for (const Vec3& c : chosen) d = std::min(d, (s - c).norm());
      if (d > best + 1e-12) {
        best = d;
        pick = s;
      }
    }
    chosen.push_back(pick);
  }
  return chosen;
}

constexpr int kMaxHoles = 26;
constexpr double kHoleRadius = 0.3;  // faces whose barycentre is this close to a centre go

}  // namespace

// =============================================================================================

Mesh make_cube(int n) {
  require(n >= 1, int_message("make_cube", "n", ">= 1", n));
  MeshBuilder b;
  // Lattice points (i, j, k) ∈ {0..n}^3 on the surface; each exists once, so the 12 edges
  // and 8 corners are shared by the faces meeting there.
  std::unordered_map<long long, int> index;
  auto vertex = [&](const std::array<int, 3>& ijk) {
    const long long key = (static_cast<long long>(ijk[0]) * (n + 1) + ijk[1]) * (n + 1) + ijk[2];
    const auto [it, inserted] = index.try_emplace(key, static_cast<int>(b.V.size()));
    if (inserted) b.add_vertex(Vec3(-1 + 2.0 * ijk[0] / n, -1 + 2.0 * ijk[1] / n, -1 + 2.0 * ijk[2] / n));
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      // Tangent axes with e_u × e_v = outward normal ±e_axis.
      int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if (side == 0) std::swap(u, v);
      auto at = [&](int i, int j) {
        std::array<int, 3> ijk;
        ijk[axis] = side * n;
        ijk[u] = i;
        ijk[v] = j;
        return vertex(ijk);
      };
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) b.add_quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  return b.to_mesh();
}

Mesh make_cylinder(int segments, int rings, bool caps) {
  require(segments >= 3, int_message("make_cylinder", "segments", ">= 3", segments));
  require(rings >= 1, int_message("make_cylinder", "rings", ">= 1", rings));
  MeshBuilder b;
  for (int j = 0; j <= rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const double a = 2 * kPi * i / segments;
      b.add_vertex(Vec3(std::cos(a), std::sin(a), -1 + 2.0 * j / rings));
    }
  auto side = [&](int i, int j) { return j * segments + i % segments; };
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < segments; ++i) b.add_quad(side(i, j), side(i + 1, j), side(i + 1, j + 1), side(i, j + 1));
  if (caps) {
    std::vector<int> bottom(static_cast<size_t>(segments)), top(static_cast<size_t>(segments));
    for (int i = 0; i < segments; ++i) {
      bottom[i] = side(i, 0);
      top[i] = side(i, rings);
    }
    add_disk_cap(b, bottom, -1.0, false);
    add_disk_cap(b, top, 1.0, true);
  }
  return b.to_mesh();
}

Mesh make_sphere(int subdivisions) {
  require(subdivisions >= 0 && subdivisions <= 10,
          int_message("make_sphere", "subdivisions", "in [0, 10]", subdivisions));
  const double t = (1 + std::sqrt(5.0)) / 2;
  MeshBuilder b;
  const double ico[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                             {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (const auto& p : ico) b.add_vertex(Vec3(p[0], p[1], p[2]).normalized());
  const int faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                            {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                            {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (const auto& f : faces) b.add_triangle(f[0], f[1], f[2]);
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int i, int j) {
      const auto key = std::minmax(i, j);
      const auto [it, inserted] = midpoint.try_emplace(key, static_cast<int>(b.V.size()));
      if (inserted) b.add_vertex((b.V[i] + b.V[j]).normalized());
      return it->second;
    };
    std::vector<Eigen::Vector3i> coarse;
    coarse.swap(b.F);
    for (const Eigen::Vector3i& f : coarse) {
      const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      b.add_triangle(f[0], ab, ca);
      b.add_triangle(f[1], bc, ab);
      b.add_triangle(f[2], ca, bc);
      b.add_triangle(ab, bc, ca);
    }
  }
  return b.to_mesh();
}

Mesh make_torus(int major_segments, int minor_segments) {
  require(major_segments >= 3, int_message("make_torus", "major_segments", ">= 3", major_segments));
  require(minor_segments >= 3, int_message("make_torus", "minor_segments", ">= 3", minor_segments));
  constexpr double R = 1.0, r = 0.4;
  MeshBuilder b;
  for (int j = 0; j < minor_segments; ++j)
    for (int i = 0; i < major_segments; ++i) {
      const double u = 2 * kPi * i / major_segments, v = 2 * kPi * j / minor_segments;
      b.add_vertex(Vec3((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)));
    }
  // ∂/∂u × ∂/∂v points outwards, so (u, v) quads are counter-clockwise seen from outside.
  auto at = [&](int i, int j) { return (j % minor_segments) * major_segments + i % major_segments; };
  for (int j = 0; j < minor_segments; ++j)
    for (int i = 0; i < major_segments; ++i) b.add_quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  return b.to_mesh();
}

int fandisk_like_patch_count() { return kFandiskPatches; }

Mesh make_fandisk_like(int n) {
  require(n >= 1, int_message("make_fandisk_like", "n", ">= 1", n));
  const std::vector<ProfileSegment> profile = fandisk_profile();
  const int k = static_cast<int>(profile.size());
  const double h = kFandiskEdge / n;
  PatchMesher mesher([h](const Vec3&) { return h; }, InteriorSampling::Lattice);

  // Corners at the back (z = 0) and front of each profile vertex, then the curves joining them.
  std::vector<int> back(k), front(k);
  for (int j = 0; j < k; ++j) {
    const Vec2 p = profile[j].a;
    back[j] = mesher.add_corner(Vec3(p.x(), p.y(), 0));
    front[j] = mesher.add_corner(Vec3(p.x(), p.y(), fandisk_front_z(p)));
  }
  std::vector<std::vector<int>> along(k), back_curve(k), front_curve(k);
  for (int j = 0; j < k; ++j) {
    const Vec2 p = profile[j].a;
    const ProfileSegment& s = profile[j];
    along[j] = mesher.add_curve(back[j], front[j], [&](double t) { return Vec3(p.x(), p.y(), t * fandisk_front_z(p)); });
    back_curve[j] = mesher.add_curve(back[j], back[(j + 1) % k], [&](double t) {
      const Vec2 x = s.at(t);
      return Vec3(x.x(), x.y(), 0);
    });
    front_curve[j] = mesher.add_curve(front[j], front[(j + 1) % k], [&](double t) {
      const Vec2 x = s.at(t);
      return Vec3(x.x(), x.y(), fandisk_front_z(x));
    });
  }
  // Walls, developed isometrically into (arc length, z).
  for (int j = 0; j < k; ++j) {
    const ProfileSegment& s = profile[j];
    std::vector<int> loop;
    append_curve(loop, back_curve[j]);
    append_curve(loop, along[(j + 1) % k]);
    append_curve(loop, front_curve[j], true);
    append_curve(loop, along[j], true);
    const double length = s.length();
    mesher.add_patch(
        loop, [&](const Vec3& p) { return Vec2(s.arclength(p.head<2>()), p.z()); },
        [&](const Vec2& u) -> Vec3 {
          const Vec2 x = s.at(u.x() / length);
          return Vec3(x.x(), x.y(), u.y());
        });
  }
  // Back cap (outward -z: the profile reversed) and slanted front cap.
  std::vector<int> back_loop, front_loop;
  for (int j = k - 1; j >= 0; --j) append_curve(back_loop, back_curve[j], true);
  for (int j = 0; j < k; ++j) append_curve(front_loop, front_curve[j]);
  mesher.add_planar_patch(back_loop);
  mesher.add_planar_patch(front_loop);

  Mesh m = mesher.to_mesh();
  centre_bounding_box(m.V);
  return m;
}

Mesh make_pyramid(int n, std::uint64_t seed) {
  require(n >= 1, int_message("make_pyramid", "n", ">= 1", n));
  // Target edge length grows linearly from 0.4 h at x = -1 to h at x = 1.
  const double h = 2.0 / n;
  PatchMesher mesher([h](const Vec3& p) { return h * (0.4 + 0.3 * (std::clamp(p.x(), -1.0, 1.0) + 1)); },
                     InteriorSampling::PoissonDisk, seed, 0.3);
  std::array<int, 4> base;
  const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int i = 0; i < 4; ++i) base[i] = mesher.add_corner(Vec3(corner[i][0], corner[i][1], -0.6));
  const int apex = mesher.add_corner(Vec3(0, 0, 0.6));
  auto segment = [&](int a, int b) {
    const Vec3 pa = mesher.position(a), pb = mesher.position(b);
    return mesher.add_curve(a, b, [=](double t) -> Vec3 { return pa + t * (pb - pa); });
  };
  std::array<std::vector<int>, 4> base_edge, lateral;
  for (int i = 0; i < 4; ++i) base_edge[i] = segment(base[i], base[(i + 1) % 4]);
  for (int i = 0; i < 4; ++i) lateral[i] = segment(base[i], apex);
  std::vector<int> bottom;
  for (int i = 3; i >= 0; --i) append_curve(bottom, base_edge[i], true);
  mesher.add_planar_patch(bottom);
  for (int i = 0; i < 4; ++i) {
    std::vector<int> loop;
    append_curve(loop, base_edge[i]);
    append_curve(loop, lateral[(i + 1) % 4]);
    append_curve(loop, lateral[i], true);
    mesher.add_planar_patch(loop);
  }
  return mesher.to_mesh();
}

Mesh make_cube_with_holes(int n, int holes) {
  require(n >= 4, int_message("make_cube_with_holes", "n", ">= 4", n));
  require(holes >= 0 && holes <= kMaxHoles, int_message("make_cube_with_holes", "holes", "in [0, 26]", holes));
  const Mesh cube = make_cube(n);
  const std::vector<Vec3> centres = hole_centres(holes);
  const Eigen::MatrixXd B = face_barycenters(cube.V, cube.F);
  std::vector<bool> keep(static_cast<size_t>(cube.F.rows()), true);
  for (Eigen::Index f = 0; f < B.rows(); ++f)
    for (const Vec3& c : centres)
      if ((B.row(f).transpose() - c).norm() < kHoleRadius) keep[f] = false;

  // Clean up until every hole is bounded by one simple loop: keep the largest connected piece
  // (no islands inside a hole) and clear the fan of any vertex where two holes or two parts of
  // one hole touch (more than two boundary edges).
  for (bool changed = true; changed;) {
    changed = false;
    Eigen::MatrixXi F(std::count(keep.begin(), keep.end(), true), 3);
    std::vector<Eigen::Index> original;
    for (Eigen::Index f = 0; f < cube.F.rows(); ++f)
      if (keep[f]) {
        F.row(static_cast<Eigen::Index>(original.size())) = cube.F.row(f);
        original.push_back(f);
      }
    const Topology topo = build_topology(F, cube.V.rows());
    int components = 0;
    const Eigen::VectorXi label = face_components(topo, &components);
    if (components > 1) {
      std::vector<int> size(static_cast<size_t>(components), 0);
      for (Eigen::Index f = 0; f < label.size(); ++f) ++size[label(f)];
      const int largest = static_cast<int>(std::max_element(size.begin(), size.end()) - size.begin());
      for (Eigen::Index f = 0; f < label.size(); ++f)
        if (label(f) != largest) keep[original[f]] = false;
      changed = true;
      continue;
    }
    std::vector<int> boundary_edges(static_cast<size_t>(cube.V.rows()), 0);
    for (Eigen::Index e = 0; e < topo.num_edges(); ++e)
      if (topo.edge_face_count(e) == 1) {
        ++boundary_edges[topo.edges(e, 0)];
        ++boundary_edges[topo.edges(e, 1)];
      }
    for (Eigen::Index f = 0; f < F.rows(); ++f)
      for (int k = 0; k < 3; ++k)
        if (boundary_edges[F(f, k)] > 2) {
          keep[original[f]] = false;
          changed = true;
        }
  }
  Mesh out = submesh(cube, keep);
  // Only at n = 4 do neighbouring holes (1 apart) come close enough to merge.
  const TopologySummary s = summarize_topology(out.F, build_topology(out.F, out.V.rows()));
  if (static_cast<int>(s.boundary_loops.size()) != holes) {
    std::ostringstream os;
    os << "make_cube_with_holes: " << holes << " holes merge into " << s.boundary_loops.size()
       << " at n = " << n << "; use a larger n";
    throw InvalidInput(os.str());
  }
  return out;
}

std::vector<std::string> shape_names() { return {"cube", "cylinder", "sphere", "torus", "fandisk", "pyramid", "holes"}; }

namespace {
[[noreturn]] void unknown_shape(const std::string& name) {
  std::string list;
  for (const std::string& s : shape_names()) list += (list.empty() ? "" : ", ") + s;
  throw InvalidInput("unknown shape '" + name + "'; valid names: " + list);
}
}  // namespace

Mesh make_shape(const std::string& name, int resolution) {
  require(resolution >= 1, int_message("make_shape", "resolution", ">= 1", resolution));
  const int r = resolution;
  if (name == "cube") return make_cube(r);
  // Edges of about 2/r, as on the cube: π r around, r along the height 2.
  if (name == "cylinder") return make_cylinder(std::max(3, static_cast<int>(std::lround(kPi * r))), r);
  // About as many faces as the cube: 20·4^s ≈ 12 r².
  if (name == "sphere")
    return make_sphere(std::clamp(static_cast<int>(std::lround(std::log(0.6 * r * r) / std::log(4.0))), 0, 10));
  // Tube steps of 360°/3r (15° at r = 8) keep the torus one smooth patch; 5:3 keeps its
  // outer quads from stretching.
  if (name == "torus") return make_torus(5 * r, 3 * r);
  if (name == "fandisk") return make_fandisk_like(r);
  if (name == "pyramid") return make_pyramid(r, 1);
  if (name == "holes") return make_cube_with_holes(std::max(4, r), 2);
  unknown_shape(name);
}

int shape_patch_count(const std::string& name) {
  if (name == "cube" || name == "holes") return 6;
  if (name == "cylinder") return 3;
  if (name == "sphere" || name == "torus") return 1;
  if (name == "pyramid") return 5;
  if (name == "fandisk") return fandisk_like_patch_count();
  unknown_shape(name);
}

}  // namespace msmesh
