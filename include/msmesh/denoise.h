// Denoising (paper §6.1): normal filtering followed by vertex updating, with presets.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "msmesh/normal_filter.h"
#include "msmesh/progress.h"
#include "msmesh/vertex_update.h"

namespace msmesh {

enum class DenoiseMethod {
  NMSTV,      ///< the paper: nonconvex MSTV (Algorithm 1) + Algorithm 2
  MSTV,       ///< ref. [11]: the same loop with all IRLA weights 1
  Bilateral,  ///< bilateral normal filtering (Zheng et al. 2011) + its classic vertex update
};

/// Parameters of bilateral normal filtering (Zheng et al. 2011) and its vertex update.
struct BilateralOptions {
  int normal_iterations = 20;  ///< normal filtering passes (≥ 1)
  double sigma_r = 0.35;       ///< range (normal difference) Gaussian width, in (0, 2]
  double sigma_s = 0.0;        ///< spatial width, mean-edge units; 0 = mean distance between adjacent face centres
  int vertex_iterations = 20;  ///< vertex update passes (≥ 1)
  void validate() const;
};

struct DenoiseOptions {
  DenoiseMethod method = DenoiseMethod::NMSTV;
  NormalFilterOptions normals;
  VertexUpdateOptions vertices;
  BilateralOptions bilateral;
  void validate() const;
};

/// Preset names: "cad" (CAD parts and scans of them: sharp creases kept), "smooth" (organic
/// shapes: the edge field is effectively off). "auto" is resolved per mesh by choose_preset().
/// Values and how they were measured: docs/presets.md.
std::vector<std::string> preset_names();

/// Options of a named preset ("cad" or "smooth"); throws InvalidInput for other names.
DenoiseOptions preset_options(const std::string& name);

/// What choose_preset() saw.
struct PresetChoice {
  std::string preset;          ///< "cad" or "smooth"
  double sharp_fraction = 0;   ///< fraction of edge length with dihedral > 30° after pre-smoothing
  double flat_fraction = 0;    ///< fraction of edge length with dihedral < 1° after pre-smoothing
  double noise_level = 0;      ///< mean angle (radians) between input and pre-smoothed normals
};

/// Picks "cad" or "smooth" for a mesh from the mesh itself (see docs/presets.md).
PresetChoice choose_preset(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

struct DenoiseResult {
  Eigen::MatrixXd V;        ///< #V by 3 denoised positions (F unchanged)
  Eigen::MatrixXd normals;  ///< #F by 3 filtered normals (the targets of the vertex update)
  Eigen::VectorXd v;        ///< #E edge field (NMSTV/MSTV; empty for bilateral)
  NormalFilterResult normal_report;   ///< iterations and histories (NMSTV/MSTV)
  VertexUpdateResult vertex_report;   ///< iterations and histories
  double seconds_normals = 0, seconds_vertices = 0;
};

/// A lower estimate of the peak memory (bytes) denoise() needs for a mesh of this size,
/// measured on meshes of 4·10^4 and 2.6·10^5 faces (docs/robustness.md). denoise() refuses to start
/// (InvalidInput) when it exceeds the available memory (msmesh/memory.h).
double denoise_memory_estimate(Eigen::Index num_vertices, Eigen::Index num_faces, const DenoiseOptions& options = {});

/// Denoises (V, F): #V by 3, #F by 3. Results do not depend on the mesh's scale, position or
/// orientation. Throws InvalidInput, SolverError or Cancelled.
DenoiseResult denoise(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const DenoiseOptions& options = {},
                      const ProgressCallback& progress = {});

/// Bilateral normal filtering (Zheng et al. 2011): #F by 3 filtered normals.
Eigen::MatrixXd bilateral_filter_normals(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                         const BilateralOptions& options, const ProgressCallback& progress = {});

/// The classic iterative vertex update (Sun et al. 2007; Zheng et al. 2011): moves each vertex
/// towards the planes of its faces' target normals N (#F by 3).
Eigen::MatrixXd classic_vertex_update(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& N,
                                      int iterations, const ProgressCallback& progress = {});

}  // namespace msmesh
