// Second-order targets on the curved parts of a surface (docs/presets.md, "Jet-fitted targets"):
// a local quadric through the vertices of a first vertex update gives each face the normal of
// the smooth surface its neighbourhood lies on, instead of its plateau's.
#include "jet_targets.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstddef>

#include "parallel.h"

namespace msmesh::detail {
namespace {

/// Scratch of one thread: stamps (the face being fitted marks what it has seen) and lists.
struct JetScratch {
  std::vector<int> face_mark, vertex_mark, faces, vertices;
  JetScratch(Eigen::Index nf, Eigen::Index nv)
      : face_mark(static_cast<std::size_t>(nf), -1), vertex_mark(static_cast<std::size_t>(nv), -1) {}
};

/// The quadric's unit normal for face f in `out`; false when the face keeps its target.
bool fit_face(const PreparedMesh& mesh, const Eigen::MatrixXd& X, const Eigen::MatrixXd& N, int f, int rings,
              JetScratch& s, Eigen::RowVector3d& out) {
  const Topology& t = mesh.topology();
  const Eigen::MatrixXi& F = mesh.faces();
  static const double cos_crease = std::cos(kJetCreaseDeg * M_PI / 180);
  static const double cos_flat = std::cos(kJetFlatDeg * M_PI / 180);
  s.faces.clear();
  s.faces.push_back(f);
  s.face_mark[static_cast<std::size_t>(f)] = f;
  // Breadth first, ring by ring: faces[begin, end) is the last ring.
  for (std::size_t r = 0, begin = 0; r < static_cast<std::size_t>(rings); ++r) {
    const std::size_t end = s.faces.size();
    for (std::size_t i = begin; i < end; ++i) {
      const int g = s.faces[i];
      for (int k = 0; k < 3; ++k) {
        const int e = t.face_edges(g, k);
        if (!t.edge_is_interior[static_cast<std::size_t>(e)]) continue;
        const int h = t.edge_faces(e, 0) == g ? t.edge_faces(e, 1) : t.edge_faces(e, 0);
        if (s.face_mark[static_cast<std::size_t>(h)] == f || N.row(g).dot(N.row(h)) < cos_crease) continue;
        s.face_mark[static_cast<std::size_t>(h)] = f;
        s.faces.push_back(h);
      }
    }
    begin = end;
  }
  if (std::all_of(s.faces.begin(), s.faces.end(), [&](int g) { return N.row(f).dot(N.row(g)) >= cos_flat; }))
    return false;
  s.vertices.clear();
  for (const int g : s.faces)
    for (int k = 0; k < 3; ++k) {
      const int v = F(g, k);
      if (s.vertex_mark[static_cast<std::size_t>(v)] == f) continue;
      s.vertex_mark[static_cast<std::size_t>(v)] = f;
      s.vertices.push_back(v);
    }
  if (s.vertices.size() < static_cast<std::size_t>(kJetMinVertices)) return false;
  // The frame of the face's target (z), centred at the face's centroid.
  const Eigen::RowVector3d z = N.row(f);
  const Eigen::RowVector3d c = (X.row(F(f, 0)) + X.row(F(f, 1)) + X.row(F(f, 2))) / 3.0;
  Eigen::RowVector3d a = std::abs(z.x()) < 0.9 ? Eigen::RowVector3d(1, 0, 0) : Eigen::RowVector3d(0, 1, 0);
  a = (a - a.dot(z) * z).normalized();
  const Eigen::RowVector3d b = z.cross(a);
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  Vector6 rhs = Vector6::Zero();
  double hh = 0;
  for (const int v : s.vertices) {
    const Eigen::RowVector3d d = X.row(v) - c;
    const double x = d.dot(a), y = d.dot(b), h = d.dot(z);
    Vector6 m;
    m << x * x, x * y, y * y, x, y, 1.0;
    A.selfadjointView<Eigen::Lower>().rankUpdate(m);
    rhs += h * m;
    hh += h * h;
  }
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(A.selfadjointView<Eigen::Lower>());
  if (ldlt.info() != Eigen::Success || !(ldlt.rcond() > 1e-12)) return false;
  const Vector6 q = ldlt.solve(rhs);
  const double residual2 = (hh - q.dot(rhs)) / static_cast<double>(s.vertices.size());
  if (!(residual2 <= kJetMaxResidual * kJetMaxResidual)) return false;
  const Eigen::RowVector3d n = z - q(3) * a - q(4) * b;
  const double length = n.norm();
  if (!(length > 0) || !std::isfinite(length)) return false;
  out = n / length;
  return true;
}

}  // namespace

JetTargets fit_jet_targets(const PreparedMesh& mesh, const Eigen::MatrixXd& X, Eigen::MatrixXd& N, int rings,
                           const std::vector<bool>& fixed) {
  JetTargets out;
  const Eigen::Index nf = mesh.num_faces();
  if (rings <= 0 || nf == 0) return out;
  Eigen::MatrixXd fitted = N;
  std::vector<char> changed(static_cast<std::size_t>(nf), 0);
  const auto run = [&](Eigen::Index begin, Eigen::Index end, JetScratch& s) {
    Eigen::RowVector3d n;
    for (Eigen::Index f = begin; f < end; ++f) {
      if (!fixed.empty() && fixed[static_cast<std::size_t>(f)]) continue;
      if (!fit_face(mesh, X, N, static_cast<int>(f), rings, s, n)) continue;
      fitted.row(f) = n;
      changed[static_cast<std::size_t>(f)] = 1;
    }
  };
  // A fit reads a few dozen faces and vertices: worth about as many simple rows (parallel.h).
  constexpr Eigen::Index kRowWeight = 40;
  const Eigen::Index nb = (nf + kBlock - 1) / kBlock;
  if (nf * kRowWeight < kParallelMin) {  // no parallel construct for small meshes: parallel.h says why
    JetScratch s(nf, X.rows());
    run(0, nf, s);
  } else {
#pragma omp parallel
    {
      JetScratch s(nf, X.rows());
#pragma omp for schedule(static)
      for (Eigen::Index b = 0; b < nb; ++b) run(b * kBlock, std::min(nf, (b + 1) * kBlock), s);
    }
  }
  N = std::move(fitted);
  for (const char c : changed) out.faces += c;
  return out;
}

}  // namespace msmesh::detail
