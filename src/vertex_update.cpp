#include "msmesh/vertex_update.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <sstream>

#include "msmesh/errors.h"
#include "msmesh/parameters.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/operators.h"
#include "msmesh/topology.h"
#include "normalize.h"
#include "parallel.h"
#include "pcg.h"
#include "sparse_build.h"
#include "sparse_solve.h"

namespace msmesh {

void VertexUpdateOptions::validate() const { check_parameters(vertex_update_parameters(), *this); }

namespace {


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

  // eq. 27: (ω₁KᵀK + ω₂HᵀH + ω₃I) V = ω₁KᵀP + ω₃V⁰, with
  //  K (3T×P): row 3i+k gives corner k of face i minus the face's mean (the centring matrix
  //    M = I − 11ᵀ/3, so KᵀK adds M = 2/3 on the diagonal, −1/3 between corners, per face);
  //  H: row per interior edge e = (i1,i2) with opposite vertices i3, i4: v_e (x1 + x2 − x3 − x4).
  // Built row by row from the vertex's corners and edge roles (no triplets, no products).
  const Eigen::VectorXd d3 = o.omega3 * w3;
  // Corners of each vertex: (f, k) as 3f + k.
  std::vector<int> corner_start(static_cast<size_t>(nv) + 1, 0), corners(static_cast<size_t>(3 * nf));
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) ++corner_start[static_cast<size_t>(F(f, k)) + 1];
  for (size_t i = 0; i < static_cast<size_t>(nv); ++i) corner_start[i + 1] += corner_start[i];
  {
    std::vector<int> fill(corner_start.begin(), corner_start.end() - 1);
    for (Eigen::Index f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) corners[static_cast<size_t>(fill[static_cast<size_t>(F(f, k))]++)] = static_cast<int>(3 * f + k);
  }
  // The four vertices (+,+,−,−) of each interior edge's H row, and each vertex's roles in them.
  std::vector<std::array<int, 4>> quad;
  std::vector<double> quad_v;
  std::vector<int> role_start(static_cast<size_t>(nv) + 1, 0), roles;
  if (o.omega2 > 0) {
    for (Eigen::Index e = 0; e < ne; ++e) {
      if (!topo.edge_is_interior[e]) continue;
      quad.push_back({topo.edges(e, 0), topo.edges(e, 1), opposite_vertex(F, topo, topo.edge_faces(e, 0), e),
                      opposite_vertex(F, topo, topo.edge_faces(e, 1), e)});
      quad_v.push_back(v(e));
    }
    for (const auto& q : quad)
      for (int r = 0; r < 4; ++r) ++role_start[static_cast<size_t>(q[r]) + 1];
    for (size_t i = 0; i < static_cast<size_t>(nv); ++i) role_start[i + 1] += role_start[i];
    roles.resize(4 * quad.size());
    std::vector<int> fill(role_start.begin(), role_start.end() - 1);
    for (size_t h = 0; h < quad.size(); ++h)
      for (int r = 0; r < 4; ++r) roles[static_cast<size_t>(fill[static_cast<size_t>(quad[h][r])]++)] = static_cast<int>(4 * h + r);
  }
  SparseMatrix A = detail::symmetric_from_rows(
      nv,
      [&](Eigen::Index i) {
        const size_t u = static_cast<size_t>(i);
        return 1 + 3 * (corner_start[u + 1] - corner_start[u]) +
               (o.omega2 > 0 ? 4 * (role_start[u + 1] - role_start[u]) : 0);
      },
      [&](Eigen::Index i, int* col, double* val) {
        const size_t u = static_cast<size_t>(i);
        int n = 0;
        // A tiny floor keeps vertices with ω₃ multiplier 0 and no face (isolated) well-posed.
        col[n] = static_cast<int>(i);
        val[n++] = std::max(d3(i), 1e-10);
        for (int c = corner_start[u]; c < corner_start[u + 1]; ++c) {
          const Eigen::Index f = corners[static_cast<size_t>(c)] / 3;
          const int a = corners[static_cast<size_t>(c)] % 3;
          for (int b = 0; b < 3; ++b) {
            col[n] = F(f, b);
            val[n++] = o.omega1 * ((a == b ? 1.0 : 0.0) - 1.0 / 3.0);
          }
        }
        if (o.omega2 > 0)
          for (int r = role_start[u]; r < role_start[u + 1]; ++r) {
            const size_t h = static_cast<size_t>(roles[static_cast<size_t>(r)]) / 4;
            const int ri = roles[static_cast<size_t>(r)] % 4;
            const double ve = quad_v[h], si = ri < 2 ? 1.0 : -1.0;
            for (int t = 0; t < 4; ++t) {
              col[n] = quad[h][t];
              val[n++] = o.omega2 * ve * ve * si * (t < 2 ? 1.0 : -1.0);
            }
          }
        return n;
      });
  // Auto: the factorisation below kCgMinVertices vertices (cheap there, and exact), conjugate
  // gradients above (linear cost; κ is bounded by about (6ω₁ + 16ω₂ + ω₃)/ω₃), unless
  // per-vertex weights lower ω₃ somewhere (inpainting: new vertices are free), which makes
  // the system badly conditioned: then factor it at any size (docs/performance.md).
  constexpr Eigen::Index kCgMinVertices = 40000;
  const bool use_cg = o.solver == LinearSolver::CG ||
                      (o.solver == LinearSolver::Auto && nv >= kCgMinVertices && w3.minCoeff() >= 0.5);
  const detail::ConstantSystem v_step(A, use_cg, "vertex update");
  A = SparseMatrix();
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
      // Stored as M P̂ (each row minus the face's mean row), which is what ω₁KᵀP gathers.
      const Eigen::RowVector3d ph_mean = (Ph.row(0) + Ph.row(1) + Ph.row(2)) / 3.0;
      P.block<3, 3>(3 * f, 0) = Ph.rowwise() - ph_mean;
    }
    // V-step (eq. 27): rhs = ω₁KᵀP + ω₃V⁰, row by row.
    detail::parallel_for(nv, [&](Eigen::Index i) {
      Eigen::RowVector3d b = rhs0.row(i);
      // ω₁KᵀP: each corner of the vertex adds its (centred) row of P.
      for (int c = corner_start[static_cast<size_t>(i)]; c < corner_start[static_cast<size_t>(i) + 1]; ++c)
        b += o.omega1 * P.row(corners[static_cast<size_t>(c)]);
      rhs.row(i) = b;
    }, 2);  // about six corners per vertex
    X_prev = X;
    if (v_step.iterative() && k >= 1) {
      // Warm start on the secant X_k + (X_k − X_{k−1}): the vertices move smoothly from one
      // iteration to the next, and this saves about a fifth of the CG sweeps (Cone: 1153 →
      // 940). Only the starting point changes, not the solution.
      X += X_prev - X_old;
    }
    const int sweeps = v_step.solve(rhs, X, o.solver_tolerance);
    if (sweeps >= 0) res.solver_iterations.push_back(sweeps);
    const double change = std::sqrt(detail::deterministic_sums<1>(nv, [&](Eigen::Index i0, Eigen::Index i1,
                                                                           std::array<double, 1>& s) {
                                       for (Eigen::Index i = i0; i < i1; ++i) s[0] += (X.row(i) - X_prev.row(i)).squaredNorm();
                                     })[0] /
                                     double(nv));
    if (v_step.iterative()) X_old = X_prev;
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
