// Error metrics of the denoising literature (DESIGN.md §"Measuring results").
#pragma once
#include <Eigen/Core>
#include <memory>
#include <vector>

namespace msmesh {

/// Face-normal errors of a result against a ground truth with the same connectivity.
struct NormalErrors {
  double msae = 0;            ///< mean over faces of θ² (radians²); the paper prints msae × 1e3
  double mean_angle_deg = 0;  ///< mean over faces of θ in degrees
  Eigen::Index flipped = 0;   ///< faces with θ > 90°
  Eigen::VectorXd angle_rad;  ///< #F per-face θ
  /// Faces folded in the truth: the truth's normal points against the area-weighted normal of
  /// the faces around it (a sliver turned over, a zig-zag: no smooth surface has them, and a
  /// denoiser that unfolds one counts as flipping it). truth_folded_faces() says which.
  Eigen::Index truth_folded = 0;
  Eigen::Index flipped_outside_folds = 0;  ///< flipped faces that are not folded in the truth
  double msae_outside_folds = 0;           ///< mean θ² over the faces not folded in the truth
};

/// #F flags: the faces of (V, F) whose normal points against both the area-weighted normals of
/// their edge neighbours (n_f · Σ A_g n_g < 0) and those of every face sharing a vertex with
/// them (edge neighbours counted twice): turned over against what lies around them, not only
/// across one edge, as a face at a sharp crease or a corner of a CAD part can be. A face
/// without neighbours or with zero area is not folded; on a tetrahedron every face is. Across a
/// non-manifold edge only its first two faces count as edge neighbours (Topology::edge_faces).
/// Throws InvalidInput for an invalid mesh.
std::vector<char> truth_folded_faces(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

/// θ per face is the angle between the unit normals of face f in (V, F) and (V_truth, F_truth);
/// a face with zero area has no normal: θ = π/2 against a proper face (not counted as
/// flipped), 0 when both are degenerate. Means are unweighted over faces, as in the papers.
/// Throws InvalidInput when F and F_truth differ (normal metrics need equal connectivity):
/// different #F, or a face made of other vertices. A face listed with the opposite
/// orientation is the same face, and shows as flipped. The figures outside the truth's folds
/// leave out the faces truth_folded_faces(V_truth, F_truth) marks.
NormalErrors normal_errors(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& V_truth,
                           const Eigen::MatrixXi& F_truth);

/// Point-to-surface distances (true point-to-triangle distance through an AABB tree, built once
/// in the constructor; queries run in parallel). Zero-area faces are skipped unless all are,
/// in which case each face counts as its longest edge. Throws InvalidInput for an invalid
/// mesh, a mesh without faces, or non-finite query points.
class SurfaceDistance {
 public:
  SurfaceDistance(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);
  ~SurfaceDistance();
  SurfaceDistance(SurfaceDistance&&) noexcept;
  SurfaceDistance& operator=(SurfaceDistance&&) noexcept;
  /// #P distances from the rows of P (#P by 3) to the surface.
  Eigen::VectorXd distances(const Eigen::MatrixXd& P) const;
  /// #P by 3 closest points on the surface.
  Eigen::MatrixXd closest_points(const Eigen::MatrixXd& P) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Vertex-to-truth-surface distances, relative to the truth's bounding-box diagonal (of its
/// referenced vertices). Only the result's referenced vertices count. The paper prints × 1e3.
struct DistanceErrors {
  double mean = 0, rms = 0, max = 0;
  double area_weighted_rms = 0;  ///< RMS weighted by the result's vertex areas (Sun et al. 2007 E_v)
};

/// Throws InvalidInput when the result has no faces or the truth has a zero-size bounding box.
DistanceErrors vertex_distance_errors(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                      const Eigen::MatrixXd& V_truth, const Eigen::MatrixXi& F_truth);

/// Everything `msmesh eval` reports. Normal errors only when connectivity matches (same #F and
/// the same vertices in every face); `normals` stays zero otherwise.
struct Evaluation {
  bool same_connectivity = false;
  NormalErrors normals;
  DistanceErrors distances;
};

Evaluation evaluate(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& V_truth,
                    const Eigen::MatrixXi& F_truth);

// ---------------------------------------------------------------------------------------
// Inpainting: error figures of a filled mesh against a ground truth
// ---------------------------------------------------------------------------------------

/// Distances of the filled region to the ground truth, relative to the truth's bounding-box
/// diagonal. Two sets of points count, with t = 0.1 mean edge length of the input:
///  - truth vertices farther than t from every input vertex (the missing surface): their
///    distance to the result's surface;
///  - result vertices farther than t from every input vertex (the new surface): their
///    distance to the truth's surface.
struct InpaintErrors {
  Eigen::Index points = 0;  ///< number of distances measured (both sets)
  double max = 0, mean = 0, rms = 0;
  Eigen::Index new_faces = 0;
  /// Mean angle (degrees) between each new face's normal and the normal of the truth face
  /// closest to its barycentre; 0 when there are no new faces.
  double mean_normal_error_deg = 0;
};

/// new_faces: #F_result flags of the faces the inpainting added (empty: the faces beyond the
/// input's #F). Throws InvalidInput for invalid meshes or a truth without faces.
InpaintErrors inpaint_errors(const Eigen::MatrixXd& V_input, const Eigen::MatrixXi& F_input,
                             const Eigen::MatrixXd& V_result, const Eigen::MatrixXi& F_result,
                             const std::vector<bool>& new_faces, const Eigen::MatrixXd& V_truth,
                             const Eigen::MatrixXi& F_truth);

}  // namespace msmesh
