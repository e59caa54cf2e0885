#include "msmesh/normal_filter.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <sstream>
#include <utility>

#include "face_graph_matrix.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/operators.h"
#include "msmesh/parameters.h"
#include "msmesh/topology.h"
#include "normal_polish.h"
#include "normalize.h"
#include "parallel.h"
#include "pcg.h"
#include "sparse_build.h"
#include "sparse_solve.h"
#include "unit_rows.h"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace msmesh {

void NormalFilterOptions::validate() const { check_parameters(normal_filter_parameters(), *this); }

namespace {

// The per-edge IRLA weight of φ₂ = log(1 + ρt)/ρ: φ₂'(t) = 1/(1 + ρt) (eq. 18).
inline double irla_weight(double p_norm, const NormalFilterOptions& o) {
  return o.reweight ? 1.0 / (1.0 + o.rho * p_norm) : 1.0;
}

double energy_normalised(const Operators& ops, const Eigen::MatrixXd& N, const Eigen::VectorXd& v,
                         const Eigen::MatrixXd& N0, const NormalFilterOptions& o, const Eigen::VectorXd& face_alpha,
                         const Eigen::VectorXd& edge_beta) {
  const Eigen::MatrixXd g = ops.G * N;
  double reg = 0;
  for (Eigen::Index e = 0; e < g.rows(); ++e) {
    const double t = g.row(e).norm();
    const double phi = o.reweight ? std::log1p(o.rho * t) / o.rho : t;
    reg += v(e) * v(e) * phi * ops.edge_lengths(e);
  }
  const Eigen::VectorXd dv = ops.D * v;
  const double smooth = o.epsilon * inner_product(dv, dv, ops.line_lengths);
  const Eigen::VectorXd vm1 = v.array() - 1.0;
  const double fid_v = inner_product(vm1, vm1, ops.edge_lengths.cwiseProduct(edge_beta)) / (4 * o.epsilon);
  const Eigen::MatrixXd dN = N - N0;
  const double fid = inner_product(dN, dN, ops.face_areas.cwiseProduct(face_alpha));
  return o.gamma * reg + o.beta * (smooth + fid_v) + o.alpha * fid;
}

Eigen::VectorXd ones_or(const Eigen::VectorXd& w, Eigen::Index n, const char* what) {
  if (w.size() == 0) {
    Eigen::VectorXd ones(n);  // first touched on the library's threads
    detail::parallel_for(n, [&](Eigen::Index i) { ones(i) = 1; });
    return ones;
  }
  if (w.size() != n) {
    std::ostringstream os;
    os << "normal filtering: " << what << " has " << w.size() << " entries, expected " << n;
    throw InvalidInput(os.str());
  }
  for (Eigen::Index i = 0; i < n; ++i)
    if (!std::isfinite(w(i)) || w(i) < 0) {
      std::ostringstream os;
      os << "normal filtering: " << what << "[" << i << "] = " << w(i) << " must be finite and >= 0";
      throw InvalidInput(os.str());
    }
  return w;
}

// c · Dᵀ L_W D (#E by #E), assembled from the corner lines: line l = 3f+k joins the edge
// entering corner k (e+, opposite corner k+1) and the edge leaving it (e−, opposite k+2).
// Edge e in slot j of face f lies on the lines of corners j+2 (as e+, paired with the edge
// of slot j+1) and j+1 (as e−, paired with slot j+2). Built row by row, straight in
// compressed form (a million-face mesh has 12 million line couplings: the triplet route
// took 0.8 s there). The matrix is symmetric, so its rows are also its columns.
// face_edges: the edges of each face (#F by 3, slot k opposite corner k); line_lengths per
// line 3f+k in the same face order.
using FaceEdges = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;
SparseMatrix edge_smoothness_matrix(Eigen::Index ne, const FaceEdges& face_edges, const Eigen::VectorXd& line_lengths,
                                    double c) {
  const Eigen::Index nf = face_edges.rows();
  // Incidences (face, slot) of every edge, grouped by edge.
  std::vector<int> first(static_cast<size_t>(ne) + 1, 0);
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int j = 0; j < 3; ++j) ++first[static_cast<size_t>(face_edges(f, j)) + 1];
  for (size_t e = 0; e < static_cast<size_t>(ne); ++e) first[e + 1] += first[e];
  std::vector<int> inc(static_cast<size_t>(3 * nf));
  {
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (Eigen::Index f = 0; f < nf; ++f)
      for (int j = 0; j < 3; ++j)
        inc[static_cast<size_t>(fill[static_cast<size_t>(face_edges(f, j))]++)] = static_cast<int>(3 * f + j);
  }
  return detail::symmetric_from_rows(
      ne, [&](Eigen::Index e) { return 1 + 2 * (first[static_cast<size_t>(e) + 1] - first[static_cast<size_t>(e)]); },
      [&](Eigen::Index e, int* col, double* val) {
        int n = 1;
        double diag = 0;
        for (int q = first[static_cast<size_t>(e)]; q < first[static_cast<size_t>(e) + 1]; ++q) {
          const Eigen::Index f = inc[static_cast<size_t>(q)] / 3;
          const int j = inc[static_cast<size_t>(q)] % 3;
          const double w1 = c * line_lengths(3 * f + (j + 2) % 3), w2 = c * line_lengths(3 * f + (j + 1) % 3);
          diag += w1 + w2;
          col[n] = face_edges(f, (j + 1) % 3);
          val[n++] = -w1;
          col[n] = face_edges(f, (j + 2) % 3);
          val[n++] = -w2;
        }
        col[0] = static_cast<int>(e);  // every diagonal entry is stored, also a zero one
        val[0] = diag;
        return n;
      });
}

}  // namespace

double nmstv_energy(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& N,
                    const Eigen::VectorXd& v, const Eigen::MatrixXd& normals0, const NormalFilterOptions& options) {
  const detail::Normalization norm = detail::normalization_for(V, F);
  const Eigen::MatrixXd Vn = norm.apply(V);
  const Topology topo = build_topology(F, V.rows());
  const Operators ops = build_operators(Vn, F, topo);
  return energy_normalised(ops, N, v, normals0, options, Eigen::VectorXd::Ones(F.rows()),
                           Eigen::VectorXd::Ones(topo.num_edges()));
}

NormalFilterResult filter_normals(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const NormalFilterOptions& o,
                                  const NormalFilterWeights& weights, const ProgressCallback& progress,
                                  const Eigen::MatrixXd& normals0) {
  o.validate();  // the options before the mesh
  return filter_normals(PreparedMesh(V, F, "normal filtering"), o, weights, progress, normals0);
}

namespace {

using Rows = detail::RowMatrixX3;

// Algorithm 1 on one prepared mesh, as named steps over shared state: the constructor
// assembles the constant parts (operators, N-step system, v-step matrix), then per iteration
// the p-step with the multiplier update (edge_pass), the stopping test with the next N-step's
// right-hand side (next_n_step_and_change), the v-step and the N-step of the next iteration.
class NormalFilterRun {
 public:
  NormalFilterRun(const PreparedMesh& mesh, const NormalFilterOptions& o, const NormalFilterWeights& weights,
                  const Eigen::MatrixXd& normals0);
  NormalFilterResult run(const ProgressCallback& progress);

 private:
  void assemble_n_step(const PreparedMesh& mesh);
  Eigen::RowVector3d n_step_rhs_row(Eigen::Index f) const;
  void n_step_rhs();
  double next_n_step_and_change();
  void n_step(Rows& N_out, const Rows& fallback);
  double edge_pass();
  int v_step();
  bool v_jacobi_suffices() const;
  void v_step_beside_next_n_step(bool last, int& v_iterations);
  bool overlap() const;
  void renumber();
  Eigen::MatrixXd in_input_order(const Rows& M) const;
  Eigen::VectorXd edges_in_input_order(const Eigen::VectorXd& x) const;

  const NormalFilterOptions& o_;
  const Eigen::MatrixXi& F_;
  const Topology& topo_;
  Operators ops_;  // its arrays are released after the set-up unless the energy is recorded
  const Eigen::Index nf_, ne_;
  Eigen::VectorXd face_alpha_;
  Eigen::VectorXd edge_beta_;
  Eigen::MatrixXd N0_;
  Eigen::VectorXd fid_weight_;  // 2α s_f (floored) per face
  std::optional<detail::ConstantSystem> n_system_;
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> gt_weight_;  // Gᵀ L per face
  Eigen::VectorXd smooth_diag_, v_rhs_, v_diag_;  // diagonal of 2βε Dᵀ L_W D; the v-step's b and diagonal
  double smooth_diag_max_ = 0;
  std::optional<detail::BlockPcg> v_system_;  // the v-step matrix; its diagonal is set per iteration
  // The faces are renumbered once into the N-step solver's order (reverse Cuthill–McKee for
  // CG, pcg.h; the input order otherwise), and the edges in the order the faces first meet
  // them: the per-face and per-edge arrays below, the two systems and the iterates all use
  // these numbers, so CG needs no permutation per solve and every pass reads neighbours
  // close together. Position i holds input face order_[i], input edge edge_order_[i]
  // (both empty: the input order).
  std::vector<int> order_, edge_order_;
  FaceEdges face_edges_;                                               // new edge numbers
  Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor> edge_faces_;  // new face numbers; −1: none
  Eigen::VectorXd area_, len_, beta_e_;  // face areas, edge lengths and β weights (new order)
  std::vector<char> interior_;           // per edge (new order)
  Rows N0r_, N_, N_prev_, N_next_, rhs_, q_, lambda_;
  Eigen::VectorXd v_, w_;
  double n_step_tolerance_ = 0;  // the relative residual at which the next N-step's CG stops
  double v_tolerance_ = 1e-10;   // the v-step's relative residual
  double v_rhs_norm_ = 0;        // ‖b‖ of the v-step
  double v_jacobi_bound2_ = 0;   // (max_e Σ_{f≠e}|a_ef|) Σ_e (Σ_{f≠e}|a_ef|) v_e², from the last edge pass
  NormalFilterResult res_;
};

NormalFilterRun::NormalFilterRun(const PreparedMesh& mesh, const NormalFilterOptions& o,
                                 const NormalFilterWeights& weights, const Eigen::MatrixXd& normals0)
    : o_(o),
      F_(mesh.faces()),
      topo_(mesh.topology()),
      ops_(build_operators(mesh.positions(), mesh.faces(), mesh.topology(), /*matrices=*/o.record_energy)),
      nf_(mesh.num_faces()),
      ne_(mesh.num_edges()),
      face_alpha_(ones_or(weights.face_alpha, nf_, "face_alpha")),
      edge_beta_(ones_or(weights.edge_beta, ne_, "edge_beta")) {
  N0_ = normals0.size() ? normals0 : face_normals(mesh.positions(), F_);
  if (N0_.rows() != nf_ || N0_.cols() != 3) throw InvalidInput("normal filtering: input normals must be #F by 3");

  // Zero-area faces would make the N-step singular where they have no interior edge; give
  // them a tiny positive weight instead (their normals then follow their neighbours).
  const double area_floor = 1e-12 * std::max(1e-300, ops_.face_areas.mean());
  fid_weight_.resize(nf_);
  detail::parallel_for(nf_, [&](Eigen::Index f) {
    fid_weight_(f) = (2.0 * o.alpha) * std::max(std::max(ops_.face_areas(f), area_floor) * face_alpha_(f), area_floor);
  });
  assemble_n_step(mesh);
  N0r_.resize(nf_, 3);
  detail::parallel_for(nf_, [&](Eigen::Index f) { N0r_.row(f) = N0_.row(f); });
  if (!o.record_energy) N0_ = Eigen::MatrixXd();  // only the energy reads the column-major copy
  renumber();

  // v-step matrix (eq. 23): L·diag(2γ w‖p‖ + β_e/(2ε)) + 2βε Dᵀ L_W D. Only the diagonal
  // changes between iterations. Dᵀ L_W D is assembled directly from the corner lines (each
  // line l couples its entering and leaving edges), stored with explicit diagonal entries.
  {
    Eigen::VectorXd lines(3 * nf_);
    detail::parallel_for(nf_, [&](Eigen::Index i) {
      const Eigen::Index f = order_.empty() ? i : order_[static_cast<size_t>(i)];
      for (int k = 0; k < 3; ++k) lines(3 * i + k) = ops_.line_lengths(3 * f + k);
    });
    SparseMatrix Kv = edge_smoothness_matrix(ne_, face_edges_, lines, 2.0 * o.beta * o.epsilon);
    smooth_diag_.resize(ne_);
    detail::parallel_for(ne_, [&](Eigen::Index e) { smooth_diag_(e) = Kv.coeff(e, e); });
    smooth_diag_max_ = smooth_diag_.size() ? smooth_diag_.maxCoeff() : 0.0;
    // Few sweeps per solve (strongly diagonally dominant): not worth a reordering. CG takes
    // the matrix over (the largest array here: ~120 MB at a million faces, not copied). In
    // double precision: rounded to single, the diagonal could fall below the right-hand side
    // plus the off-diagonal row sum, and v rise above 1 (measured: 1 + 6e-8 on flat faces).
    v_system_.emplace(std::move(Kv), /*reorder=*/false);
    // Diagonally dominant by a factor ~1/(4ε²): Chebyshev on Gershgorin's interval, one pass a sweep.
    v_system_->use_chebyshev();
  }
  v_rhs_.resize(ne_);
  detail::parallel_for(ne_, [&](Eigen::Index e) { v_rhs_(e) = len_(e) * beta_e_(e) * (o.beta / (2 * o.epsilon)); });
  v_rhs_norm_ = v_rhs_.norm();
  v_diag_.resize(ne_);
  if (!o.record_energy) {
    // Only the energy reads the input-order arrays from here on (the renumbered copies serve
    // the iterations): freed before the iterations' arrays, which then reuse the memory (at
    // this size every fresh page costs its zeroing in the kernel).
    ops_ = Operators();
    face_alpha_ = Eigen::VectorXd();
    edge_beta_ = Eigen::VectorXd();
  }

  // The iterates, row-major (one row per face or edge) and allocated once. Filled on the
  // library's threads: the first touch of each fresh page costs its zeroing in the kernel
  // (~1.3 GB here at 5M faces, 3 s on one thread; docs/performance.md, "sixteenth round").
  N_.resize(nf_, 3);
  detail::parallel_for(nf_, [&](Eigen::Index f) { N_.row(f) = N0r_.row(f); });
  N_prev_.resize(nf_, 3);
  N_next_.resize(nf_, 3);
  rhs_.resize(nf_, 3);
  // q = r p + λ per edge, what the N-step right-hand side needs of p and λ (p itself is
  // used only in the pass over the edges that makes it).
  q_.resize(ne_, 3);
  lambda_.resize(ne_, 3);
  v_.resize(ne_);
  w_.resize(ne_);
  detail::parallel_for(ne_, [&](Eigen::Index e) {
    q_.row(e).setZero();
    lambda_.row(e).setZero();
    v_(e) = o.v_initial;
    w_(e) = 1;  // w⁰ = 1
  });
}

// N-step matrix (eq. 20 in matrix form, DESIGN.md step 1): 2αS + r Gᵀ L G; constant. Also the
// Gᵀ L weights of its right-hand side.
void NormalFilterRun::assemble_n_step(const PreparedMesh& mesh) {
  // Auto: the factorisation below kCgMinFaces faces (cheap there, and exact), conjugate
  // gradients above (linear cost, where the factor grows like n^1.5; with the single-precision
  // Chebyshev sweeps and inexact early steps the crossover fell from 80K to between 21K and
  // 24K faces: Cone, 61K, 0.28 → 0.21 s, a noisy 59K cube 0.55 → 0.21 s; docs/performance.md,
  // "Issue 20, eleventh round"), unless per-face α weights switch the fidelity off somewhere
  // (inpainting): the matrix then loses its diagonal dominance and the factorisation is
  // faster at any size (docs/performance.md).
  // Below kCgMinFaces, CG too when the ADMM penalty is small against the fidelity (r ≤ 0.2 α,
  // preset smooth's r 0.1): the matrix is then nearly diagonal (κ ≈ 1.1), a few sweeps solve
  // it and beat the factorisation at any size (GNF bunny, 69K faces: 0.55 → 0.23 s).
  constexpr Eigen::Index kCgMinFaces = 25000;
  constexpr double kCgMaxPenaltyPerAlpha = 0.2;
  const bool well_conditioned = o_.penalty <= kCgMaxPenaltyPerAlpha * o_.alpha;
  const bool use_cg =
      o_.solver == LinearSolver::CG ||
      (o_.solver == LinearSolver::Auto && (nf_ >= kCgMinFaces || well_conditioned) && face_alpha_.minCoeff() >= 0.5);
  // CG keeps the N-step matrix and its work vectors in single precision (pcg.h): fewer bytes
  // per sweep; the unit normals it solves for are well scaled, and the figures of
  // docs/quality.md stay the same to their printed digits (docs/performance.md). Rounding the
  // matrix moves the solution by about κ·6e-8 (~4e-7 for cad's κ ≈ 6.6), so a tolerance
  // tighter than kLooseSolvesFromTolerance (preset paper's 1e-8, exact comparisons) keeps double.
  using Method = detail::ConstantSystem::Method;
  const Method method = !use_cg                                                    ? Method::Cholesky
                        : o_.solver_tolerance >= detail::kLooseSolvesFromTolerance ? Method::CgSingle
                                                                                   : Method::Cg;
  // Row f: its fidelity weight plus r·len(e) on the diagonal for each interior edge e of f,
  // −r·len(e) towards the face across e. CG takes the rows straight into its own layout (no
  // assembled matrix: 0.2 s less at 1.3M faces); the factorisation needs the matrix.
  const auto diagonal = [&](Eigen::Index f) { return fid_weight_(f); };
  const auto weight = [&](int e) { return o_.penalty * ops_.edge_lengths(e); };
  if (use_cg)
    n_system_.emplace(nf_, detail::face_graph_rows(topo_, diagonal, weight), mesh.face_order(), method,
                      "normal filtering (N-step)");
  else
    n_system_.emplace(detail::face_graph_matrix(topo_, nf_, diagonal, weight), method, "normal filtering (N-step)");

  // Gᵀ L per face: face f meets edge face_edges(f,k) with sign gt_sign(f,k) (+1 when f is the
  // edge's first face, −1 for the second, 0 when the edge carries no gradient), so the
  // right-hand side is assembled face by face without a scatter.
  gt_weight_.resize(nf_, 3);
  detail::parallel_for(nf_, [&](Eigen::Index f) {
    for (int k = 0; k < 3; ++k) {
      const int e = topo_.face_edges(f, k);
      double sgn = 0;
      if (topo_.edge_is_interior[e])
        sgn = topo_.edge_faces(e, 0) == f ? 1.0 : (topo_.edge_faces(e, 1) == f ? -1.0 : 0.0);
      gt_weight_(f, k) = sgn * ops_.edge_lengths(e);
    }
  });
}

// Puts the per-face arrays into the N-step solver's order (order_), with the face numbers of
// the edges to match.
void NormalFilterRun::renumber() {
  order_ = n_system_->order();
  const bool same = order_.empty();
  auto old_face = [&](Eigen::Index i) { return same ? i : static_cast<Eigen::Index>(order_[static_cast<size_t>(i)]); };
  std::vector<int> new_face;
  if (!same) {
    new_face.resize(static_cast<size_t>(nf_));
    for (Eigen::Index i = 0; i < nf_; ++i)
      new_face[static_cast<size_t>(order_[static_cast<size_t>(i)])] = static_cast<int>(i);
  }
  face_edges_.resize(nf_, 3);
  area_.resize(nf_);
  Eigen::VectorXd fid(nf_);
  Rows gt(nf_, 3), n0(nf_, 3);
  detail::parallel_for(nf_, [&](Eigen::Index i) {
    const Eigen::Index f = old_face(i);
    for (int k = 0; k < 3; ++k) face_edges_(i, k) = topo_.face_edges(f, k);
    area_(i) = ops_.face_areas(f);
    fid(i) = fid_weight_(f);
    gt.row(i) = gt_weight_.row(f);
    n0.row(i) = N0r_.row(f);
  });
  fid_weight_.swap(fid);
  gt_weight_.swap(gt);
  N0r_.swap(n0);
  // Edges in the order the (renumbered) faces first meet them.
  std::vector<int> new_edge;
  if (!same) {
    new_edge.assign(static_cast<size_t>(ne_), -1);
    edge_order_.reserve(static_cast<size_t>(ne_));
    for (Eigen::Index i = 0; i < nf_; ++i)
      for (int k = 0; k < 3; ++k) {
        int& e = face_edges_(i, k);
        int& ne = new_edge[static_cast<size_t>(e)];
        if (ne < 0) {
          ne = static_cast<int>(edge_order_.size());
          edge_order_.push_back(e);
        }
        e = ne;
      }
    // Edges on no face (none from build_topology) keep the end.
    for (Eigen::Index e = 0; e < ne_; ++e)
      if (new_edge[static_cast<size_t>(e)] < 0) {
        new_edge[static_cast<size_t>(e)] = static_cast<int>(edge_order_.size());
        edge_order_.push_back(static_cast<int>(e));
      }
  }
  edge_faces_.resize(ne_, 2);
  len_.resize(ne_);
  beta_e_.resize(ne_);
  interior_.resize(static_cast<size_t>(ne_));
  detail::parallel_for(ne_, [&](Eigen::Index i) {
    const Eigen::Index e = same ? i : edge_order_[static_cast<size_t>(i)];
    for (int k = 0; k < 2; ++k) {
      const int f = topo_.edge_faces(e, k);
      edge_faces_(i, k) = f < 0 || same ? f : new_face[static_cast<size_t>(f)];
    }
    len_(i) = ops_.edge_lengths(e);
    beta_e_(i) = edge_beta_(e);
    interior_[static_cast<size_t>(i)] = topo_.edge_is_interior[static_cast<size_t>(e)] ? 1 : 0;
  });
}

// x (one value per edge in the solver's order) in the input edge order.
Eigen::VectorXd NormalFilterRun::edges_in_input_order(const Eigen::VectorXd& x) const {
  if (edge_order_.empty()) return x;
  Eigen::VectorXd out(x.size());
  detail::parallel_for(x.size(), [&](Eigen::Index i) { out(edge_order_[static_cast<size_t>(i)]) = x(i); });
  return out;
}

// M (#F rows in the solver's order) in the input face order.
Eigen::MatrixXd NormalFilterRun::in_input_order(const Rows& M) const {
  if (order_.empty()) return Eigen::MatrixXd(M);
  Eigen::MatrixXd out(M.rows(), 3);
  detail::parallel_for(M.rows(), [&](Eigen::Index i) { out.row(order_[static_cast<size_t>(i)]) = M.row(i); });
  return out;
}

// 1. N-step right-hand side: 2αS N⁰ + GᵀL (r p + λ) of face f.
Eigen::RowVector3d NormalFilterRun::n_step_rhs_row(Eigen::Index f) const {
  Eigen::RowVector3d b = fid_weight_(f) * N0r_.row(f);
  for (int j = 0; j < 3; ++j) {
    const int e = face_edges_(f, j);
    if (gt_weight_(f, j) != 0) b += gt_weight_(f, j) * q_.row(e);
  }
  return b;
}

// The first N-step's right-hand side.
void NormalFilterRun::n_step_rhs() {
  detail::parallel_for(nf_, [&](Eigen::Index f) { rhs_.row(f) = n_step_rhs_row(f); });
}

// One pass over the faces: the next N-step's right-hand side, its warm start (a copy of N,
// under CG) and the stopping test's ‖N^{k+1} − N^k‖_U, returned (one pass where there were
// three: ~100 MB less memory traffic per iteration at a million faces).
double NormalFilterRun::next_n_step_and_change() {
  const bool warm_start = n_system_->iterative();
  const Eigen::VectorXd& area = area_;
  const double change2 =
      detail::deterministic_sums<1>(nf_, [&](Eigen::Index f0, Eigen::Index f1, std::array<double, 1>& s) {
        for (Eigen::Index f = f0; f < f1; ++f) {
          rhs_.row(f) = n_step_rhs_row(f);
          if (warm_start) N_next_.row(f) = N_.row(f);
          s[0] += area(f) * (N_.row(f) - N_prev_.row(f)).squaredNorm();
        }
      })[0];
  return std::sqrt(std::max(0.0, change2));
}

// 1. N-step: (2αS + r GᵀLG) N_out = rhs, warm-started from N_out for CG.
// The paper projects N onto the unit sphere after every N-step. That makes the splitting
// inconsistent (p and λ then refer to another N than the linear N-step produces): for
// α ≲ 1 or heavy noise the residual grows and the normals end up worse than the input
// (gnf fandisk 0.7: normal MSAE 1106e-3 at α = 0.5 against 818e-3 for the noisy input).
// Default: solve the relaxed problem and project once after the loop (docs/presets.md).
void NormalFilterRun::n_step(Rows& N_out, const Rows& fallback) {
  const int sweeps = n_system_->solve_in_order(rhs_, N_out, n_step_tolerance_);
  if (sweeps >= 0) res_.n_solver_iterations.push_back(sweeps);
  if (o_.project_each_iteration) detail::normalize_rows(N_out, fallback);
}

// 2.+4. One pass over the edges: p-step (eq. 22: vector soft threshold of ψ = ∇N − λ/r by
// γ v² w / r), the multiplier (DESIGN.md step 4: λ += ν r (p − ∇N)), the diagonal d of the
// v-step with this iteration's weights w and its Jacobi guess v = D⁻¹b (v_step); then the IRLA
// weights of the next iteration from p^{k+1}. Returns ‖p − ∇N‖²_V.
double NormalFilterRun::edge_pass() {
  const Eigen::VectorXd& len = len_;
  const NormalFilterOptions& o = o_;
  const auto sums = detail::deterministic_sums<2>(ne_, [&](Eigen::Index e0, Eigen::Index e1, std::array<double, 2>& s) {
    for (Eigen::Index e = e0; e < e1; ++e) {
      Eigen::RowVector3d g = Eigen::RowVector3d::Zero(), pe = Eigen::RowVector3d::Zero();
      double pe_norm = 0;
      if (interior_[static_cast<size_t>(e)]) {
        g = N_.row(edge_faces_(e, 0)) - N_.row(edge_faces_(e, 1));
        const Eigen::RowVector3d psi = g - lambda_.row(e) / o.penalty;
        const double psi_norm = psi.norm();
        const double thr = o.gamma * v_(e) * v_(e) * w_(e) / o.penalty;
        if (psi_norm > thr) {
          pe = (1.0 - thr / psi_norm) * psi;
          pe_norm = psi_norm - thr;
        }
      }
      const Eigen::RowVector3d r = pe - g;
      lambda_.row(e) += o.relaxation * o.penalty * r;
      q_.row(e) = o.penalty * pe + lambda_.row(e);
      s[0] += len(e) * r.squaredNorm();
      const double d =
          smooth_diag_(e) + len(e) * (2 * o.gamma * w_(e) * pe_norm + beta_e_(e) * o.beta / (2 * o.epsilon));
      v_diag_(e) = d;
      v_(e) = v_rhs_(e) / d;  // this edge's p-step has read its v
      s[1] += smooth_diag_(e) * v_(e) * v_(e);
      w_(e) = irla_weight(pe_norm, o);
    }
  });
  v_jacobi_bound2_ = smooth_diag_max_ * sums[1];
  return sums[0];
}

// Whether the Jacobi guess y = D⁻¹b that edge_pass left in v already solves the v-step to
// v_tolerance_. Its residual is −Oy (O: the off-diagonal part, whose row sums of |o_ef| are at
// most smooth_diag_ = diag(2βε Dᵀ L_W D)), and by Cauchy–Schwarz
// ‖Oy‖² ≤ Σ_e (Σ_f |o_ef|)(Σ_f |o_ef| y_f²) ≤ (max_e smooth_diag_e) Σ_f smooth_diag_f y_f²,
// a bound edge_pass sums without a pass over the matrix. It is about 4ε²·b: for the default
// ε = 1e-3 below the N-step's tolerance while the normals still move.
bool NormalFilterRun::v_jacobi_suffices() const { return std::sqrt(v_jacobi_bound2_) <= v_tolerance_ * v_rhs_norm_; }

// 3. v-step (eq. 23) with the weights of this iteration and the new p: the Jacobi guess D⁻¹b
// when it is provably close enough (v_jacobi_suffices: no pass over the matrix), else
// Chebyshev iteration on Gershgorin's interval (or CG) from it (the matrix is strongly
// diagonally dominant for small ε: one sweep). Returns the sweeps; throws SolverError when
// 1000 do not suffice.
int NormalFilterRun::v_step() {
  if (v_jacobi_suffices()) return 0;
  // From the Jacobi guess D⁻¹b that edge_pass left in v rather than from the last v: its
  // residual is the off-diagonal part, ~4ε² of b, where the last v's is the change of v
  // between iterations, so it needs one sweep fewer.
  v_system_->set_diagonal(v_diag_);
  return v_system_->solve(v_rhs_, v_, v_tolerance_, 1000, "normal filtering (v-step)").iterations;
}

// The next N-step needs only p and λ, not v, so it can run beside this iteration's v-step:
// on two threads when the N-step is factored (each side then runs its own loops on one
// thread; measured faster than the two one after the other on two threads each). Same
// arithmetic either way.
bool NormalFilterRun::overlap() const {
  if (v_jacobi_suffices()) return false;  // no v-step to run beside: the N-step takes both threads
#ifdef _OPENMP
  // With more than two threads and enough edges for the v-step's own loops to spread, the
  // v-step keeps all threads instead (inside a section it would run on one).
  const int threads = omp_get_max_threads();
  return !n_system_->iterative() && threads > 1 && (threads == 2 || ne_ < detail::kParallelMin);
#else
  return false;
#endif
}

// The v-step, and beside it the N-step of the next iteration (unless this is the last).
void NormalFilterRun::v_step_beside_next_n_step(bool last, int& v_iterations) {
  if (overlap() && !last) {
    // Not a parallel region with an if clause: the loops inside an inactive region ran on
    // one thread (the 100K-face cube's normal filter took 1.14 s instead of 0.73 s).
    std::exception_ptr failed[2];
#pragma omp parallel sections num_threads(2)
    {
#pragma omp section
      try {
        n_step(N_next_, N_);
      } catch (...) {
        failed[0] = std::current_exception();
      }
#pragma omp section
      try {
        v_iterations = v_step();
      } catch (...) {
        failed[1] = std::current_exception();
      }
    }
    for (const auto& e : failed)
      if (e) std::rethrow_exception(e);
  } else {
    if (!last) n_step(N_next_, N_);
    v_iterations = v_step();
  }
}

NormalFilterResult NormalFilterRun::run(const ProgressCallback& progress) {
  // Inexact N-steps (a relative error criterion, as in Eckstein and Yao's inexact ADMM): while
  // the normals still move, CG needs to solve the N-step only to a small fraction of that
  // move, not to solver_tolerance: it stops at kInexactFraction times the last relative change
  // ‖N^k − N^{k−1}‖_U / ‖1‖_U, at most kInexactMax (also the first N-step's: the iterations
  // correct it), never below solver_tolerance (reached as the change falls). The 1.3M-face
  // sphere: 275 → 205 sweeps, MSAE the same to 4 digits; docs/quality.md's printed digits the
  // same (docs/performance.md). The factorisation solves exactly anyway, and a tolerance below
  // kLooseSolvesFromTolerance (preset paper's, exact comparisons) holds for every N-step.
  const bool inexact = o_.solver_tolerance >= detail::kLooseSolvesFromTolerance;
  constexpr double kInexactFraction = 0.01, kInexactMax = 1e-4;
  const double unit_norm = std::max(std::sqrt(area_.sum()), 1e-300);  // ‖1‖_U
  n_step_tolerance_ = inexact ? std::max(o_.solver_tolerance, kInexactMax) : o_.solver_tolerance;
  v_tolerance_ = std::min(1e-10, o_.solver_tolerance);  // exact: as tight as before the inexact steps
  n_step_rhs();
  N_prev_ = N_;
  n_step(N_, N_prev_);
  for (int k = 0; k < o_.max_iterations; ++k) {
    // (The edge pass reads neither the change nor the tolerances; the last iteration's
    // right-hand side is not used.)
    const double resid2 = edge_pass();
    const double change = next_n_step_and_change();
    const bool last = k + 1 == o_.max_iterations || change < o_.tolerance;
    if (inexact) {
      n_step_tolerance_ = std::max(o_.solver_tolerance, std::min(kInexactMax, kInexactFraction * change / unit_norm));
      v_tolerance_ = n_step_tolerance_;  // v enters the p-step's thresholds: as accurate as N
    }
    int v_iterations = 0;
    v_step_beside_next_n_step(last, v_iterations);
    res_.v_solver_iterations.push_back(v_iterations);

    res_.residual_history.push_back(std::sqrt(std::max(0.0, resid2)));
    res_.change_history.push_back(change);
    if (o_.record_energy)
      res_.energy_history.push_back(
          energy_normalised(ops_, in_input_order(N_), edges_in_input_order(v_), N0_, o_, face_alpha_, edge_beta_));
    res_.iterations = k + 1;

    if (progress) {
      ProgressEvent ev{"normal filtering", k + 1, o_.max_iterations, change};
      if (!progress(ev)) throw Cancelled("normal filtering cancelled");
    }
    if (change < o_.tolerance) {
      res_.converged = true;
      break;
    }
    if (last) break;
    N_prev_.swap(N_);  // N_prev = N^k
    N_.swap(N_next_);  // N = N^{k+1}
  }
  detail::normalize_rows(N_, N0r_);
  res_.normals = in_input_order(N_);
  res_.v = edges_in_input_order(v_);
  res_.edges = topo_.edges;
  return std::move(res_);
}

}  // namespace

NormalFilterResult filter_normals(const PreparedMesh& mesh, const NormalFilterOptions& o,
                                  const NormalFilterWeights& weights, const ProgressCallback& progress,
                                  const Eigen::MatrixXd& normals0) {
  o.validate();
  if (mesh.num_faces() == 0) throw InvalidInput("normal filtering: the mesh has no faces");
  NormalFilterResult r;
  {
    NormalFilterRun run(mesh, o, weights, normals0);  // its arrays are freed before the polish
    r = run.run(progress);
  }
  if (o.polish > 0) r.normals = detail::polish_normals(mesh, r.normals, r.v, o.polish, o.polish_range);
  return r;
}

}  // namespace msmesh
