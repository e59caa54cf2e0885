// The two solvers of the constant systems (Cholesky factorisation and warm-started
// conjugate gradients) give the same filtered normals and vertices, and the parallel loops
// give bit-identical results whatever the number of threads (set_threads; its checks: test_threads.cpp; msmesh
// --threads: cli/test_threads_cli.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/io.h"
#include "msmesh/noise.h"
#include "msmesh/presets.h"
#include "msmesh/shapes.h"
#include "msmesh/threads.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

// solver_tolerance: below 1e-6 every N-step is solved to it; at the default (1e-6) the early
// ones only to a fraction of the normals' change (normal_filter.cpp, run()).
NormalFilterResult filter_with(const Mesh& m, LinearSolver s, const char* preset = "cad",
                               double solver_tolerance = 1e-6) {
  NormalFilterOptions o = preset_options(preset).normals;
  o.solver = s;
  o.tolerance = 0;
  o.solver_tolerance = solver_tolerance;
  return filter_normals(m.V, m.F, o);
}

}  // namespace

TEST(Solver, ConjugateGradientsMatchCholeskyInTheNormalFilter) {
  const Mesh m = test::noisy_cube(8);
  for (const char* preset : {"cad", "smooth"}) {
    const NormalFilterResult a = filter_with(m, LinearSolver::Cholesky, preset, 0.99e-6);
    const NormalFilterResult b = filter_with(m, LinearSolver::CG, preset, 0.99e-6);
    EXPECT_TRUE(a.n_solver_iterations.empty());
    ASSERT_EQ(b.n_solver_iterations.size(), 30u);
    for (int it : b.n_solver_iterations) {
      EXPECT_GT(it, 0);
      EXPECT_LT(it, 60);  // bounded: the N-step matrix is well conditioned at any size
    }
    // Every N-step to (just below) the default solver tolerance: within 1e-5 after 30 iterations.
    EXPECT_LT((a.normals - b.normals).cwiseAbs().maxCoeff(), 1e-5) << preset;
    EXPECT_LT((a.v - b.v).cwiseAbs().maxCoeff(), 1e-5) << preset;
  }
  // Auto factors small meshes (exact, and faster there).
  EXPECT_TRUE(filter_with(m, LinearSolver::Auto).n_solver_iterations.empty());
}

TEST(Solver, EarlyNStepsAreSolvedLooselyAndLandNearTheFactorisation) {
  // At the default solver tolerance an N-step (and the v-step) is solved only to a hundredth of
  // the normals' last relative change (at most 1e-4, at least 1e-6; normal_filter.cpp, run());
  // just below it every N-step is solved to it. The loose early steps take the iterations
  // along another path: after 30 iterations (not converged) within 2e-5 of the factorisation's
  // normals on the cad cube (measured 1.3e-5), 3e-3 on the smooth one, whose small ADMM
  // penalty keeps a perturbation of the path longer in the iterates (measured 1.5e-3; the
  // quality figures of docs/quality.md and docs/sweep.md did not move, docs/performance.md).
  const Mesh m = test::noisy_cube(8);
  for (const char* preset : {"cad", "smooth"}) {
    const NormalFilterResult exact = filter_with(m, LinearSolver::Cholesky, preset, 0.99e-6);
    const NormalFilterResult loose = filter_with(m, LinearSolver::CG, preset);
    const NormalFilterResult tight = filter_with(m, LinearSolver::CG, preset, 0.99e-6);
    ASSERT_EQ(loose.n_solver_iterations.size(), tight.n_solver_iterations.size());
    int sum_loose = 0, sum_tight = 0;
    for (size_t k = 0; k < loose.n_solver_iterations.size(); ++k) {
      sum_loose += loose.n_solver_iterations[k];
      sum_tight += tight.n_solver_iterations[k];
    }
    EXPECT_LT(sum_loose, 0.9 * sum_tight) << preset;
    const bool cad = std::string(preset) == "cad";
    EXPECT_LT((loose.normals - exact.normals).cwiseAbs().maxCoeff(), cad ? 2e-5 : 3e-3) << preset;
    EXPECT_LT((loose.v - exact.v).cwiseAbs().maxCoeff(), cad ? 5e-5 : 1e-4) << preset;
  }
}

TEST(Solver, TheVStepTakesItsJacobiGuessWhereItIsProvablyCloseEnough) {
  // The v-step's matrix is diagonally dominant by ~1/(4ε²): the guess D⁻¹b has a relative
  // residual of about 4ε², which a bound summed in the edge pass shows below the step's
  // tolerance at the default ε (1e-3): no sweep (normal_filter.cpp, v_jacobi_suffices). Near
  // the end, where the tolerance reaches 1e-6, the bound is close to it (the sanitizers' build
  // measured 3 of the 30 v-steps with a sweep, the release build none). At a tolerance below
  // 1e-6 every v-step is solved to 1e-10 as before (a sweep each), and at a large ε the bound
  // fails and the v-step sweeps.
  const Mesh m = test::noisy_cube(8);
  NormalFilterOptions o = preset_options("cad").normals;
  o.tolerance = 0;
  const NormalFilterResult loose = filter_normals(m.V, m.F, o);
  ASSERT_EQ(loose.v_solver_iterations.size(), 30u);
  int without_sweep = 0;
  for (int it : loose.v_solver_iterations) {
    EXPECT_LE(it, 1);
    without_sweep += it == 0;
  }
  EXPECT_GE(without_sweep, 20);
  o.solver_tolerance = 0.99e-6;
  const NormalFilterResult tight = filter_normals(m.V, m.F, o);
  for (int it : tight.v_solver_iterations) EXPECT_GE(it, 1);
  EXPECT_LT((loose.v - tight.v).cwiseAbs().maxCoeff(), 5e-5);
  o.solver_tolerance = 1e-6;
  o.epsilon = 0.3;
  const NormalFilterResult wide = filter_normals(m.V, m.F, o);
  int sweeps = 0;
  for (int it : wide.v_solver_iterations) sweeps += it;
  EXPECT_GT(sweeps, 0);
  EXPECT_GE(wide.v.minCoeff(), 0.0);
  EXPECT_LE(wide.v.maxCoeff(), 1.0);
}

TEST(Solver, ConjugateGradientsRecordTheEnergyOfTheFactorisation) {
  // CG renumbers the faces and edges internally (normal_filter.cpp): the recorded energy must
  // still be that of the input-order normals and v.
  const Mesh m = test::noisy_cube(8);
  NormalFilterOptions o = preset_options("cad").normals;
  o.record_energy = true;
  o.tolerance = 0;
  o.max_iterations = 10;
  o.solver_tolerance = 0.99e-6;  // every N-step solved to it (not only to a fraction of the change)
  o.solver = LinearSolver::Cholesky;
  const NormalFilterResult a = filter_normals(m.V, m.F, o);
  o.solver = LinearSolver::CG;
  const NormalFilterResult b = filter_normals(m.V, m.F, o);
  ASSERT_EQ(a.energy_history.size(), 10u);
  ASSERT_EQ(b.energy_history.size(), 10u);
  for (size_t k = 0; k < a.energy_history.size(); ++k)
    EXPECT_NEAR(a.energy_history[k], b.energy_history[k], 1e-5 * std::abs(a.energy_history[k])) << k;
}

TEST(Solver, TighterToleranceApproachesTheFactorisation) {
  const Mesh m = test::noisy_cube(6);
  const NormalFilterResult exact = filter_with(m, LinearSolver::Cholesky, "cad", 1e-11);
  double previous = 1e300;
  for (double tol : {1e-4, 1e-7, 1e-11}) {
    NormalFilterOptions o = preset_options("cad").normals;
    o.solver = LinearSolver::CG;
    o.solver_tolerance = tol;
    o.tolerance = 0;
    const double err = (filter_normals(m.V, m.F, o).normals - exact.normals).cwiseAbs().maxCoeff();
    EXPECT_LT(err, previous * 1.01 + 1e-13) << tol;
    previous = err;
  }
  EXPECT_LT(previous, 1e-9);
}

TEST(Solver, ConjugateGradientsMatchCholeskyInTheVertexUpdate) {
  const Mesh m = test::noisy_cube(8);
  const Mesh clean = make_cube(8);
  const Eigen::MatrixXd N = face_normals(clean.V, clean.F);
  // The plain alternation, and the accelerated one (which carries the solver's error of the
  // last few iterations into its combination: measured 1.2e-5 edge lengths on the cad cube).
  for (int acceleration : {0, 5})
    for (const char* preset : {"cad", "smooth"}) {
      VertexUpdateOptions o = preset_options(preset).vertices;
      o.tolerance = 0;
      o.acceleration = acceleration;
      o.solver = LinearSolver::Cholesky;
      const VertexUpdateResult a = update_vertices(m.V, m.F, N, {}, o);
      o.solver = LinearSolver::CG;
      const VertexUpdateResult b = update_vertices(m.V, m.F, N, {}, o);
      ASSERT_EQ(b.solver_iterations.size(), 30u);
      // CG at the default tolerance solves a V-step only to 3 % of the last move while the
      // vertices still move (src/vertex_update.cpp): the plain cad alternation still moves
      // 6e-4 edges at iteration 30, measured 1.8e-5 apart.
      const double edge = 2.0 / 8, bound = (acceleration ? 5e-5 : 1e-5) + 0.03 * b.change_history.back();
      EXPECT_LT((a.V - b.V).cwiseAbs().maxCoeff(), bound * edge) << preset << " acceleration " << acceleration;
      EXPECT_EQ(a.fallback_projections, b.fallback_projections);
    }
}

TEST(Solver, AutoUsesConjugateGradientsOnLargeMeshesUnlessWeightsSwitchTheDataTermOff) {
  // Inpainting gives new vertices ω₃ ≈ 0: the system is then badly conditioned and Auto
  // factors it; with plain weights Auto uses conjugate gradients from 40K vertices (10K when
  // accelerated).
  const Mesh m = test::noisy_cube(82);  // 80688 faces, 40346 vertices
  ASSERT_GT(m.V.rows(), 40000);
  const Eigen::MatrixXd N = face_normals(make_cube(82).V, m.F);
  VertexUpdateOptions o;
  o.max_iterations = 2;
  VertexUpdateWeights w;
  w.vertex_omega3 = Eigen::VectorXd::Ones(m.V.rows());
  EXPECT_FALSE(update_vertices(m.V, m.F, N, {}, o, w).solver_iterations.empty());
  w.vertex_omega3(0) = 0;
  EXPECT_TRUE(update_vertices(m.V, m.F, N, {}, o, w).solver_iterations.empty());
  // A pinned vertex (huge ω₃) would dominate CG's relative residual: factored too, and it moves
  // the others.
  w.vertex_omega3(0) = 1e9;
  const VertexUpdateResult pinned = update_vertices(m.V, m.F, N, {}, o, w);
  EXPECT_TRUE(pinned.solver_iterations.empty());
  EXPECT_GT((pinned.V - m.V).rowwise().norm().maxCoeff(), 1e-3 * mean_edge_length(m.V, m.F));
  NormalFilterOptions no;
  no.max_iterations = 2;
  EXPECT_FALSE(filter_normals(m.V, m.F, no).n_solver_iterations.empty());
  NormalFilterWeights nw;
  nw.face_alpha = Eigen::VectorXd::Ones(m.F.rows());
  nw.face_alpha(5) = 0;
  EXPECT_TRUE(filter_normals(m.V, m.F, no, nw).n_solver_iterations.empty());
}

TEST(Solver, BadSolverToleranceIsRejectedWithItsRange) {
  const Mesh m = test::noisy_cube(2);
  NormalFilterOptions o;
  o.solver_tolerance = 0;
  try {
    filter_normals(m.V, m.F, o);
    FAIL() << "accepted solver_tolerance 0";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("solver-tolerance"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("(0, 1)"), std::string::npos);
  }
  VertexUpdateOptions vo;
  vo.solver_tolerance = 2;
  EXPECT_THROW(update_vertices(m.V, m.F, face_normals(m.V, m.F), {}, vo), InvalidInput);
}

TEST(Solver, ResultsDoNotDependOnTheThreadCount) {
#ifndef _OPENMP
  GTEST_SKIP() << "built without OpenMP";
#else
  // Large enough for the per-face and per-edge loops to run in parallel (at least
  // kParallelMin = 32768 rows), for both solver paths: the factored N-step runs beside the
  // v-step on two threads (sequentially on one), CG splits its kernels over the threads.
  const Mesh m = test::noisy_cube(53);
  ASSERT_GE(m.F.rows(), 32768);
  const int threads = msmesh::threads();
  for (const LinearSolver solver : {LinearSolver::Auto, LinearSolver::CG}) {
    SCOPED_TRACE(solver == LinearSolver::Auto ? "auto (factor)" : "cg");
    DenoiseOptions o = preset_options("cad");
    o.normals.max_iterations = 5;
    o.vertices.max_iterations = 5;
    o.normals.solver = o.vertices.solver = solver;
    set_threads(1);
    ASSERT_EQ(msmesh::threads(), 1);
    const DenoiseResult one = denoise(m.V, m.F, o);
    set_threads(std::max(2, threads));
    const DenoiseResult many = denoise(m.V, m.F, o);
    set_threads(threads);
    EXPECT_EQ(one.V, many.V);  // bit for bit
    EXPECT_EQ(one.normals, many.normals);
    EXPECT_EQ(one.v, many.v);
    EXPECT_EQ(one.normal_report.residual_history, many.normal_report.residual_history);
  }
#endif
}

// The N-step of iteration k+1 is solved beside the v-step of iteration k; it must not be
// solved when iteration k is the last (max_iterations or converged), and stopping on the
// tolerance must give the iterate of the stopping iteration, whatever the solver.
TEST(Solver, OneNStepPerIterationAlsoWhenStoppingEarly) {
  const Mesh m = test::noisy_cube(6, 0.05);
  for (const LinearSolver solver : {LinearSolver::Cholesky, LinearSolver::CG}) {
    SCOPED_TRACE(solver == LinearSolver::Cholesky ? "cholesky" : "cg");
    NormalFilterOptions o = preset_options("cad").normals;
    o.solver = solver;
    o.max_iterations = 200;
    o.tolerance = 1e-3;
    const NormalFilterResult early = filter_normals(m.V, m.F, o);
    ASSERT_TRUE(early.converged);
    ASSERT_LT(early.iterations, 200);
    ASSERT_EQ(early.change_history.size(), static_cast<size_t>(early.iterations));
    EXPECT_LT(early.change_history.back(), 1e-3);
    if (solver == LinearSolver::CG) EXPECT_EQ(early.n_solver_iterations.size(), static_cast<size_t>(early.iterations));
    // The same number of iterations run to their end without the tolerance: same result.
    o.tolerance = 0;
    o.max_iterations = early.iterations;
    const NormalFilterResult fixed = filter_normals(m.V, m.F, o);
    EXPECT_FALSE(fixed.converged);
    EXPECT_EQ(fixed.iterations, early.iterations);
    EXPECT_EQ(fixed.normals, early.normals);
    EXPECT_EQ(fixed.v, early.v);
    if (solver == LinearSolver::CG) EXPECT_EQ(fixed.n_solver_iterations, early.n_solver_iterations);
  }
}
