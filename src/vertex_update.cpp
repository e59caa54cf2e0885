#include "msmesh/vertex_update.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <sstream>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/operators.h"
#include "msmesh/topology.h"
#include "normalize.h"
#include "parallel.h"
#include "pcg.h"
#include "sparse_solve.h"

namespace msmesh {

void VertexUpdateOptions::validate() const {
  auto fail = [](const char* name, double value, const char* range) {
    std::ostringstream os;
    os << "vertex update: " << name << " = " << value << " is out of range; valid: " << range;
    throw InvalidInput(os.str());
  };
  if (!(std::isfinite(omega1) && omega1 > 0)) fail("omega1", omega1, "> 0");
  if (!(std::isfinite(omega2) && omega2 >= 0)) fail("omega2", omega2, ">= 0");
  if (!(std::isfinite(omega3) && omega3 > 0)) fail("omega3", omega3, "> 0");
  if (max_iterations < 1 || max_iterations > 100000) fail("max_iterations", max_iterations, "[1, 100000]");
  if (!(std::isfinite(tolerance) && tolerance >= 0)) fail("tolerance", tolerance, ">= 0");
  if (!(std::isfinite(solver_tolerance) && solver_tolerance > 0 && solver_tolerance < 1))
    fail("solver_tolerance", solver_tolerance, "(0, 1)");
}

namespace {

using Triplet = Eigen::Triplet<double>;

// The vertex opposite edge slot k of face f is F(f,k) (face_edges(f,k) is opposite corner k).
int opposite_vertex(const Eigen::MatrixXi& F, const Topology& t, int f, Eigen::Index e) {
  for (int k = 0; k < 3; ++k)
    if (t.face_edges(f, k) == e) return F(f, k);
  return -1;
}

}  // namespace

VertexUpdateResult update_vertices(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& N,
                                   const Eigen::VectorXd& v_in, const VertexUpdateOptions& o,
                                   const VertexUpdateWeights& weights, const ProgressCallback& progress) {
  o.validate();
  validate_mesh(V, F, "vertex update");
  const Eigen::Index nv = V.rows(), nf = F.rows();
  if (N.rows() != nf || N.cols() != 3) throw InvalidInput("vertex update: target normals must be #F by 3");
  const Topology topo = build_topology(F, nv);
  const Eigen::Index ne = topo.num_edges();
  Eigen::VectorXd v = v_in.size() ? v_in : Eigen::VectorXd::Ones(ne);
  if (v.size() != ne) throw InvalidInput("vertex update: edge field v must have one value per edge");
  Eigen::VectorXd w3 = Eigen::VectorXd::Ones(nv);
  if (weights.vertex_omega3.size()) {
    if (weights.vertex_omega3.size() != nv) throw InvalidInput("vertex update: vertex_omega3 must have #V entries");
    w3 = weights.vertex_omega3;
    if ((w3.array() < 0).any() || !w3.allFinite()) throw InvalidInput("vertex update: vertex_omega3 must be finite and >= 0");
  }
  VertexUpdateResult res;
  if (nf == 0) {
    res.V = V;
    res.converged = true;
    return res;
  }
  const detail::Normalization norm = detail::normalization_for(V, F, edge_lengths(V, topo).mean());
  const Eigen::MatrixXd V0 = norm.apply(V);

  // K (3T×P): row 3i+k gives corner k of face i minus the face's mean (the centring matrix M).
  std::vector<Triplet> kt;
  kt.reserve(static_cast<size_t>(9 * nf));
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) kt.emplace_back(3 * f + k, F(f, j), (j == k ? 2.0 : -1.0) / 3.0);
  SparseMatrix K(3 * nf, nv);
  K.setFromTriplets(kt.begin(), kt.end());
  // H: row per interior edge e = (i1,i2) with opposite vertices i3, i4: v_e (x1 + x2 − x3 − x4).
  std::vector<Triplet> ht;
  Eigen::Index hrows = 0;
  for (Eigen::Index e = 0; e < ne; ++e) {
    if (!topo.edge_is_interior[e]) continue;
    const int i3 = opposite_vertex(F, topo, topo.edge_faces(e, 0), e);
    const int i4 = opposite_vertex(F, topo, topo.edge_faces(e, 1), e);
    const double ve = v(e);
    ht.emplace_back(hrows, topo.edges(e, 0), ve);
    ht.emplace_back(hrows, topo.edges(e, 1), ve);
    ht.emplace_back(hrows, i3, -ve);
    ht.emplace_back(hrows, i4, -ve);
    ++hrows;
  }
  SparseMatrix H(hrows, nv);
  H.setFromTriplets(ht.begin(), ht.end());
  const Eigen::VectorXd d3 = o.omega3 * w3;
  // eq. 27: (ω₁KᵀK + ω₂HᵀH + ω₃I) V = ω₁KᵀP + ω₃V⁰; factor once.
  SparseMatrix A = o.omega1 * SparseMatrix(K.transpose() * K);
  if (o.omega2 > 0) A += o.omega2 * SparseMatrix(H.transpose() * H);
  // A tiny floor keeps vertices with ω₃ multiplier 0 and no face (isolated) well-posed.
  A += SparseMatrix(d3.cwiseMax(1e-10).asDiagonal());
  // Auto: the factorisation below kCgMinVertices vertices (cheap there, and exact), conjugate
  // gradients above (linear cost; κ is bounded by about (6ω₁ + 16ω₂ + ω₃)/ω₃), unless
  // per-vertex weights lower ω₃ somewhere (inpainting: new vertices are free), which makes
  // the system badly conditioned: then factor it at any size (docs/performance.md).
  constexpr Eigen::Index kCgMinVertices = 40000;
  const bool use_cg = o.solver == LinearSolver::CG ||
                      (o.solver == LinearSolver::Auto && nv >= kCgMinVertices && w3.minCoeff() >= 0.5);
  std::unique_ptr<detail::FixedCholesky> chol;
  std::unique_ptr<detail::BlockPcg> pcg;
  if (use_cg)
    pcg = std::make_unique<detail::BlockPcg>(A);
  else
    chol = std::make_unique<detail::FixedCholesky>(A, "vertex update");
  A = SparseMatrix();
  const detail::RowSparse Kt = o.omega1 * K.transpose();  // row-major: one row per vertex
  K = SparseMatrix();
  using Rows = detail::RowMatrixX3;
  const Rows rhs0 = detail::to_rows(d3.asDiagonal() * V0);

  Rows X = detail::to_rows(V0), X_prev(nv, 3), X_old(nv, 3), rhs(nv, 3), P(3 * nf, 3);
  for (int k = 0; k < o.max_iterations; ++k) {
    // P-step (eq. 25), per face.
    Eigen::Index fallbacks = 0;
#pragma omp parallel for schedule(static) reduction(+ : fallbacks) if (nf >= detail::kParallelMin)
    for (Eigen::Index f = 0; f < nf; ++f) {
      Eigen::Matrix3d C;  // rows: centred corners M V_f
      for (int c = 0; c < 3; ++c) C.row(c) = X.row(F(f, c));
      const Eigen::RowVector3d mean = C.colwise().mean();
      C.rowwise() -= mean;
      const Eigen::Vector3d nt = N.row(f).transpose();
      const Eigen::Matrix3d proj = Eigen::Matrix3d::Identity() - nt * nt.transpose();
      Eigen::Matrix3d Ph = C * proj;
      const Eigen::Vector3d cur = (C.row(1) - C.row(0)).transpose().cross((C.row(2) - C.row(0)).transpose());
      if (cur.dot(nt) < 0) {
        // Closest degenerate triangle: project onto the top right-singular direction h of P̂
        // (the top eigenvector of P̂ᵀP̂).
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(Ph.transpose() * Ph);
        const Eigen::Vector3d h = es.eigenvectors().col(2);
        Ph = Ph * (h * h.transpose());
        ++fallbacks;
      }
      P.block<3, 3>(3 * f, 0) = Ph;
    }
    // V-step (eq. 27): rhs = ω₁KᵀP + ω₃V⁰, row by row.
    detail::parallel_for(nv, [&](Eigen::Index i) {
      Eigen::RowVector3d b = rhs0.row(i);
      for (detail::RowSparse::InnerIterator it(Kt, i); it; ++it) b += it.value() * P.row(it.col());
      rhs.row(i) = b;
    });
    if (use_cg && k >= 1) {
      // Warm start on the secant X_k + (X_k − X_{k−1}): the vertices move smoothly from one
      // iteration to the next, and this saves about a fifth of the CG sweeps (Cone: 1153 →
      // 940). Only the starting point changes, not the solution.
      X_prev = X;
      X += X - X_old;
    } else {
      X_prev = X;
    }
    if (use_cg) {
      const detail::PcgStats st = pcg->solve(rhs, X, o.solver_tolerance, 100000, "vertex update");
      res.solver_iterations.push_back(st.iterations);
    } else {
      X = chol->solve(Eigen::MatrixXd(rhs), "vertex update");
    }
    const double change = std::sqrt(detail::deterministic_sums<1>(nv, [&](Eigen::Index i0, Eigen::Index i1,
                                                                           std::array<double, 1>& s) {
                                       for (Eigen::Index i = i0; i < i1; ++i) s[0] += (X.row(i) - X_prev.row(i)).squaredNorm();
                                     })[0] /
                                     double(nv));
    X_old = X_prev;
    res.change_history.push_back(change);
    res.iterations = k + 1;
    res.fallback_projections = fallbacks;
    if (progress) {
      ProgressEvent ev{"vertex update", k + 1, o.max_iterations, change};
      if (!progress(ev)) throw Cancelled("vertex update cancelled");
    }
    if (change < o.tolerance) {
      res.converged = true;
      break;
    }
  }
  res.V = norm.undo(Eigen::MatrixXd(X));
  return res;
}

}  // namespace msmesh
