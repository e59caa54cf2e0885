// Internal: the polish of the filtered normals (NormalFilterOptions::polish): one implicit step
// of a joint bilateral filter guided by the filtered normals N themselves and masked by the
// edge field v,
//   min_X Σ_f ‖X_f − N_f‖² + λ Σ_e v_e² exp(−‖N_i − N_j‖² / (2σ²)) len(e) ‖X_i − X_j‖²,
// over the interior edges e between faces i and j (len in mean edge lengths), then every row
// normalised. It flattens the noise Algorithm 1's fidelity term leaves in flat and smoothly
// curved regions and leaves creases (large ‖N_i − N_j‖, small v) alone (docs/presets.md,
// "The polish").
#pragma once
#include <Eigen/Core>

#include "msmesh/prepared_mesh.h"

namespace msmesh::detail {

/// N: #F by 3 unit normals; v: #E edge field on mesh.topology() (clipped to [0, 1] here);
/// weight λ > 0, range σ > 0. Solved in mesh.face_order(). Returns the polished unit normals.
Eigen::MatrixXd polish_normals(const PreparedMesh& mesh, const Eigen::MatrixXd& N, const Eigen::VectorXd& v,
                               double weight, double range);

}  // namespace msmesh::detail
