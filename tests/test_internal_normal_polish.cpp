// The polish of the filtered normals (src/normal_polish.h): constant normals stay (∇ of a
// constant is 0), noise on flat parts shrinks, creases are not averaged across, and an edge
// field of 0 switches it off.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <random>

#include "msmesh/geometry.h"
#include "msmesh/prepared_mesh.h"
#include "msmesh/shapes.h"
#include "normal_polish.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

// Unit normals N plus Gaussian noise of `sigma` per coordinate, renormalised (seeded).
Eigen::MatrixXd jitter(const Eigen::MatrixXd& N, double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, sigma);
  Eigen::MatrixXd out = N;
  for (Eigen::Index f = 0; f < N.rows(); ++f) {
    for (int c = 0; c < 3; ++c) out(f, c) += g(rng);
    out.row(f).normalize();
  }
  return out;
}

double mean_angle(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  double s = 0;
  for (Eigen::Index f = 0; f < A.rows(); ++f) s += std::acos(std::clamp(A.row(f).dot(B.row(f)), -1.0, 1.0));
  return s / static_cast<double>(A.rows());
}

}  // namespace

TEST(InternalNormalPolish, ConstantNormalsStay) {
  const Mesh g = test::grid(10);
  const PreparedMesh mesh(g.V, g.F);
  const Eigen::MatrixXd N = face_normals(g.V, g.F);
  const Eigen::VectorXd v = Eigen::VectorXd::Ones(mesh.num_edges());
  const Eigen::MatrixXd P = detail::polish_normals(mesh, N, v, 3.0, 0.3);
  EXPECT_LT((P - N).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(InternalNormalPolish, NoiseOnAFlatPartShrinksAndMoreWeightSmoothsMore) {
  const Mesh g = test::grid(16);
  const PreparedMesh mesh(g.V, g.F);
  const Eigen::MatrixXd N = face_normals(g.V, g.F);
  const Eigen::MatrixXd noisy = jitter(N, 0.05, 1);
  const Eigen::VectorXd v = Eigen::VectorXd::Ones(mesh.num_edges());
  const double before = mean_angle(noisy, N);
  const double light = mean_angle(detail::polish_normals(mesh, noisy, v, 1.0, 0.3), N);
  const double strong = mean_angle(detail::polish_normals(mesh, noisy, v, 3.0, 0.3), N);
  EXPECT_LT(light, 0.7 * before);
  EXPECT_LT(strong, light);
}

TEST(InternalNormalPolish, CreasesAreNotAveragedAcross) {
  // A cube's faces meet at 90°: ‖N_i − N_j‖ = √2 across an edge, a range weight of e^{−11} at
  // σ 0.3; every face keeps its side's normal.
  const Mesh c = make_cube(4);
  const PreparedMesh mesh(c.V, c.F);
  const Eigen::MatrixXd N = face_normals(c.V, c.F);
  const Eigen::VectorXd v = Eigen::VectorXd::Ones(mesh.num_edges());
  const Eigen::MatrixXd P = detail::polish_normals(mesh, N, v, 3.0, 0.3);
  EXPECT_LT((P - N).cwiseAbs().maxCoeff(), 1e-3);
  // With a range far wider than the crease, the corners' faces are pulled off their sides.
  const Eigen::MatrixXd wide = detail::polish_normals(mesh, N, v, 3.0, 10.0);
  EXPECT_GT((wide - N).cwiseAbs().maxCoeff(), 0.1);
}

TEST(InternalNormalPolish, AnEdgeFieldOfZeroSwitchesItOff) {
  const Mesh g = test::grid(8);
  const PreparedMesh mesh(g.V, g.F);
  const Eigen::MatrixXd noisy = jitter(face_normals(g.V, g.F), 0.05, 2);
  const Eigen::VectorXd v = Eigen::VectorXd::Zero(mesh.num_edges());
  EXPECT_LT((detail::polish_normals(mesh, noisy, v, 3.0, 0.3) - noisy).cwiseAbs().maxCoeff(), 1e-12);
}
