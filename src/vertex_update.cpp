#include "msmesh/vertex_update.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "anderson.h"
#include "default_init_allocator.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/operators.h"
#include "msmesh/parameters.h"
#include "msmesh/topology.h"
#include "parallel.h"
#include "pcg.h"
#include "retargeted_update.h"
#include "sparse_build.h"
#include "sparse_solve.h"

namespace msmesh {

void VertexUpdateOptions::validate() const { check_parameters(vertex_update_parameters(), *this); }

namespace {

using Rows = detail::RowMatrixX3;

// The vertex opposite edge slot k of face f is F(f,k) (face_edges(f,k) is opposite corner k).
int opposite_vertex(const Eigen::MatrixXi& F, const Topology& t, int f, Eigen::Index e) {
  for (int k = 0; k < 3; ++k)
    if (t.face_edges(f, k) == e) return F(f, k);
  return -1;
}

// Corners of each vertex, (f, k) as 3f + k: those of vertex i are corners[start[i] .. start[i+1]).
struct VertexCorners {
  std::vector<int> start;
  detail::UninitializedVector<int> corners;  // (written in full by vertex_corners)
};

VertexCorners vertex_corners(const Eigen::MatrixXi& F, Eigen::Index nv) {
  const Eigen::Index nf = F.rows();
  VertexCorners c;
  c.start.assign(static_cast<size_t>(nv) + 1, 0);
  c.corners.resize(static_cast<size_t>(3 * nf));
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) ++c.start[static_cast<size_t>(F(f, k)) + 1];
  for (size_t i = 0; i < static_cast<size_t>(nv); ++i) c.start[i + 1] += c.start[i];
  std::vector<int> fill(c.start.begin(), c.start.end() - 1);
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      c.corners[static_cast<size_t>(fill[static_cast<size_t>(F(f, k))]++)] = static_cast<int>(3 * f + k);
  return c;
}

// The four vertices (+,+,−,−) of each interior edge's H row with its v_e, and each vertex's
// roles in them (4h + r, grouped by vertex like VertexCorners).
struct EdgeQuads {
  detail::UninitializedVector<std::array<int, 4>> quad;  // (written in full by edge_quads)
  detail::UninitializedVector<double> quad_v;
  std::vector<int> role_start;
  detail::UninitializedVector<int> roles;
  std::vector<Eigen::RowVector3d> quad_normal;  // unit mean target normal (a fairness along the normals)
};

// F and the quads in the numbering `vertex` gives topo's vertices (empty: topo's own); with
// target normals N (#F by 3, else empty), each quad's mean normal too.
EdgeQuads edge_quads(const Eigen::MatrixXi& F, const Topology& topo, const std::vector<int>& vertex,
                     const Eigen::VectorXd& v, Eigen::Index nv, const Eigen::MatrixXd& N) {
  EdgeQuads q;
  q.role_start.assign(static_cast<size_t>(nv) + 1, 0);
  auto renumbered = [&](int i) { return vertex.empty() ? i : vertex[static_cast<size_t>(i)]; };
  // The interior edges in edge order: counted per block, then each block's quads made in
  // parallel at its offset.
  const Eigen::Index ne = topo.num_edges(), blocks = (ne + detail::kBlock - 1) / detail::kBlock;
  std::vector<Eigen::Index> offset(static_cast<size_t>(blocks) + 1, 0);
  detail::parallel_for_blocks(ne, [&](Eigen::Index e0, Eigen::Index e1) {
    Eigen::Index count = 0;
    for (Eigen::Index e = e0; e < e1; ++e) count += topo.edge_is_interior[e] ? 1 : 0;
    offset[static_cast<size_t>(e0 / detail::kBlock) + 1] = count;
  });
  for (size_t b = 0; b < static_cast<size_t>(blocks); ++b) offset[b + 1] += offset[b];
  q.quad.resize(static_cast<size_t>(offset.back()));
  q.quad_v.resize(q.quad.size());
  if (N.size()) q.quad_normal.resize(q.quad.size());
  detail::parallel_for_blocks(ne, [&](Eigen::Index e0, Eigen::Index e1) {
    size_t h = static_cast<size_t>(offset[static_cast<size_t>(e0 / detail::kBlock)]);
    for (Eigen::Index e = e0; e < e1; ++e) {
      if (!topo.edge_is_interior[e]) continue;
      q.quad[h] = {renumbered(topo.edges(e, 0)), renumbered(topo.edges(e, 1)),
                   opposite_vertex(F, topo, topo.edge_faces(e, 0), e),
                   opposite_vertex(F, topo, topo.edge_faces(e, 1), e)};
      q.quad_v[h] = v(e);
      if (N.size()) {
        const Eigen::RowVector3d n = N.row(topo.edge_faces(e, 0)) + N.row(topo.edge_faces(e, 1));
        const double len = n.norm();
        // Opposite normals (a fold), or two dropped targets (denoise.cpp, unreachable targets),
        // have no mean: the whole term acts there, as the paper's.
        q.quad_normal[h] = len > 1e-6 ? Eigen::RowVector3d(n / len) : Eigen::RowVector3d::Zero();
      }
      ++h;
    }
  });
  for (const auto& h : q.quad)
    for (int r = 0; r < 4; ++r) ++q.role_start[static_cast<size_t>(h[r]) + 1];
  for (size_t i = 0; i < static_cast<size_t>(nv); ++i) q.role_start[i + 1] += q.role_start[i];
  q.roles.resize(4 * q.quad.size());
  std::vector<int> fill(q.role_start.begin(), q.role_start.end() - 1);
  for (size_t h = 0; h < q.quad.size(); ++h)
    for (int r = 0; r < 4; ++r)
      q.roles[static_cast<size_t>(fill[static_cast<size_t>(q.quad[h][r])]++)] = static_cast<int>(4 * h + r);
  return q;
}

// The vertices in the order they first appear along the faces in `face_order` (unreferenced
// ones last, in their own order): position i holds vertex order[i]. Along the mesh's reverse
// Cuthill–McKee face order (PreparedMesh::face_order) this keeps the vertex update's
// neighbours close in memory, as an order of its own matrix would, for neither that
// matrix's reordering (~0.1 s at 1.3M faces) nor its copy into it (~150 MB).
std::vector<int> vertex_order(const Eigen::MatrixXi& F, Eigen::Index nv, const std::vector<int>& face_order) {
  std::vector<int> order;
  order.reserve(static_cast<size_t>(nv));
  std::vector<char> seen(static_cast<size_t>(nv), 0);
  for (const int f : face_order)
    for (int k = 0; k < 3; ++k) {
      const int i = F(f, k);
      if (!seen[static_cast<size_t>(i)]) {
        seen[static_cast<size_t>(i)] = 1;
        order.push_back(i);
      }
    }
  for (Eigen::Index i = 0; i < nv; ++i)
    if (!seen[static_cast<size_t>(i)]) order.push_back(static_cast<int>(i));
  return order;
}

// eq. 27's matrix ω₁KᵀK + ω₂HᵀH + diag(d3), with
//  K (3T×P): row 3i+k gives corner k of face i minus the face's mean (the centring matrix
//    M = I − 11ᵀ/3, so KᵀK adds M = 2/3 on the diagonal, −1/3 between corners, per face);
//  H: row per interior edge e = (i1,i2) with opposite vertices i3, i4: v_e (x1 + x2 − x3 − x4).
// Built row by row from the vertex's corners and edge roles (no triplets, no products).
SparseMatrix v_step_matrix(const Eigen::MatrixXi& F, const VertexCorners& vc, const EdgeQuads& eq,
                           const Eigen::VectorXd& d3, const VertexUpdateOptions& o) {
  const Eigen::Index nv = d3.size();
  return detail::symmetric_from_rows(
      nv,
      [&](Eigen::Index i) {
        const size_t u = static_cast<size_t>(i);
        return 1 + 3 * (vc.start[u + 1] - vc.start[u]) +
               (o.omega2 > 0 ? 4 * (eq.role_start[u + 1] - eq.role_start[u]) : 0);
      },
      [&](Eigen::Index i, int* col, double* val) {
        const size_t u = static_cast<size_t>(i);
        int n = 0;
        // A tiny floor keeps vertices with ω₃ multiplier 0 and no face (isolated) well-posed.
        col[n] = static_cast<int>(i);
        val[n++] = std::max(d3(i), 1e-10);
        for (int c = vc.start[u]; c < vc.start[u + 1]; ++c) {
          const Eigen::Index f = vc.corners[static_cast<size_t>(c)] / 3;
          const int a = vc.corners[static_cast<size_t>(c)] % 3;
          for (int b = 0; b < 3; ++b) {
            col[n] = F(f, b);
            val[n++] = o.omega1 * ((a == b ? 1.0 : 0.0) - 1.0 / 3.0);
          }
        }
        if (o.omega2 > 0)
          for (int r = eq.role_start[u]; r < eq.role_start[u + 1]; ++r) {
            const size_t h = static_cast<size_t>(eq.roles[static_cast<size_t>(r)]) / 4;
            const int ri = eq.roles[static_cast<size_t>(r)] % 4;
            const double ve = eq.quad_v[h], si = ri < 2 ? 1.0 : -1.0;
            for (int t = 0; t < 4; ++t) {
              col[n] = eq.quad[h][t];
              val[n++] = o.omega2 * ve * ve * si * (t < 2 ? 1.0 : -1.0);
            }
          }
        return n;
      });
}

// P-step (eq. 25), per face: P (3#F by 3) gets M P̂ of each face; returns the number of faces
// that took the degenerate fallback.
Eigen::Index p_step(const Eigen::MatrixXi& F, const Rows& X, const Eigen::MatrixXd& N, Rows& P) {
  const Eigen::Index nf = F.rows();
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
  return fallbacks;
}

// Q-step of the fairness along the normals: with the term written as
// ω₂ v_e² (‖d_e − q_e‖² + λ‖q_e‖²), q_e in the plane orthogonal to n_e and λ = τ/(1 − τ), its
// minimum over q_e is v_e² (1 − τ)(d_e − n_e(n_e·d_e)), which makes the term
// ω₂ v_e² [(n_e·d_e)² + τ‖d_e − n_e(n_e·d_e)‖²]: the alternation with the V-step minimises it
// as the P-step's projection does the normal term. Q holds ω₂ v_e² q_e.
void q_step(const EdgeQuads& eq, const Rows& X, double omega2, double tangential, Rows& Q) {
  detail::parallel_for(static_cast<Eigen::Index>(eq.quad.size()), [&](Eigen::Index h) {
    const auto& q = eq.quad[static_cast<size_t>(h)];
    const Eigen::RowVector3d d = X.row(q[0]) + X.row(q[1]) - X.row(q[2]) - X.row(q[3]);
    const Eigen::RowVector3d& n = eq.quad_normal[static_cast<size_t>(h)];
    const double ve = eq.quad_v[static_cast<size_t>(h)];
    if (n.squaredNorm() == 0)
      Q.row(h).setZero();  // a fold: the whole term
    else
      Q.row(h) = omega2 * ve * ve * (1 - tangential) * (d - n.dot(d) * n);
  });
}

// V-step right-hand side (eq. 27): rhs = ω₁KᵀP + ω₃V⁰ (rhs0) [+ HᵀQ], row by row.
void v_step_rhs(const Rows& rhs0, const Rows& P, const VertexCorners& vc, double omega1, const EdgeQuads* eq,
                const Rows& Q, Rows& rhs) {
  detail::parallel_for(
      rhs0.rows(),
      [&](Eigen::Index i) {
        Eigen::RowVector3d b = rhs0.row(i);
        // ω₁KᵀP: each corner of the vertex adds its (centred) row of P.
        for (int c = vc.start[static_cast<size_t>(i)]; c < vc.start[static_cast<size_t>(i) + 1]; ++c)
          b += omega1 * P.row(vc.corners[static_cast<size_t>(c)]);
        if (eq)
          for (int r = eq->role_start[static_cast<size_t>(i)]; r < eq->role_start[static_cast<size_t>(i) + 1]; ++r) {
            const int role = eq->roles[static_cast<size_t>(r)];
            b += (role % 4 < 2 ? 1.0 : -1.0) * Q.row(role / 4);
          }
        rhs.row(i) = b;
      },
      2);  // about six corners per vertex
}

// The stopping test's RMS vertex move between X_prev and X.
double rms_move(const Rows& X, const Rows& X_prev) {
  const Eigen::Index nv = X.rows();
  return std::sqrt(detail::deterministic_sums<1>(
                       nv,
                       [&](Eigen::Index i0, Eigen::Index i1, std::array<double, 1>& s) {
                         for (Eigen::Index i = i0; i < i1; ++i) s[0] += (X.row(i) - X_prev.row(i)).squaredNorm();
                       },
                       3)[0] /
                   double(nv));
}

// ‖X‖ over all its entries, summed in a fixed order (the same on any thread count).
double frobenius_norm(const Rows& X) {
  return std::sqrt(detail::deterministic_sums<1>(
      X.rows(),
      [&](Eigen::Index i0, Eigen::Index i1, std::array<double, 1>& s) {
        for (Eigen::Index i = i0; i < i1; ++i) s[0] += X.row(i).squaredNorm();
      },
      3)[0]);
}

}  // namespace

VertexUpdateResult update_vertices(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& N,
                                   const Eigen::VectorXd& v, const VertexUpdateOptions& o,
                                   const VertexUpdateWeights& weights, const ProgressCallback& progress) {
  o.validate();  // the options before the mesh
  return update_vertices(PreparedMesh(V, F, "vertex update"), N, v, o, weights, progress);
}

VertexUpdateResult update_vertices(const PreparedMesh& mesh, const Eigen::MatrixXd& N, const Eigen::VectorXd& v,
                                   const VertexUpdateOptions& o, const VertexUpdateWeights& weights,
                                   const ProgressCallback& progress) {
  return detail::update_vertices_retargeted(mesh, N, v, o, weights, progress, {});
}

VertexUpdateResult detail::update_vertices_retargeted(const PreparedMesh& mesh, const Eigen::MatrixXd& N_in,
                                                      const Eigen::VectorXd& v_in, const VertexUpdateOptions& o,
                                                      const VertexUpdateWeights& weights,
                                                      const ProgressCallback& progress, const Retarget& retarget) {
  o.validate();
  const Eigen::MatrixXi& F = mesh.faces();
  const Eigen::Index nv = mesh.num_vertices(), nf = mesh.num_faces();
  if (N_in.rows() != nf || N_in.cols() != 3) throw InvalidInput("vertex update: target normals must be #F by 3");
  Eigen::MatrixXd retargeted;  // the targets `retarget` makes (empty until it runs)
  const Eigen::MatrixXd* targets = &N_in;
  const Topology& topo = mesh.topology();
  const Eigen::Index ne = topo.num_edges();
  Eigen::VectorXd v = v_in.size() ? v_in : Eigen::VectorXd::Ones(ne);
  if (v.size() != ne) throw InvalidInput("vertex update: edge field v must have one value per edge");
  Eigen::VectorXd w3 = Eigen::VectorXd::Ones(nv);
  if (weights.vertex_omega3.size()) {
    if (weights.vertex_omega3.size() != nv) throw InvalidInput("vertex update: vertex_omega3 must have #V entries");
    w3 = weights.vertex_omega3;
    if ((w3.array() < 0).any() || !w3.allFinite())
      throw InvalidInput("vertex update: vertex_omega3 must be finite and >= 0");
  }
  VertexUpdateResult res;
  if (nf == 0) {
    res.V = mesh.positions();  // not normalised without faces: the input
    res.converged = true;
    return res;
  }

  // Auto: the factorisation below kCgMinVertices vertices (cheap there, and exact), conjugate
  // gradients above (linear cost; κ is bounded by about (6ω₁ + 16ω₂ + ω₃)/ω₃). The accelerated
  // alternation needs 6–11 V-steps instead of up to 30, too few to pay for a factorisation: CG
  // from kCgMinVerticesAccelerated there (Cone 0.24 → 0.18 s, GNF bunny 0.63 → 0.14 s; below,
  // the factorisation costs a few ms and keeps the result exact, hence invariant under rotation
  // to round-off). Either way only with moderate per-vertex weights: where they lower ω₃
  // (inpainting: new vertices are free) the system is badly conditioned, and where they raise it
  // far (a pinned vertex) that vertex dominates CG's relative residual, which then stops before
  // the others move; such systems are factored at any size (docs/performance.md).
  constexpr Eigen::Index kCgMinVertices = 40000, kCgMinVerticesAccelerated = 10000;
  constexpr double kCgMinWeight = 0.5, kCgMaxWeight = 10.0;
  const bool moderate_weights = w3.minCoeff() >= kCgMinWeight && w3.maxCoeff() <= kCgMaxWeight;
  const bool large = nv >= kCgMinVertices || (o.acceleration > 0 && nv >= kCgMinVerticesAccelerated);
  const bool use_cg = o.solver == LinearSolver::CG || (o.solver == LinearSolver::Auto && large && moderate_weights);

  // CG works in vertex_order's numbering: the system is assembled in it and kept as it is
  // (position i holds input vertex order[i]; empty: the input's numbering).
  std::vector<int> order, renumber;
  Eigen::MatrixXi F_ordered;
  if (use_cg) {
    order = vertex_order(F, nv, mesh.face_order());
    renumber.resize(static_cast<size_t>(nv));
    for (Eigen::Index i = 0; i < nv; ++i)
      renumber[static_cast<size_t>(order[static_cast<size_t>(i)])] = static_cast<int>(i);
    F_ordered.resize(nf, 3);
    detail::parallel_for(nf, [&](Eigen::Index f) {
      for (int k = 0; k < 3; ++k) F_ordered(f, k) = renumber[static_cast<size_t>(F(f, k))];
    });
  }
  const Eigen::MatrixXi& Fw = use_cg ? F_ordered : F;
  auto input_vertex = [&](Eigen::Index i) {
    return order.empty() ? i : static_cast<Eigen::Index>(order[static_cast<size_t>(i)]);
  };
  Eigen::VectorXd d3(nv);
  detail::parallel_for(nv, [&](Eigen::Index i) { d3(i) = o.omega3 * w3(input_vertex(i)); });

  // Assembly of eq. 27: (ω₁KᵀK + ω₂HᵀH + ω₃I) V = ω₁KᵀP + ω₃V⁰.
  const VertexCorners vc = vertex_corners(Fw, nv);
  // A fairness along the normals keeps the quads for its Q-step; else the quads (~80 MB at a
  // million faces), and the matrix when it is factored, are freed before the iterations' arrays
  // are allocated; CG takes the matrix's arrays over.
  // The matrix reads the targets only through the fairness along the normals: built again for
  // new targets only then.
  const bool along_normals = o.omega2 > 0 && o.fairness_tangential < 1;
  EdgeQuads eq;
  std::optional<detail::ConstantSystem> v_step_system;
  const auto assemble = [&] {
    eq = o.omega2 > 0 ? edge_quads(Fw, topo, renumber, v, nv, along_normals ? *targets : Eigen::MatrixXd())
                      : EdgeQuads{};
    SparseMatrix A_v = v_step_matrix(Fw, vc, eq, d3, o);
    if (!along_normals) eq = EdgeQuads();
    v_step_system.reset();
    if (use_cg)
      v_step_system.emplace(std::move(A_v), "vertex update");
    else
      v_step_system.emplace(A_v, detail::ConstantSystem::Method::Cholesky, "vertex update");
  };
  assemble();
  Rows X(nv, 3);  // the iterate, from the input positions (allocated after the assembly's scratch is freed)
  detail::parallel_for(nv, [&](Eigen::Index i) { X.row(i) = mesh.positions().row(input_vertex(i)); });
  const Rows rhs0 = d3.asDiagonal() * X;

  // X is the iterate x_k, G = G(x_k) the positions one P-step and V-step make of it; the plain
  // alternation takes x_{k+1} = G, the accelerated one combines G with the last iterations'.
  // The move of an iteration is ‖G(x_k) − x_k‖ either way (the plain alternation's step).
  Rows X_old, G(nv, 3), rhs(nv, 3), P(3 * nf, 3), Q(along_normals ? static_cast<Eigen::Index>(eq.quad.size()) : 0, 3);
  // Inexact V-steps, as the normal filter's N-steps: while the vertices still move, CG solves a
  // V-step only until its error is a small fraction of the last move. The matrix is at least
  // ω₃·min(w₃) I, so a residual r moves the solution by at most ‖r‖ / (ω₃ min w₃): a relative
  // residual t ≤ kInexactFraction · change · ω₃ min w₃ · √#V / ‖B‖ keeps the RMS error below
  // kInexactFraction times the last RMS move (ε₂ = 1e-3 mean edges at the end), at most
  // kInexactMax (also the first V-step's), never below solver_tolerance. Cone 139 → 94 sweeps,
  // 82K sphere 77 → 51; of docs/quality.md's 29 rows 22 the same to their printed digits, 5
  // lower, 2 higher by 0.02, less than a 10 % change of ε₂ moves them (docs/performance.md,
  // "Issue 20, eleventh round"). A tolerance below kLooseSolvesFromTolerance (preset paper's)
  // solves every V-step to it.
  constexpr double kInexactFraction = 0.03, kInexactMax = 1e-4;
  const bool inexact = v_step_system->iterative() && o.solver_tolerance >= detail::kLooseSolvesFromTolerance;
  const double closeness_min = d3.minCoeff();
  // The positions in the input's numbering, normalised units.
  const auto positions = [&] {
    Eigen::MatrixXd V(nv, 3);
    detail::parallel_for(nv, [&](Eigen::Index i) { V.row(input_vertex(i)) = X.row(i); });
    return V;
  };
  // One run of the alternation, or two when `retarget` changes the targets after the first: the
  // second starts from the first's result, afresh (no history, no last move) but with its system.
  for (int run = 0, done = 0; run < 2; ++run) {
    if (run == 1) {
      if (!retarget) break;
      retargeted = *targets;
      if (!retarget(positions(), retargeted)) break;
      targets = &retargeted;
      if (along_normals) assemble();
    }
    const Eigen::MatrixXd& N = *targets;
    std::optional<detail::AndersonAcceleration> accelerate;
    if (o.acceleration > 0) accelerate.emplace(o.acceleration);
    double last_change = std::numeric_limits<double>::infinity();
    for (int k = 0; k < o.max_iterations; ++k) {
      const Eigen::Index fallbacks = p_step(Fw, X, N, P);
      if (along_normals) q_step(eq, X, o.omega2, o.fairness_tangential, Q);
      v_step_rhs(rhs0, P, vc, o.omega1, along_normals ? &eq : nullptr, Q, rhs);
      // CG's warm start: in the plain alternation the secant x_k + (x_k − x_{k−1}) (the vertices
      // move smoothly from one iteration to the next: about a fifth fewer sweeps, Cone 1153 →
      // 940); the accelerated iterate x_k itself, already an extrapolation. Only the starting
      // point changes, not the solution.
      if (v_step_system->iterative()) {
        if (!accelerate && k >= 1)
          G = X + (X - X_old);
        else
          G = X;
      }
      double tolerance = o.solver_tolerance;
      if (inexact) {
        const double bound = std::isfinite(last_change) ? kInexactFraction * last_change * closeness_min *
                                                              std::sqrt(double(nv)) / frobenius_norm(rhs)
                                                        : kInexactMax;
        tolerance = std::max(o.solver_tolerance, std::min(kInexactMax, bound));
      }
      const int sweeps = v_step_system->solve(rhs, G, tolerance);
      if (sweeps >= 0) res.solver_iterations.push_back(sweeps);
      const double change = rms_move(G, X);
      res.change_history.push_back(change);
      res.iterations = done + k + 1;
      res.fallback_projections = fallbacks;
      if (progress) {
        ProgressEvent ev{"vertex update", k + 1, o.max_iterations, change};
        if (!progress(ev)) throw Cancelled("vertex update cancelled");
      }
      if (change < o.tolerance || k + 1 == o.max_iterations) {
        X.swap(G);
        res.converged = change < o.tolerance;
        break;
      }
      if (accelerate) {
        // A move larger than the last one: the combination overshot (the P-step's projection is
        // not smooth where a face is about to flip), so start the history again from G.
        if (change > last_change) accelerate->restart();
        accelerate->step(G, X);
      } else {
        if (v_step_system->iterative()) X_old = X;
        X.swap(G);
      }
      last_change = change;
    }
    done = res.iterations;
  }
  res.V = mesh.to_input_units(positions());
  return res;
}

}  // namespace msmesh
