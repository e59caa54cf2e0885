// The hole puncher, for tests and benchmarks of inpainting (as noise.h is for denoising):
// removes seeded geodesic disks of faces from a mesh.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace msmesh {

struct PunchResult {
  Eigen::MatrixXd V;           ///< #V' by 3 the remaining vertices (unreferenced ones removed)
  Eigen::MatrixXi F;           ///< #F' by 3 the remaining faces, in their input order, re-indexed
  Eigen::VectorXi vertex_map;  ///< #V' : input row of each output vertex
  Eigen::VectorXi old_to_new;  ///< #V  : output row of each input vertex, -1 when removed
  Eigen::VectorXi face_map;    ///< #F' : input face of each output face
  std::vector<int> centers;    ///< input vertex at the centre of each hole punched
  int punched = 0;             ///< holes made (fewer than asked when no room was left)
};

/// Punches `count` holes into (V, F): geodesic disks (Dijkstra along edges) of `radius` mean
/// edge lengths around random centre vertices (seeded, deterministic). Every face touching a
/// disk vertex is removed. Disks are grown where needed so that each hole's boundary is a
/// simple loop, and kept apart from each other and from existing boundaries. With
/// `on_features`, centres are vertices on sharp edges (dihedral angle > 60°), corners included.
/// Throws InvalidInput for bad arguments.
PunchResult punch_holes(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, int count, double radius,
                        std::uint64_t seed, bool on_features = false);

}  // namespace msmesh
