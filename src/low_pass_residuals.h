// Internal: each vertex's distance along the normal from a low-pass copy of the mesh, the
// measurement behind the noise estimate (noise_estimate.h) and the spike removal (despike.h).
#pragma once
#include <Eigen/Core>
#include <vector>

#include "msmesh/despike.h"

namespace msmesh::detail {

/// The low-pass copy (taubin_smooth, kLowPassIterations iterations), its vertex normals and the
/// residuals (V − S)·N per vertex. `used` marks the vertices some face refers to.
struct LowPassResiduals {
  Eigen::MatrixXd smooth;    ///< #V by 3 low-pass positions
  Eigen::MatrixXd normals;   ///< #V by 3 vertex normals of the low-pass copy
  Eigen::VectorXd residual;  ///< #V signed distances along the normals, in the mesh's units
  Eigen::VectorXd across;    ///< #V lengths of the rest of V − S (across the normals), the same units
  /// #V: the same after the first kLightPassIterations iterations only (along that copy's
  /// normals). White noise leaves a fixed fraction of itself in both; the shape's detail and
  /// creases grow with the iterations (noise_estimate.cpp).
  Eigen::VectorXd light_residual;
  std::vector<bool> used;  ///< #V: referenced by a face
  double mean_edge = 0;    ///< mean edge length of the low-pass copy
};

constexpr int kLowPassIterations = 10;
constexpr int kLightPassIterations = 3;
constexpr double kMadToSigma = 1.4826;  // σ of a Gaussian / its median absolute deviation

LowPassResiduals low_pass_residuals(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

/// despike() on residuals already computed from V (low_pass_residuals(V, F)): the same result,
/// without a second low pass when the noise estimate has just measured the same mesh.
DespikeResult despike_from(const Eigen::MatrixXd& V, const LowPassResiduals& lp, double threshold);

/// The median of x (the upper one for an even count); 0 for none.
double median_of(std::vector<double> x);

/// The median of x and its robust standard deviation, kMadToSigma × the median absolute
/// deviation from it (the noise estimate's and the spike removal's measure).
struct RobustSpread {
  double median = 0, sigma = 0;
};
RobustSpread robust_spread(std::vector<double> x);

}  // namespace msmesh::detail
