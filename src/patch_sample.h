// Internal: a sample of a large mesh made of patches spread over it, for the statistics that
// `--preset auto` measures (the noise estimate and the shape rule). Their filters reach a few
// rings, so only the patches' cores (far enough from where a patch was cut out) are measured.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "sub_mesh.h"

namespace msmesh::detail {

struct PatchSample {
  SubMesh mesh;                   ///< the patches' faces, as one mesh (vertices renumbered)
  std::vector<char> core_face;    ///< per face of `mesh`: at least `margin` rings from a cut
  std::vector<char> core_vertex;  ///< per vertex of `mesh`: a corner of a core face
  Eigen::Index patches = 0;       ///< the number of patches grown
  Eigen::Index core_faces = 0;    ///< how many faces are core
};

/// Grows `patches` patches of about `patch_faces` faces each (breadth first over faces sharing a
/// vertex) from seed faces spread evenly over the face order of (V, F), and marks as core the
/// faces at least `margin` vertex rings away from every face of the mesh outside the sample.
/// Deterministic. A mesh smaller than patches × patch_faces comes back whole, all core.
PatchSample sample_patches(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, Eigen::Index patches,
                           Eigen::Index patch_faces, int margin);

}  // namespace msmesh::detail
