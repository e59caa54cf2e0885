// The library's conjugate gradients (src/pcg.h): one column as the v-step uses them, three as
// the N-step and the vertex update; both matrix layouts and both storage precisions.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/noise.h"
#include "msmesh/presets.h"
#include "msmesh/shapes.h"
#include "pcg.h"
#include "test_helpers.h"
#include "wide_rows.h"

using namespace msmesh;

TEST(InternalPcg, OneColumnSolvesWithAChangedDiagonal) {
  // A path-graph Laplacian plus a diagonal, set after construction.
  const int n = 50;
  Eigen::SparseMatrix<double> A(n, n);
  for (int i = 0; i < n; ++i) {
    A.insert(i, i) = 0.0;  // stored, replaced below
    if (i > 0) A.insert(i, i - 1) = -1.0;
    if (i + 1 < n) A.insert(i, i + 1) = -1.0;
  }
  A.makeCompressed();
  for (bool reorder : {false, true}) {
    detail::BlockPcg pcg(A, reorder);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    EXPECT_THROW(pcg.solve(b, x, 1e-10, 1000, "test"), SolverError);  // zero diagonal
    const Eigen::VectorXd d = Eigen::VectorXd::Constant(n, 3.0);
    pcg.set_diagonal(d);
    const detail::PcgStats st = pcg.solve(b, x, 1e-10, 1000, "test");
    Eigen::SparseMatrix<double> Ad = A;
    for (int i = 0; i < n; ++i) Ad.coeffRef(i, i) = 3.0;
    EXPECT_LT((Ad * x - b).norm(), 1e-9 * b.norm());
    EXPECT_GT(st.iterations, 0);
    EXPECT_EQ(pcg.solve(b, x, 1e-10, 1000, "test").iterations, 0);  // warm start: done
  }
}

namespace {

// A w×w grid graph's weighted Laplacian plus `shift` on the diagonal. max_neighbours 4: every
// grid link (up to 4 entries beside the diagonal, the compressed layout); 3: the vertical
// links of every other column only (at most 3, as in a face graph: the fixed-width layout).
Eigen::SparseMatrix<double> grid_matrix(int w, int max_neighbours, double shift) {
  const int n = w * w;
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) t.emplace_back(i, i, shift);
  auto link = [&](int a, int b, double weight) {
    t.emplace_back(a, b, -weight);
    t.emplace_back(b, a, -weight);
    t.emplace_back(a, a, weight);
    t.emplace_back(b, b, weight);
  };
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < w; ++x) {
      const int i = y * w + x;
      if (x + 1 < w) link(i, i + 1, 1.0 + 0.1 * (i % 7));
      // Vertical links only from even x: every row then has at most 3 neighbours (a face
      // graph's count), unless max_neighbours asks for all four.
      if (y + 1 < w && (max_neighbours > 3 || (x + y) % 2 == 0)) link(i, i + w, 0.5 + 0.1 * (i % 5));
    }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

}  // namespace

TEST(InternalPcg, BothLayoutsAndPrecisionsSolveToTheTolerance) {
  // At most 3 neighbours per row: the fixed-width layout; 4: the compressed rows. Each in
  // double and in single-precision storage, three columns, against a direct solution.
  for (int neighbours : {3, 4}) {
    const Eigen::SparseMatrix<double> A = grid_matrix(40, neighbours, 0.3);
    const Eigen::Index n = A.rows();
    Eigen::MatrixXd B(n, 3);
    for (Eigen::Index i = 0; i < n; ++i) B.row(i) << std::sin(0.1 * i), std::cos(0.07 * i), 1.0;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(A);
    const Eigen::MatrixXd exact = ldlt.solve(B);
    const detail::RowMatrixX3 Br = detail::to_rows(B);
    for (bool single : {false, true}) {
      detail::RowMatrixX3 X = detail::RowMatrixX3::Zero(n, 3);
      const detail::PcgStats st = single ? detail::SingleBlockPcg(A).solve(Br, X, 1e-6, 1000, "test")
                                         : detail::BlockPcg(A).solve(Br, X, 1e-6, 1000, "test");
      EXPECT_GT(st.iterations, 5) << neighbours << single;
      EXPECT_LE(st.relative_residual, 1e-6);
      for (int c = 0; c < 3; ++c) {
        // The true residual, not only CG's updated one: single precision rounds the matrix
        // (relative 6e-8) and the work vectors, far below the tolerance.
        const double res = (A * X.col(c) - B.col(c)).norm() / B.col(c).norm();
        EXPECT_LT(res, 2e-6) << neighbours << " " << single << " " << c;
        EXPECT_LT((X.col(c) - exact.col(c)).cwiseAbs().maxCoeff(), 1e-4 * exact.col(c).cwiseAbs().maxCoeff());
      }
    }
  }
}

TEST(InternalPcg, AGivenOrderIsUsedAsItIs) {
  // The order of another solver of the same pattern (the polish takes the N-step's): the same
  // solution as in the solver's own order, the order kept; one of the wrong length is refused.
  const Eigen::SparseMatrix<double> A = grid_matrix(40, 3, 0.3);
  const Eigen::Index n = A.rows();
  const detail::BlockPcg own(A);
  ASSERT_FALSE(own.order().empty());
  std::vector<int> reversed(own.order().rbegin(), own.order().rend());
  const detail::BlockPcg given(A, reversed);
  EXPECT_EQ(given.order(), reversed);
  detail::RowMatrixX3 B(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) B.row(i) << 1.0, std::sin(0.1 * i), std::cos(0.05 * i);
  detail::RowMatrixX3 X1 = detail::RowMatrixX3::Zero(n, 3), X2 = X1;
  own.solve(B, X1, 1e-10, 1000, "test");
  given.solve(B, X2, 1e-10, 1000, "test");
  EXPECT_LT((X1 - X2).norm(), 1e-8 * X1.norm());
  EXPECT_LT((A * Eigen::MatrixXd(X2) - Eigen::MatrixXd(B)).norm(), 1e-9 * B.norm());
  EXPECT_THROW(detail::BlockPcg(A, std::vector<int>(static_cast<size_t>(n - 1), 0)), SolverError);
}

TEST(InternalPcg, FixedWidthRowsGiveTheAssembledMatrixsSolverBitForBit) {
  // The rows of grid_matrix(…, 3, …) handed over one by one (the N-step's and the polish's
  // face graphs): the same order, the same products and so the same solution to the last bit
  // as the solver of the assembled matrix, in both precisions and with a given order; the
  // entries in any order, a repeated column summed (one link split in two here).
  const Eigen::SparseMatrix<double> A = grid_matrix(30, 3, 0.3);
  const Eigen::Index n = A.rows();
  const Eigen::Map<const detail::RowSparse> R(n, n, A.nonZeros(), A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr());
  const detail::FixedWidthRows rows = [&](Eigen::Index i, double* diag, int* cols, double* vals) {
    int m = 0;
    for (Eigen::Map<const detail::RowSparse>::InnerIterator it(R, i); it; ++it)
      if (it.col() == i) {
        *diag = it.value();
      } else {
        cols[m] = static_cast<int>(it.col());
        vals[m++] = it.value();
      }
    std::reverse(cols, cols + m);
    std::reverse(vals, vals + m);
    if (m == 1) {  // the one link split into two halves of the same column
      cols[1] = cols[0];
      vals[1] = vals[0] = 0.5 * vals[0];
      m = 2;
    }
    return m;
  };
  detail::RowMatrixX3 B(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) B.row(i) << 1.0, std::sin(0.1 * i), std::cos(0.05 * i);
  auto solution = [&](const auto& pcg) {
    detail::RowMatrixX3 X = detail::RowMatrixX3::Zero(n, 3);
    pcg.solve(B, X, 1e-8, 1000, "test");
    return X;
  };
  const detail::BlockPcg assembled(A);
  const detail::BlockPcg from_rows(n, rows, {});
  EXPECT_EQ(from_rows.order(), assembled.order());
  EXPECT_EQ(solution(from_rows), solution(assembled));
  EXPECT_EQ(solution(detail::SingleBlockPcg(n, rows, {})), solution(detail::SingleBlockPcg(A)));
  std::vector<int> reversed(assembled.order().rbegin(), assembled.order().rend());
  EXPECT_EQ(solution(detail::BlockPcg(n, rows, reversed)), solution(detail::BlockPcg(A, reversed)));
  EXPECT_LT((A * Eigen::MatrixXd(solution(from_rows)) - Eigen::MatrixXd(B)).norm(), 1e-7 * B.norm());
  // Four entries beside the diagonal, a wrong order's length, a diagonal that is not positive.
  const detail::FixedWidthRows wide = [](Eigen::Index i, double* diag, int* cols, double* vals) {
    *diag = 5;
    for (int k = 0; k < 4; ++k) {  // (the last row too: written into the room beyond three)
      cols[k] = static_cast<int>((i + k + 1) % 10);
      vals[k] = -1;
    }
    return 4;
  };
  EXPECT_THROW(detail::BlockPcg(10, wide, {}), SolverError);
  const detail::FixedWidthRows last_wide = [&](Eigen::Index i, double* diag, int* cols, double* vals) {
    return i + 1 == n ? wide(i, diag, cols, vals) : rows(i, diag, cols, vals);
  };
  EXPECT_THROW(detail::BlockPcg(n, last_wide, {}), SolverError);
  EXPECT_THROW(detail::BlockPcg(n, rows, std::vector<int>(static_cast<size_t>(n - 1), 0)), SolverError);
  const detail::FixedWidthRows negative = [&](Eigen::Index i, double* diag, int* cols, double* vals) {
    const int m = rows(i, diag, cols, vals);
    if (i == 7) *diag = -1;
    return m;
  };
  const detail::BlockPcg bad(n, negative, {});
  detail::RowMatrixX3 X = detail::RowMatrixX3::Zero(n, 3);
  try {
    bad.solve(B, X, 1e-8, 1000, "test");
    ADD_FAILURE() << "no error for a negative diagonal entry";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("diagonal entry 7 = -1"), std::string::npos) << e.what();
  }
}

TEST(InternalPcg, OneColumnWithAChangedDiagonalInTheCompressedLayout) {
  // Four neighbours per row (the v-step's edge graph has up to four): compressed rows, whose
  // diagonal entries set_diagonal rewrites in place.
  const Eigen::SparseMatrix<double> A = grid_matrix(20, 4, 0.0);
  const Eigen::Index n = A.rows();
  detail::BlockPcg pcg(A, /*reorder=*/true);
  Eigen::VectorXd d(n);
  for (Eigen::Index i = 0; i < n; ++i) d(i) = A.coeff(i, i) + 1.0 + 0.01 * (i % 3);
  pcg.set_diagonal(d);
  Eigen::SparseMatrix<double> Ad = A;
  for (Eigen::Index i = 0; i < n; ++i) Ad.coeffRef(i, i) = d(i);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  pcg.solve(b, x, 1e-10, 1000, "test");
  EXPECT_LT((Ad * x - b).norm(), 1e-9 * b.norm());
}

namespace {

// A sequence of warm-started solves as in the N-step, with Chebyshev (after its first solve,
// CG, has learnt the spectrum) and with plain CG side by side, each against a direct solution;
// one right-hand side column is 0 every other solve.
template <class Pcg>
void check_chebyshev_sequence(const Eigen::SparseMatrix<double>& A, const std::string& label) {
  const Eigen::Index n = A.rows();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(A);
  Pcg cheb(A), cg(A);
  cheb.use_chebyshev();
  detail::RowMatrixX3 X = detail::RowMatrixX3::Zero(n, 3), Xcg = X;
  int sweeps = 0, cg_sweeps = 0;
  for (int k = 0; k < 6; ++k) {
    Eigen::MatrixXd B(n, 3);
    for (Eigen::Index i = 0; i < n; ++i)
      B.row(i) << std::sin(0.1 * i + 0.3 * k), k % 2 == 0 ? 0.0 : std::cos(0.07 * i), 1.0 + 0.1 * k;
    const detail::RowMatrixX3 Br = detail::to_rows(B);
    const Eigen::MatrixXd exact = ldlt.solve(B);
    const detail::PcgStats st = cheb.solve(Br, X, 1e-6, 1000, "test");
    const detail::PcgStats st_cg = cg.solve(Br, Xcg, 1e-6, 1000, "test");
    EXPECT_LE(st.relative_residual, 1e-6);
    if (k > 0) {
      sweeps += st.iterations;
      cg_sweeps += st_cg.iterations;
    }
    for (int c = 0; c < 3; ++c) {
      if (B.col(c).norm() == 0) {
        EXPECT_EQ(X.col(c).norm(), 0.0);
        continue;
      }
      const double res = (A * X.col(c) - B.col(c)).norm() / B.col(c).norm();
      EXPECT_LT(res, 2e-6) << label << " " << k << " " << c;
      EXPECT_LT((X.col(c) - exact.col(c)).cwiseAbs().maxCoeff(), 1e-4 * exact.col(c).cwiseAbs().maxCoeff());
    }
  }
  // Chebyshev needs a few more sweeps than CG, not many more.
  EXPECT_GT(sweeps, 0);
  EXPECT_LE(sweeps, 1.6 * cg_sweeps) << label;
}

}  // namespace

TEST(InternalPcg, ChebyshevAfterTheFirstSolveReachesTheTolerance) {
  // use_chebyshev in both layouts (3 neighbours: fixed width; 4: compressed) and both precisions.
  for (int neighbours : {3, 4}) {
    const Eigen::SparseMatrix<double> A = grid_matrix(40, neighbours, 0.3);
    check_chebyshev_sequence<detail::BlockPcg>(A, std::to_string(neighbours) + " double");
    check_chebyshev_sequence<detail::SingleBlockPcg>(A, std::to_string(neighbours) + " single");
  }
}

TEST(InternalPcg, ChebyshevWithASpectrumLearntFromOnePartStillConverges) {
  // Two uncoupled blocks: a well-conditioned one (a large shift) and a badly conditioned one
  // (a small shift). The first solve's right-hand side lives on the first block only, so the
  // spectrum learnt from it misses the second block's small eigenvalues; the later solves on
  // the second block converge slower than Chebyshev's rate promises, CG takes over, and the
  // tolerance is met all the same.
  const Eigen::SparseMatrix<double> A1 = grid_matrix(30, 3, 5.0), A2 = grid_matrix(30, 3, 0.01);
  const Eigen::Index m = A1.rows(), n = 2 * m;
  std::vector<Eigen::Triplet<double>> t;
  for (int part = 0; part < 2; ++part) {
    const Eigen::SparseMatrix<double>& Ap = part == 0 ? A1 : A2;
    for (int k = 0; k < Ap.outerSize(); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it(Ap, k); it; ++it)
        t.emplace_back(part * m + it.row(), part * m + it.col(), it.value());
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  // Double storage: the second block's κ (~10³) would make single precision's rounding of
  // the matrix itself visible in the true residual.
  detail::BlockPcg pcg(A);
  pcg.use_chebyshev();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(n), x = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 0; i < m; ++i) b(i) = std::sin(0.05 * i);
  EXPECT_GE(pcg.solve(b, x, 1e-6, 1000, "test").iterations, 8);  // CG: learns block 1's spectrum
  EXPECT_LT((A * x - b).norm(), 2e-6 * b.norm());
  for (int k = 0; k < 3; ++k) {
    for (Eigen::Index i = 0; i < n; ++i) b(i) = i < m ? 0.0 : 1.0 + k + std::sin(0.01 * i);
    const detail::PcgStats st = pcg.solve(b, x, 1e-6, 1000, "test");
    EXPECT_LE(st.relative_residual, 1e-6);
    EXPECT_LT((A * x - b).norm(), 2e-6 * b.norm()) << k;
  }
}

TEST(InternalPcg, ChebyshevOnGershgorinsIntervalFollowsTheDiagonal) {
  // A strongly diagonally dominant matrix whose diagonal set_diagonal replaces before every
  // solve (the v-step's): Chebyshev runs from the first solve on Gershgorin's interval,
  // recomputed for each diagonal, one column, compressed rows, to a tight tolerance.
  const Eigen::SparseMatrix<double> A = grid_matrix(30, 4, 0.0);
  const Eigen::Index n = A.rows();
  detail::BlockPcg pcg(A, /*reorder=*/false);
  pcg.use_chebyshev();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  for (int k = 0; k < 4; ++k) {
    Eigen::VectorXd d(n);
    for (Eigen::Index i = 0; i < n; ++i) d(i) = 500.0 * (1 + 0.3 * std::sin(0.2 * i + k));
    pcg.set_diagonal(d);
    Eigen::SparseMatrix<double> Ad = A;
    for (Eigen::Index i = 0; i < n; ++i) Ad.coeffRef(i, i) = d(i);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0 + k);
    const detail::PcgStats st = pcg.solve(b, x, 1e-10, 1000, "test");
    EXPECT_LE(st.iterations, 8) << k;  // κ ≈ 1.03: a few sweeps, as CG
    EXPECT_LT((Ad * x - b).norm(), 2e-10 * b.norm()) << k;
  }
  // The Jacobi guess x = D⁻¹b (the v-step's start, made by the normal filter's edge pass):
  // its residual is the off-diagonal part alone, so it needs fewer sweeps than the last
  // solution.
  Eigen::VectorXd d(n);
  for (Eigen::Index i = 0; i < n; ++i) d(i) = 5e4 * (1 + 0.3 * std::cos(0.1 * i));
  Eigen::SparseMatrix<double> Ad = A;
  for (Eigen::Index i = 0; i < n; ++i) Ad.coeffRef(i, i) = d(i);
  const Eigen::VectorXd bj = Eigen::VectorXd::LinSpaced(n, 1.0, 3.0);
  Eigen::VectorXd warm = x, jacobi = bj.cwiseQuotient(d);
  pcg.set_diagonal(d);
  const int from_jacobi = pcg.solve(bj, jacobi, 1e-10, 1000, "test").iterations;
  const int from_warm = pcg.solve(bj, warm, 1e-10, 1000, "test").iterations;
  EXPECT_LT(from_jacobi, from_warm);
  EXPECT_LE(from_jacobi, 2);
  EXPECT_LT((Ad * jacobi - bj).norm(), 2e-10 * bj.norm());
  EXPECT_LT((Ad * warm - bj).norm(), 2e-10 * bj.norm());
  // A diagonal matrix: Gershgorin's interval is one point.
  Eigen::SparseMatrix<double> D(n, n);
  for (Eigen::Index i = 0; i < n; ++i) D.insert(i, i) = 2.0 + (i % 3);
  D.makeCompressed();
  detail::BlockPcg diagonal(D, /*reorder=*/false);
  diagonal.use_chebyshev();
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 1.0);
  x.setZero();
  EXPECT_LE(diagonal.solve(b, x, 1e-10, 1000, "test").iterations, 2);
  EXPECT_LT((D * x - b).norm(), 2e-10 * b.norm());
}

namespace {

// Switches the wide rows (wide_rows.h) off for one scope.
struct ScalarRows {
  ScalarRows() { detail::set_wide_rows(false); }
  ~ScalarRows() { detail::set_wide_rows(true); }
};

// Three solves of the same system from the same start (the first of CG, learning the spectrum
// when Chebyshev is on; the next ones by Chebyshev): the iterates and sweeps of each.
template <class Pcg>
std::vector<std::pair<detail::RowMatrixX3, int>> three_solves(const Pcg& pcg, const detail::RowMatrixX3& B) {
  std::vector<std::pair<detail::RowMatrixX3, int>> out;
  detail::RowMatrixX3 X = detail::RowMatrixX3::Zero(B.rows(), 3);
  for (int k = 0; k < 3; ++k) {
    detail::RowMatrixX3 Bk = B * (1.0 + 0.5 * k);
    const int sweeps = pcg.solve(Bk, X, 1e-7, 2000, "test").iterations;
    out.emplace_back(X, sweeps);
  }
  return out;
}

}  // namespace

TEST(InternalPcg, WideRowsGiveTheScalarLoopsResultsBitForBit) {
  // Rows padded to four and four columns per instruction where the processor has AVX: the
  // same operations in the same order, so the same iterates to the last bit, in both layouts,
  // both precisions, CG and Chebyshev, on enough rows for several parallel blocks.
  if (!detail::wide_rows()) GTEST_SKIP() << "no AVX on this processor: only the scalar loops run";
  for (int neighbours : {3, 4}) {
    const Eigen::SparseMatrix<double> A = grid_matrix(190, neighbours, 0.3);
    const Eigen::Index n = A.rows();
    detail::RowMatrixX3 B(n, 3);
    for (Eigen::Index i = 0; i < n; ++i) B.row(i) << std::sin(0.1 * i), std::cos(0.07 * i), 1.0;
    for (bool single : {false, true})
      for (bool chebyshev : {false, true}) {
        auto run = [&] {
          if (single) {
            detail::SingleBlockPcg pcg(A);
            if (chebyshev) pcg.use_chebyshev();
            return three_solves(pcg, B);
          }
          detail::BlockPcg pcg(A);
          if (chebyshev) pcg.use_chebyshev();
          return three_solves(pcg, B);
        };
        const auto wide = run();
        std::vector<std::pair<detail::RowMatrixX3, int>> scalar;
        {
          const ScalarRows off;
          scalar = run();
        }
        for (size_t k = 0; k < wide.size(); ++k) {
          EXPECT_GT(wide[k].second, 0);
          EXPECT_EQ(wide[k].second, scalar[k].second) << neighbours << single << chebyshev << k;
          EXPECT_TRUE(test::bit_identical(Eigen::MatrixXd(wide[k].first), Eigen::MatrixXd(scalar[k].first)))
              << neighbours << single << chebyshev << k;
        }
      }
  }
}

TEST(InternalPcg, WideRowsGiveTheSameDenoisedMesh) {
  // A whole default denoise large enough for the N-step's Chebyshev sweeps, the polish and
  // the vertex update's CG: the same positions to the last bit with the wide rows off.
  if (!detail::wide_rows()) GTEST_SKIP() << "no AVX on this processor: only the scalar loops run";
  const Mesh clean = make_fandisk_like(50);
  ASSERT_GE(clean.F.rows(), 25000);
  NoiseOptions no;
  no.sigma = 0.3;
  no.seed = 4;
  const Eigen::MatrixXd V = add_noise(clean.V, clean.F, no);
  const DenoiseOptions o = resolve_preset("auto", V, clean.F).options;
  ASSERT_GT(o.normals.polish, 0);
  const DenoiseResult wide = denoise(V, clean.F, o);
  DenoiseResult scalar;
  {
    const ScalarRows off;
    scalar = denoise(V, clean.F, o);
  }
  EXPECT_FALSE(wide.normal_report.n_solver_iterations.empty());
  EXPECT_EQ(wide.normal_report.n_solver_iterations, scalar.normal_report.n_solver_iterations);
  EXPECT_TRUE(test::bit_identical(wide.V, scalar.V));
}
