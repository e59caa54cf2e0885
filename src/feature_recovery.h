// Internal: feature recovery of inpainting (inpaint.h, docs/inpainting.md). The paper's §6.2
// (NMSTV normal filtering and vertex updating with large fidelity outside the filled region,
// almost none inside, β/10 inside) plus three steps beyond it: the piecewise-smooth completion
// of the normals, the orthogonal vertex placement and the crease-aligning edge flips.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "msmesh/inpaint.h"
#include "msmesh/topology.h"

namespace msmesh::detail {

// A filled hole as the feature recovery sees it.
struct FilledHole {
  int index = 0;  // into InpaintResult::holes / reports
  const std::vector<int>* loop = nullptr;
  int first_face = 0, face_count = 0, first_vertex = 0, vertex_count = 0;
  double jump_angle = 60;  // degrees: normals further apart inside form the edge set
};

// Does a crease of the input run into this hole? Looks at the interior edges of the input at
// the hole's boundary vertices: at least two sharper than feature_angle (a crease enters and
// leaves, or creases meet at a corner inside), and the others mostly flat (median below
// smooth_angle), i.e. the sharp edges separate smooth patches rather than being the
// roughness of an organic surface. Returns a short description either way.
// Also returns in `weakest_crease` the smallest dihedral angle (degrees) above 30° there: the
// gentlest crease that runs into the hole (180 when there is none).
bool crease_enters(const std::vector<int>& loop, const Topology& topo, const Eigen::VectorXd& dihedral,
                   const std::vector<std::vector<int>>& vertex_edges, const InpaintOptions& o, std::string& why,
                   double& weakest_crease);

// Feature recovery on the filled mesh (V1, F1), in place: the paper's §6.2 weighting on a
// submesh made of the new faces of the holes in `holes` and `context_rings` rings of faces
// around them. Everything outside those holes is pinned.
void recover_features(Eigen::MatrixXd& V1, Eigen::MatrixXi& F1, Eigen::Index nv0, Eigen::Index nf0,
                      const std::vector<FilledHole>& holes, const InpaintOptions& o, const ProgressCallback& progress,
                      InpaintResult& res);

}  // namespace msmesh::detail
