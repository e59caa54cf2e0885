// Internal: the two measurements of `--preset auto` restricted to some vertices or faces (the
// cores of a patch sample of a large mesh, patch_sample.h). nullptr measures everything, as
// the public estimate_noise and choose_preset do.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "low_pass_residuals.h"
#include "msmesh/noise_estimate.h"
#include "msmesh/presets.h"

namespace msmesh::detail {

/// estimate_noise over the vertices with measured[i] != 0 (and used by a face).
NoiseEstimate estimate_noise_masked(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                    const std::vector<char>* measured_vertices);

/// The same on the residuals of a low pass already computed (low_pass_residuals(V, F)).
NoiseEstimate estimate_noise_from(const LowPassResiduals& lp, const std::vector<char>* measured_vertices);

/// choose_preset over the interior edges between two faces with measured[f] != 0.
PresetChoice choose_preset_masked(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                  const std::vector<char>* measured_faces);

}  // namespace msmesh::detail
