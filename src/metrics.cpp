#include "msmesh/metrics.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hole_fill.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/topology.h"

namespace msmesh {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

constexpr double kPi = 3.141592653589793238462643383279502884;

/// Indices of the vertices some face refers to, in increasing order.
std::vector<int> referenced_vertices(Eigen::Index num_vertices, const Eigen::MatrixXi& F) {
  std::vector<bool> used(num_vertices, false);
  for (Eigen::Index i = 0; i < F.size(); ++i) used[F(i)] = true;
  std::vector<int> r;
  for (Eigen::Index v = 0; v < num_vertices; ++v)
    if (used[v]) r.push_back(int(v));
  return r;
}

/// Bounding-box diagonal of the vertices listed in `rows`.
double diagonal_of(const Eigen::MatrixXd& V, const std::vector<int>& rows) {
  if (rows.empty()) return 0.0;
  Eigen::RowVector3d lo = V.row(rows[0]), hi = lo;
  for (int v : rows) {
    lo = lo.cwiseMin(V.row(v));
    hi = hi.cwiseMax(V.row(v));
  }
  return (hi - lo).norm();
}

Eigen::Vector3d closest_on_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return a + t * ab;
}

/// First face whose vertex set differs between F and G (same #F assumed), or -1. The order of
/// a face's vertices may differ: a face listed with the opposite orientation is the same face
/// with a reversed normal, which the metrics then count as flipped.
Eigen::Index first_different_face(const Eigen::MatrixXi& F, const Eigen::MatrixXi& G) {
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    int a[3] = {F(f, 0), F(f, 1), F(f, 2)}, b[3] = {G(f, 0), G(f, 1), G(f, 2)};
    std::sort(a, a + 3);
    std::sort(b, b + 3);
    if (!std::equal(a, a + 3, b)) return f;
  }
  return -1;
}

// Points hashed on a uniform grid of cell size `cell`, for "is any point within r ≤ cell".
class PointGrid {
 public:
  PointGrid(const Eigen::MatrixXd& P, const std::vector<int>& rows, double cell) : P_(P), cell_(cell) {
    for (int i : rows) cells_[key(cell_of(P.row(i)))].push_back(i);
  }
  bool any_within(const Eigen::RowVector3d& q, double r) const {
    const std::array<long long, 3> c = cell_of(q);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (it == cells_.end()) continue;
          for (int i : it->second)
            if ((P_.row(i) - q).squaredNorm() <= r * r) return true;
        }
    return false;
  }

 private:
  std::array<long long, 3> cell_of(const Eigen::RowVector3d& p) const {
    return {static_cast<long long>(std::floor(p(0) / cell_)), static_cast<long long>(std::floor(p(1) / cell_)),
            static_cast<long long>(std::floor(p(2) / cell_))};
  }
  static unsigned long long key(const std::array<long long, 3>& c) {
    const auto u = [](long long x) { return static_cast<unsigned long long>(x) & 0x1FFFFFull; };
    return (u(c[0]) << 42) | (u(c[1]) << 21) | u(c[2]);
  }
  const Eigen::MatrixXd& P_;
  double cell_;
  std::unordered_map<unsigned long long, std::vector<int>> cells_;
};

/// truth_folded_faces() of a mesh already validated.
std::vector<char> folded_faces(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  const Eigen::Index nf = F.rows();
  // Unnormalised normals (2 × area × unit normal), summed per vertex: a face's ring is the sum
  // over its corners less itself (three times), in which its edge neighbours count twice.
  Eigen::MatrixXd C(nf, 3);
  Eigen::MatrixXd at_vertex = Eigen::MatrixXd::Zero(V.rows(), 3);
  for (Eigen::Index f = 0; f < nf; ++f) {
    const Eigen::Vector3d a = V.row(F(f, 0)), b = V.row(F(f, 1)), c = V.row(F(f, 2));
    C.row(f) = (b - a).cross(c - a).transpose();
    for (int k = 0; k < 3; ++k) at_vertex.row(F(f, k)) += C.row(f);
  }
  // The edge neighbours (on a non-manifold edge, the first two faces).
  const Topology t = build_topology(F, V.rows());
  Eigen::MatrixXd across = Eigen::MatrixXd::Zero(nf, 3);
  for (Eigen::Index e = 0; e < t.num_edges(); ++e) {
    const int f = t.edge_faces(e, 0), g = t.edge_faces(e, 1);
    if (f < 0 || g < 0) continue;
    across.row(f) += C.row(g);
    across.row(g) += C.row(f);
  }
  std::vector<char> folded(static_cast<std::size_t>(nf), 0);
  for (Eigen::Index f = 0; f < nf; ++f) {
    const Eigen::RowVector3d ring =
        at_vertex.row(F(f, 0)) + at_vertex.row(F(f, 1)) + at_vertex.row(F(f, 2)) - 3 * C.row(f);
    folded[static_cast<std::size_t>(f)] = C.row(f).dot(ring) < 0 && C.row(f).dot(across.row(f)) < 0;
  }
  return folded;
}

}  // namespace

std::vector<char> truth_folded_faces(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  validate_mesh(V, F, "truth");
  return folded_faces(V, F);
}

NormalErrors normal_errors(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& V_truth,
                           const Eigen::MatrixXi& F_truth) {
  validate_mesh(V, F, "result");
  validate_mesh(V_truth, F_truth, "truth");
  if (F.rows() != F_truth.rows()) {
    std::ostringstream os;
    os << "normal metrics need equal connectivity: result has " << F.rows() << " faces, truth " << F_truth.rows();
    throw InvalidInput(os.str());
  }
  const Eigen::Index mismatch = first_different_face(F, F_truth);
  if (mismatch >= 0) {
    const Eigen::Index f = mismatch;
    std::ostringstream os;
    os << "normal metrics need equal connectivity: face " << f << " is (" << F(f, 0) << ", " << F(f, 1) << ", "
       << F(f, 2) << ") in the result, (" << F_truth(f, 0) << ", " << F_truth(f, 1) << ", " << F_truth(f, 2)
       << ") in the truth";
    throw InvalidInput(os.str());
  }

  const Eigen::MatrixXd N = face_normals(V, F);
  const Eigen::MatrixXd Nt = face_normals(V_truth, F_truth);
  const std::vector<char> folded = folded_faces(V_truth, F_truth);
  NormalErrors e;
  e.angle_rad.resize(F.rows());
  double sum = 0, sum2 = 0, sum2_outside = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d a = N.row(f).transpose(), b = Nt.row(f).transpose();
    const bool da = a.squaredNorm() == 0, db = b.squaredNorm() == 0;
    double theta;
    if (da || db) {
      // A degenerate face has no normal: 0 when both are degenerate, else π/2 (no
      // information about the orientation; not counted as flipped).
      theta = (da && db) ? 0.0 : kPi / 2;
    } else {
      // atan2 keeps full accuracy for small angles, where acos(a·b) loses half the digits.
      theta = std::atan2(a.cross(b).norm(), a.dot(b));
    }
    e.angle_rad(f) = theta;
    sum += theta;
    sum2 += theta * theta;
    if (theta > kPi / 2) ++e.flipped;
    if (folded[static_cast<std::size_t>(f)]) {
      ++e.truth_folded;
    } else {
      sum2_outside += theta * theta;
      if (theta > kPi / 2) ++e.flipped_outside_folds;
    }
  }
  if (F.rows() > 0) {
    e.msae = sum2 / double(F.rows());
    e.mean_angle_deg = sum / double(F.rows()) * 180.0 / kPi;
  }
  if (F.rows() > e.truth_folded) e.msae_outside_folds = sum2_outside / double(F.rows() - e.truth_folded);
  return e;
}

struct SurfaceDistance::Impl {
  std::vector<Triangle> triangles;  // must outlive `tree`, which holds iterators into it
  Tree tree;
  // Used only when every face is degenerate: each face is then its longest edge.
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> segments;

  Eigen::Vector3d closest(const Eigen::Vector3d& p) const {
    if (!triangles.empty()) {
      const Point c = tree.closest_point(Point(p.x(), p.y(), p.z()));
      return {c.x(), c.y(), c.z()};
    }
    Eigen::Vector3d best = segments[0].first;
    double best_d2 = (p - best).squaredNorm();
    for (const auto& s : segments) {
      const Eigen::Vector3d c = closest_on_segment(p, s.first, s.second);
      const double d2 = (p - c).squaredNorm();
      if (d2 < best_d2) best_d2 = d2, best = c;
    }
    return best;
  }
};

SurfaceDistance::SurfaceDistance(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) : impl_(new Impl) {
  validate_mesh(V, F, "surface");
  if (F.rows() == 0) throw InvalidInput("surface distance: the surface has no faces");
  impl_->triangles.reserve(F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Point a(V(F(f, 0), 0), V(F(f, 0), 1), V(F(f, 0), 2));
    const Point b(V(F(f, 1), 0), V(F(f, 1), 1), V(F(f, 1), 2));
    const Point c(V(F(f, 2), 0), V(F(f, 2), 1), V(F(f, 2), 2));
    // Zero-area triangles are skipped: projecting onto them divides by their squared normal
    // (the test below also catches normals whose square underflows), and the segment they
    // span is normally an edge of their neighbours.
    if (CGAL::cross_product(b - a, c - a).squared_length() > 0) impl_->triangles.emplace_back(a, b, c);
  }
  if (!impl_->triangles.empty()) {
    impl_->tree.rebuild(impl_->triangles.cbegin(), impl_->triangles.cend());
    // Builds the internal KD-tree now: afterwards queries are const and thread-safe.
    impl_->tree.accelerate_distance_queries();
  } else {
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
      Eigen::Vector3d best_a, best_b;
      double best = -1;
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector3d a = V.row(F(f, k)).transpose(), b = V.row(F(f, (k + 1) % 3)).transpose();
        if ((b - a).squaredNorm() > best) best = (b - a).squaredNorm(), best_a = a, best_b = b;
      }
      impl_->segments.emplace_back(best_a, best_b);
    }
  }
}

SurfaceDistance::~SurfaceDistance() = default;
SurfaceDistance::SurfaceDistance(SurfaceDistance&&) noexcept = default;
SurfaceDistance& SurfaceDistance::operator=(SurfaceDistance&&) noexcept = default;

Eigen::MatrixXd SurfaceDistance::closest_points(const Eigen::MatrixXd& P) const {
  if (P.rows() > 0 && P.cols() != 3) {
    std::ostringstream os;
    os << "surface distance: query points must be #P by 3, got " << P.rows() << " by " << P.cols();
    throw InvalidInput(os.str());
  }
  for (Eigen::Index i = 0; i < P.rows(); ++i)
    if (!P.row(i).allFinite()) {
      std::ostringstream os;
      os << "surface distance: query point " << i << " is not finite";
      throw InvalidInput(os.str());
    }
  Eigen::MatrixXd C(P.rows(), 3);
  const Impl& impl = *impl_;
#pragma omp parallel for schedule(dynamic, 256)
  for (Eigen::Index i = 0; i < P.rows(); ++i) C.row(i) = impl.closest(P.row(i).transpose()).transpose();
  return C;
}

Eigen::VectorXd SurfaceDistance::distances(const Eigen::MatrixXd& P) const {
  const Eigen::MatrixXd C = closest_points(P);
  return (P.rows() > 0 ? Eigen::VectorXd((P - C).rowwise().norm()) : Eigen::VectorXd());
}

DistanceErrors vertex_distance_errors(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                      const Eigen::MatrixXd& V_truth, const Eigen::MatrixXi& F_truth) {
  validate_mesh(V, F, "result");
  validate_mesh(V_truth, F_truth, "truth");
  const std::vector<int> used = referenced_vertices(V.rows(), F);
  if (used.empty()) throw InvalidInput("distance metrics: the result has no faces");
  const double diag = diagonal_of(V_truth, referenced_vertices(V_truth.rows(), F_truth));
  if (!(diag > 0)) throw InvalidInput("distance metrics: the truth has no faces or a zero-size bounding box");

  Eigen::MatrixXd P(used.size(), 3);
  for (size_t i = 0; i < used.size(); ++i) P.row(i) = V.row(used[i]);
  const Eigen::VectorXd d = SurfaceDistance(V_truth, F_truth).distances(P) / diag;

  // Vertex area: a third of the area of each incident face of the result (Sun et al. 2007).
  const Eigen::VectorXd fa = face_areas(V, F);
  Eigen::VectorXd area = Eigen::VectorXd::Zero(V.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) area(F(f, k)) += fa(f) / 3.0;

  DistanceErrors e;
  double wsum = 0, wd2 = 0;
  for (size_t i = 0; i < used.size(); ++i) {
    const double w = area(used[i]);
    wsum += w;
    wd2 += w * d(i) * d(i);
  }
  e.mean = d.mean();
  e.rms = std::sqrt(d.squaredNorm() / double(d.size()));
  e.max = d.maxCoeff();
  // A result whose faces all have zero area has no weights: fall back to the plain RMS.
  e.area_weighted_rms = wsum > 0 ? std::sqrt(wd2 / wsum) : e.rms;
  return e;
}

Evaluation evaluate(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& V_truth,
                    const Eigen::MatrixXi& F_truth) {
  Evaluation ev;
  ev.distances = vertex_distance_errors(V, F, V_truth, F_truth);
  ev.same_connectivity = F.rows() == F_truth.rows() && first_different_face(F, F_truth) < 0;
  if (ev.same_connectivity) ev.normals = normal_errors(V, F, V_truth, F_truth);
  return ev;
}

InpaintErrors inpaint_errors(const Eigen::MatrixXd& V_input, const Eigen::MatrixXi& F_input,
                             const Eigen::MatrixXd& V_result, const Eigen::MatrixXi& F_result,
                             const std::vector<bool>& new_faces, const Eigen::MatrixXd& V_truth,
                             const Eigen::MatrixXi& F_truth) {
  validate_mesh(V_input, F_input, "inpainting errors: input");
  validate_mesh(V_result, F_result, "inpainting errors: result");
  validate_mesh(V_truth, F_truth, "inpainting errors: truth");
  if (F_truth.rows() == 0 || F_result.rows() == 0)
    throw InvalidInput("inpainting errors: the result and the truth need faces");
  if (!new_faces.empty() && new_faces.size() != static_cast<size_t>(F_result.rows()))
    throw InvalidInput("inpainting errors: new_faces must have one flag per result face");
  const std::vector<int> truth_rows = referenced_vertices(V_truth.rows(), F_truth);
  Eigen::MatrixXd truth_pts(static_cast<Eigen::Index>(truth_rows.size()), 3);
  for (size_t i = 0; i < truth_rows.size(); ++i)
    truth_pts.row(static_cast<Eigen::Index>(i)) = V_truth.row(truth_rows[i]);
  const double diag = bounding_box_diagonal(truth_pts);
  if (!(diag > 0)) throw InvalidInput("inpainting errors: the truth has a zero-size bounding box");

  double h = F_input.rows() ? mean_edge_length(V_input, F_input) : 0;
  if (!(h > 0)) h = mean_edge_length(V_truth, F_truth);
  const double t = 0.1 * h;
  const std::vector<int> input_rows = referenced_vertices(V_input.rows(), F_input);
  const PointGrid grid(V_input, input_rows, t);

  auto far_points = [&](const Eigen::MatrixXd& P, const std::vector<int>& rows) {
    std::vector<int> keep;
    for (int i : rows)
      if (!grid.any_within(P.row(i), t)) keep.push_back(i);
    Eigen::MatrixXd Q(static_cast<Eigen::Index>(keep.size()), 3);
    for (size_t k = 0; k < keep.size(); ++k) Q.row(static_cast<Eigen::Index>(k)) = P.row(keep[k]);
    return Q;
  };
  const Eigen::MatrixXd missing = far_points(V_truth, truth_rows);
  const Eigen::MatrixXd added = far_points(V_result, referenced_vertices(V_result.rows(), F_result));
  std::vector<double> d;
  if (missing.rows()) {
    const Eigen::VectorXd a = SurfaceDistance(V_result, F_result).distances(missing);
    d.insert(d.end(), a.data(), a.data() + a.size());
  }
  const SurfaceDistance truth_surface(V_truth, F_truth);
  if (added.rows()) {
    const Eigen::VectorXd b = truth_surface.distances(added);
    d.insert(d.end(), b.data(), b.data() + b.size());
  }
  InpaintErrors e;
  e.points = static_cast<Eigen::Index>(d.size());
  double sum = 0, sum2 = 0;
  for (double x : d) {
    e.max = std::max(e.max, x / diag);
    sum += x / diag;
    sum2 += (x / diag) * (x / diag);
  }
  if (!d.empty()) {
    e.mean = sum / double(d.size());
    e.rms = std::sqrt(sum2 / double(d.size()));
  }

  std::vector<int> nf;
  for (Eigen::Index f = 0; f < F_result.rows(); ++f)
    if (new_faces.empty() ? f >= F_input.rows() : new_faces[f]) nf.push_back(static_cast<int>(f));
  e.new_faces = static_cast<Eigen::Index>(nf.size());
  if (!nf.empty()) {
    Eigen::MatrixXi Fn(e.new_faces, 3);
    for (size_t k = 0; k < nf.size(); ++k) Fn.row(static_cast<Eigen::Index>(k)) = F_result.row(nf[k]);
    const Eigen::MatrixXd Nn = face_normals(V_result, Fn);
    const Eigen::MatrixXd B = face_barycenters(V_result, Fn);
    const Eigen::VectorXi cf = detail::closest_faces(V_truth, F_truth, B);
    const Eigen::MatrixXd Nt = face_normals(V_truth, F_truth);
    double s = 0;
    for (Eigen::Index k = 0; k < e.new_faces; ++k) {
      const Eigen::RowVector3d a = Nn.row(k), b = Nt.row(cf(k));
      s += (a.squaredNorm() == 0 || b.squaredNorm() == 0) ? 90.0
                                                          : std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * 180.0 / kPi;
    }
    e.mean_normal_error_deg = s / double(e.new_faces);
  }
  return e;
}

}  // namespace msmesh
