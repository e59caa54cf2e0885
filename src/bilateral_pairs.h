// Internal: bilateral normal filtering with its weights computed once per pair of faces, for
// the shape rule of `--preset auto` (src/presets.cpp), which runs 15 passes on every mesh.
#pragma once
#include <Eigen/Core>

namespace msmesh::detail {

/// The same filter as bilateral_filter_normals (src/bilateral.cpp) with sigma_s 0 (the mean
/// distance between adjacent face centres), to single precision (~1e-7): the spatial weight of
/// each pair of neighbouring faces is computed once rather than in every pass, and the range
/// weight once per pair and pass rather than once from each side (a third of the exponentials in
/// 15 passes), as a float by a vectorised exponential. The same bits at any thread count.
/// #F by 3 unit normals.
Eigen::MatrixXd bilateral_normals_by_pairs(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, int passes,
                                           double sigma_r);

}  // namespace msmesh::detail
