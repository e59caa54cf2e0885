// Internal: the mesh made of some faces of a mesh, its vertices renumbered in order of first
// use (denoising components one by one, the feature recovery's working region).
#pragma once
#include <Eigen/Core>
#include <vector>

namespace msmesh::detail {

struct SubMesh {
  Eigen::MatrixXd V;        ///< #global by 3
  Eigen::MatrixXi F;        ///< #faces by 3, indices into V
  std::vector<int> global;  ///< the vertex of the whole mesh of each row of V
};

/// The faces `faces` (indices into F) of (V, F). `local` is scratch of #V entries, all -1 on
/// entry and again on return (so that many small sub-meshes cost their own size only).
template <class Index>
SubMesh sub_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::vector<Index>& faces,
                 std::vector<int>& local) {
  SubMesh s;
  s.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const int g = F(faces[i], k);
      if (local[g] < 0) {
        local[g] = static_cast<int>(s.global.size());
        s.global.push_back(g);
      }
      s.F(static_cast<Eigen::Index>(i), k) = local[g];
    }
  s.V.resize(static_cast<Eigen::Index>(s.global.size()), 3);
  for (std::size_t i = 0; i < s.global.size(); ++i) {
    s.V.row(static_cast<Eigen::Index>(i)) = V.row(s.global[i]);
    local[s.global[i]] = -1;
  }
  return s;
}

}  // namespace msmesh::detail
