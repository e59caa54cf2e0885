// Denoising (paper §6.1): normal filtering followed by vertex updating. The named parameter
// sets (presets, and "auto", chosen from the mesh) are in presets.h.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "msmesh/bilateral.h"
#include "msmesh/normal_filter.h"
#include "msmesh/progress.h"
#include "msmesh/vertex_update.h"

namespace msmesh {

enum class DenoiseMethod {
  NMSTV,      ///< the paper: nonconvex MSTV (Algorithm 1) + Algorithm 2
  MSTV,       ///< ref. [11]: the same loop with all IRLA weights 1
  Bilateral,  ///< bilateral normal filtering (Zheng et al. 2011) + its classic vertex update
};

/// Options of denoise(). The defaults are those of preset "cad" (presets.h); ranges and help of
/// every parameter in denoise_parameters() (parameters.h).
struct DenoiseOptions {
  DenoiseMethod method = DenoiseMethod::NMSTV;
  NormalFilterOptions normals;
  VertexUpdateOptions vertices;
  BilateralOptions bilateral;
  /// Robust first normals (NMSTV/MSTV): Taubin λ|μ passes (taubin.h) on a copy of the vertices
  /// before the input normals N⁰ are taken from it; the vertex update still starts from, and
  /// stays close to, the input. 0: N⁰ are the input's face normals, as in the paper. The
  /// noise-adaptive preset "auto" sets it from the noise estimate (presets.h).
  int prefilter_iterations = 0;
  /// Impulsive outliers (NMSTV/MSTV): when > 0, vertices farther than this many robust σ from a
  /// low-pass copy are first moved onto it (despike.h), and everything after works on that mesh
  /// (the first normals and the closeness of the vertex update). 0: off, as in the paper. Preset
  /// "auto" turns it on when the noise estimate finds many outliers (presets.h).
  double despike_threshold = 0;
  /// Planar regions (NMSTV/MSTV): after the normal filter, every connected region of at least
  /// this many faces whose filtered normals agree (neighbours within 1°, all within 4° of their
  /// mean) takes the normal of the least-squares plane through its input vertices, as the
  /// vertex update's target: the noise averaged over the whole flat part rather than over the
  /// plateaus Algorithm 1 leaves in it (docs/presets.md, "Planar regions"). 0: off, as the paper
  /// (preset "paper").
  int plane_min_faces = 100;
  /// Jet-fitted targets (NMSTV/MSTV): when > 0, after the vertex update each face on a curved
  /// part (not across a crease, not inside a flat plateau) gets as its target the normal of a
  /// quadric fitted to the updated vertices within this many rings of it, and the vertex update
  /// runs again from there: second-order targets where Algorithm 1's piecewise constant normals
  /// leave facets (docs/presets.md, "Jet-fitted targets"). 0: off, as the paper (preset
  /// "paper"); "auto" turns it off where it counts detail as correlated noise.
  int jet_rings = 3;
  /// Unreachable targets (NMSTV/MSTV), degrees: when > 0, a face whose normal after the vertex
  /// update lies farther than this from its target loses that target, and the vertex update
  /// runs again (with the jet-fitted targets, if any): the face then follows its neighbours. Its
  /// neighbours held it on one side of a crease while Algorithm 1 gave it the other side's normal
  /// (docs/presets.md, "Unreachable targets"). 0: off, as the paper (preset "paper"); preset
  /// "smooth" 0; "auto" 10 for the class cad, off where it counts detail as correlated noise.
  double unreachable_angle = 10;
  /// Small components (NMSTV/MSTV): the vertex-connected components of fewer faces than this
  /// are kept as they are, and the rest is denoised as a mesh of its own. On a part of a few
  /// dozen triangles every face is a feature and the noise cannot be told from the shape (a
  /// cube of 12 triangles beside a sphere came out with its corners moved by a third of its
  /// side; docs/presets.md, "Small components"). 0: every component denoised, as the paper.
  int min_component_faces = 40;
  void validate() const;
};

struct DenoiseResult {
  Eigen::MatrixXd V;                ///< #V by 3 denoised positions (F unchanged)
  Eigen::MatrixXd normals;          ///< #F by 3 filtered normals (the targets of the vertex update)
  Eigen::VectorXd v;                ///< #E edge field, v[e] belongs to edges.row(e) (NMSTV/MSTV; empty for bilateral)
  Eigen::MatrixXi edges;            ///< #E by 2 vertex indices of the edges of v (empty for bilateral)
  NormalFilterStats normal_report;  ///< iterations and histories (NMSTV/MSTV)
  VertexUpdateStats vertex_report;  ///< iterations and histories
  double seconds_normals = 0, seconds_vertices = 0;
  Eigen::Index despiked_vertices = 0;  ///< vertices moved by DenoiseOptions::despike_threshold
  Eigen::Index planar_regions = 0;     ///< regions snapped to a plane (DenoiseOptions::plane_min_faces)
  Eigen::Index planar_faces = 0;       ///< faces in them
  Eigen::Index jet_faces = 0;          ///< faces given jet-fitted targets (DenoiseOptions::jet_rings)
  Eigen::Index unreachable_faces = 0;  ///< faces whose targets were dropped (DenoiseOptions::unreachable_angle)
  Eigen::Index kept_components = 0;    ///< components kept as they are (DenoiseOptions::min_component_faces)
  Eigen::Index kept_faces = 0;         ///< faces in them
};

/// A lower estimate of the peak memory (bytes) denoise() needs for a mesh of this size,
/// measured on meshes of 4·10^4 and 2.6·10^5 faces (docs/robustness.md). denoise() refuses to start
/// (InvalidInput) when it exceeds the available memory (msmesh/memory.h).
double denoise_memory_estimate(Eigen::Index num_vertices, Eigen::Index num_faces, const DenoiseOptions& options = {});

/// Denoises (V, F): #V by 3, #F by 3. Results do not depend on the mesh's scale, position or
/// orientation. Throws InvalidInput, SolverError or Cancelled.
DenoiseResult denoise(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const DenoiseOptions& options = {},
                      const ProgressCallback& progress = {});

}  // namespace msmesh
