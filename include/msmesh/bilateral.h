// The bilateral normal filtering baseline (Zheng et al. 2011) and the classic iterative vertex
// update (Sun et al. 2007), for comparison with NMSTV (`msmesh denoise --method bilateral`).
#pragma once
#include <Eigen/Core>

#include "msmesh/progress.h"

namespace msmesh {

/// Parameters of bilateral normal filtering (Zheng et al. 2011) and its vertex update; ranges
/// and help in bilateral_parameters() (parameters.h).
struct BilateralOptions {
  int normal_iterations = 20;  ///< normal filtering passes (≥ 1)
  double sigma_r = 0.35;       ///< range (normal difference) Gaussian width, in (0, 2]
  double sigma_s = 0.0;        ///< spatial width, mean-edge units; 0 = mean distance between adjacent face centres
  int vertex_iterations = 20;  ///< vertex update passes (≥ 1)
  /// Throws InvalidInput naming the parameter, its value and the valid range.
  void validate() const;
};

/// Bilateral normal filtering (Zheng et al. 2011): #F by 3 filtered normals.
Eigen::MatrixXd bilateral_filter_normals(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                         const BilateralOptions& options, const ProgressCallback& progress = {});

/// The classic iterative vertex update (Sun et al. 2007; Zheng et al. 2011): moves each vertex
/// towards the planes of its faces' target normals N (#F by 3).
Eigen::MatrixXd classic_vertex_update(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& N,
                                      int iterations, const ProgressCallback& progress = {});

}  // namespace msmesh
