#include "msmesh/normal_filter.h"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <sstream>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/operators.h"
#include "msmesh/topology.h"
#include "normalize.h"

namespace msmesh {

namespace {

void require(bool ok, const char* name, double value, const char* range) {
  if (ok) return;
  std::ostringstream os;
  os << "normal filtering: " << name << " = " << value << " is out of range; valid: " << range;
  throw InvalidInput(os.str());
}

// ‖a‖_w for a field with one row per element and weights w.
double weighted_norm(const Eigen::MatrixXd& a, const Eigen::VectorXd& w) {
  return std::sqrt(std::max(0.0, inner_product(a, a, w)));
}

}  // namespace

void NormalFilterOptions::validate() const {
  auto pos = [](double x) { return std::isfinite(x) && x > 0; };
  require(pos(alpha), "alpha", alpha, "> 0");
  require(pos(beta), "beta", beta, "> 0");
  require(pos(gamma), "gamma", gamma, "> 0");
  require(pos(epsilon), "epsilon", epsilon, "> 0");
  require(pos(rho), "rho", rho, "> 0");
  require(pos(penalty), "penalty (r_p)", penalty, "> 0");
  require(std::isfinite(relaxation) && relaxation > 0 && relaxation < (1 + std::sqrt(5.0)) / 2, "relaxation (nu)",
          relaxation, "(0, 1.618...)");
  require(max_iterations >= 1 && max_iterations <= 100000, "max_iterations", max_iterations, "[1, 100000]");
  require(std::isfinite(tolerance) && tolerance >= 0, "tolerance", tolerance, ">= 0");
  require(std::isfinite(v_initial) && v_initial >= 0 && v_initial <= 1, "v_initial", v_initial, "[0, 1]");
}

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
  if (w.size() == 0) return Eigen::VectorXd::Ones(n);
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
  o.validate();
  validate_mesh(V, F, "normal filtering");
  if (F.rows() == 0) throw InvalidInput("normal filtering: the mesh has no faces");
  const detail::Normalization norm = detail::normalization_for(V, F);
  const Eigen::MatrixXd Vn = norm.apply(V);
  const Topology topo = build_topology(F, V.rows());
  const Operators ops = build_operators(Vn, F, topo);
  const Eigen::Index nf = F.rows(), ne = topo.num_edges();
  const Eigen::VectorXd face_alpha = ones_or(weights.face_alpha, nf, "face_alpha");
  const Eigen::VectorXd edge_beta = ones_or(weights.edge_beta, ne, "edge_beta");

  Eigen::MatrixXd N0 = normals0.size() ? normals0 : face_normals(Vn, F);
  if (N0.rows() != nf || N0.cols() != 3) throw InvalidInput("normal filtering: input normals must be #F by 3");

  // Zero-area faces would make the N-step singular where they have no interior edge; give
  // them a tiny positive weight instead (their normals then follow their neighbours).
  const double area_floor = 1e-12 * std::max(1e-300, ops.face_areas.mean());
  const Eigen::VectorXd fid_weight =
      (2.0 * o.alpha) * ops.face_areas.cwiseMax(area_floor).cwiseProduct(face_alpha).cwiseMax(area_floor);

  // N-step matrix (eq. 20 in matrix form, DESIGN.md step 1): 2αS + r Gᵀ L G; constant.
  const SparseMatrix GtL = ops.G.transpose() * ops.edge_lengths.asDiagonal();
  SparseMatrix A = o.penalty * (GtL * ops.G);
  A += SparseMatrix(fid_weight.asDiagonal());
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> chol;
  chol.compute(A);
  if (chol.info() != Eigen::Success)
    throw SolverError("normal filtering: Cholesky factorisation of the N-step matrix failed");
  const Eigen::MatrixXd rhs0 = fid_weight.asDiagonal() * N0;

  // v-step matrix (eq. 23): L·diag(2γ w‖p‖ + β_e/(2ε)) + 2βε Dᵀ L_W D. Only the diagonal
  // changes; keep the constant part and the positions of its diagonal entries.
  SparseMatrix Kv = (2.0 * o.beta * o.epsilon) * SparseMatrix(ops.D.transpose() * ops.line_lengths.asDiagonal() * ops.D);
  {
    SparseMatrix I(ne, ne);
    I.setIdentity();
    Kv += 0.0 * I;  // make sure every diagonal entry is stored
  }
  Kv.makeCompressed();
  std::vector<double*> diag(static_cast<size_t>(ne), nullptr);
  for (Eigen::Index c = 0; c < Kv.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(Kv, c); it; ++it)
      if (it.row() == it.col()) diag[c] = &it.valueRef();
  const Eigen::VectorXd Kv_diag = Kv.diagonal();
  const Eigen::VectorXd v_rhs = ops.edge_lengths.cwiseProduct(edge_beta) * (o.beta / (2 * o.epsilon));
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper, Eigen::DiagonalPreconditioner<double>> cg;
  cg.setTolerance(1e-10);
  cg.setMaxIterations(1000);

  Eigen::MatrixXd N = N0;
  Eigen::MatrixXd p = Eigen::MatrixXd::Zero(ne, 3), lambda = Eigen::MatrixXd::Zero(ne, 3);
  Eigen::VectorXd v = Eigen::VectorXd::Constant(ne, o.v_initial);
  Eigen::VectorXd w = Eigen::VectorXd::Ones(ne);  // w⁰ = 1
  Eigen::VectorXd p_norm = Eigen::VectorXd::Zero(ne);

  NormalFilterResult res;
  for (int k = 0; k < o.max_iterations; ++k) {
    // 1. N-step: (2αS + r GᵀLG) N = 2αS N⁰ + GᵀL (r p + λ), then project rows onto the sphere.
    const Eigen::MatrixXd rhs = rhs0 + GtL * (o.penalty * p + lambda);
    Eigen::MatrixXd Nn = chol.solve(rhs);
    if (chol.info() != Eigen::Success) throw SolverError("normal filtering: N-step solve failed");
    // The paper projects N onto the unit sphere after every N-step. That makes the splitting
    // inconsistent (p and λ then refer to another N than the linear N-step produces): for
    // α ≲ 1 or heavy noise the residual grows and the normals end up worse than the input
    // (gnf fandisk 0.7: normal MSAE 1106e-3 at α = 0.5 against 818e-3 for the noisy input).
    // Default: solve the relaxed problem and project once after the loop (docs/presets.md).
    if (o.project_each_iteration) {
      for (Eigen::Index f = 0; f < nf; ++f) {
        const double len = Nn.row(f).norm();
        if (len > 0 && std::isfinite(len))
          Nn.row(f) /= len;
        else
          Nn.row(f) = N.row(f);
      }
    }
    // 2. p-step (eq. 22): vector soft threshold of ψ = ∇N − λ/r by γ v² w / r.
    const Eigen::MatrixXd gN = ops.G * Nn;
#pragma omp parallel for schedule(static)
    for (Eigen::Index e = 0; e < ne; ++e) {
      if (!topo.edge_is_interior[e]) {
        p.row(e).setZero();
        p_norm(e) = 0;
        continue;
      }
      const Eigen::RowVector3d psi = gN.row(e) - lambda.row(e) / o.penalty;
      const double psi_norm = psi.norm();
      const double thr = o.gamma * v(e) * v(e) * w(e) / o.penalty;
      if (psi_norm > thr) {
        p.row(e) = (1.0 - thr / psi_norm) * psi;
        p_norm(e) = psi_norm - thr;
      } else {
        p.row(e).setZero();
        p_norm(e) = 0;
      }
    }
    // 3. v-step (eq. 23) with the weights of this iteration and the new p; warm-started
    // Jacobi-preconditioned CG (the matrix is strongly diagonally dominant for small ε).
    for (Eigen::Index e = 0; e < ne; ++e)
      *diag[e] = Kv_diag(e) + ops.edge_lengths(e) * (2 * o.gamma * w(e) * p_norm(e) +
                                                     edge_beta(e) * o.beta / (2 * o.epsilon));
    cg.compute(Kv);
    Eigen::VectorXd vn = cg.solveWithGuess(v_rhs, v);
    if (cg.info() != Eigen::Success && cg.error() > 1e-6)
      throw SolverError("normal filtering: v-step conjugate gradient did not converge");
    res.v_solver_iterations.push_back(static_cast<int>(cg.iterations()));
    v = vn;
    // 4. Multiplier (DESIGN.md step 4: λ += ν r (p − ∇N), the sign consistent with the N- and p-steps).
    const Eigen::MatrixXd r = p - gN;
    lambda += o.relaxation * o.penalty * r;

    const Eigen::MatrixXd dN = Nn - N;
    const double change = weighted_norm(dN, ops.face_areas);
    N = std::move(Nn);
    res.residual_history.push_back(weighted_norm(r, ops.edge_lengths));
    res.change_history.push_back(change);
    res.energy_history.push_back(energy_normalised(ops, N, v, N0, o, face_alpha, edge_beta));
    res.iterations = k + 1;
    // IRLA weights for the next iteration from p^{k+1}.
    for (Eigen::Index e = 0; e < ne; ++e) w(e) = irla_weight(p_norm(e), o);

    if (progress) {
      ProgressEvent ev{"normal filtering", k + 1, o.max_iterations, change};
      if (!progress(ev)) throw Cancelled("normal filtering cancelled");
    }
    if (change < o.tolerance) {
      res.converged = true;
      break;
    }
  }
  for (Eigen::Index f = 0; f < nf; ++f) {
    const double len = N.row(f).norm();
    if (len > 0 && std::isfinite(len))
      N.row(f) /= len;
    else
      N.row(f) = N0.row(f);
  }
  res.normals = std::move(N);
  res.v = std::move(v);
  return res;
}

}  // namespace msmesh
