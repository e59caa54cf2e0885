// Presets: the named parameter sets of denoising, and the defaults of inpainting and
// segmentation. This is the only place that names parameter values; docs/presets.md says
// how they were measured. What each parameter means, its unit and range: parameters.h.
//
// The options structs' own defaults are preset "cad" (DenoiseOptions{} == preset_options("cad"),
// test Presets.StructDefaultsAreTheCadPreset), so a library caller who sets nothing gets what
// the documentation lists as the default.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "msmesh/denoise.h"
#include "msmesh/normal_filter.h"
#include "msmesh/vertex_update.h"

namespace msmesh {

/// The named parameter sets: "cad" (CAD parts and scans of them: sharp creases kept) and
/// "smooth" (organic shapes: the edge field is effectively off). Besides these, "auto"
/// (resolve_preset) picks one of them from the mesh.
std::vector<std::string> preset_names();

/// The default of `msmesh denoise --preset` and of Python's denoise(preset=...): "auto".
const char* default_preset();

/// Options of a named preset. Throws InvalidInput for "auto" (it needs the mesh: use
/// resolve_preset) and for unknown names, listing the valid ones.
DenoiseOptions preset_options(const std::string& name);

/// What the "auto" rule saw on a mesh, and what it picked.
struct PresetChoice {
  std::string preset;         ///< "cad" or "smooth"
  double sharp_fraction = 0;  ///< fraction of edge length with dihedral > 30° after pre-smoothing
  double flat_fraction = 0;   ///< fraction of edge length with dihedral < 1° after pre-smoothing
  double noise_level = 0;     ///< mean angle (radians) between input and pre-smoothed normals
  std::string reason;         ///< one line: the figures and the thresholds that decided
};

/// The "auto" rule: picks "cad" or "smooth" for a mesh (#V by 3, #F by 3) from the mesh itself
/// (docs/presets.md, "--preset auto").
PresetChoice choose_preset(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

/// A preset name resolved for one mesh.
struct ResolvedPreset {
  std::string requested;   ///< what was asked for: "auto" or a preset name
  std::string preset;      ///< the preset used: "cad" or "smooth"
  bool automatic = false;  ///< requested == "auto"
  PresetChoice choice;     ///< what the auto rule saw (when automatic)
  DenoiseOptions options;  ///< the preset's options
  /// Why: "chosen automatically: ..." (auto) or "requested".
  std::string reason() const;
};

/// Resolves "auto" (from the mesh) or a preset name. Throws InvalidInput for unknown names.
ResolvedPreset resolve_preset(const std::string& name, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

/// Normal filter options of segmentation (SegmentOptions::normals): preset "cad"'s.
NormalFilterOptions segment_normal_options();

/// Normal filter and vertex update options of inpainting around the holes
/// (InpaintOptions::normals, ::vertices); measured with bench/inpaint (docs/inpainting.md).
NormalFilterOptions inpaint_normal_options();
VertexUpdateOptions inpaint_vertex_options();

}  // namespace msmesh
