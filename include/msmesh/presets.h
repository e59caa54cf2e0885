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
#include "msmesh/noise_estimate.h"
#include "msmesh/normal_filter.h"
#include "msmesh/vertex_update.h"

namespace msmesh {

/// The named parameter sets: "cad" (CAD parts and scans of them: sharp creases kept),
/// "smooth" (organic shapes: the edge field is effectively off) and "paper" (Algorithms 1 and 2
/// as published, with the paper's §5.1 settings). Besides these, "auto" (resolve_preset, the
/// default) sets the parameters from the mesh's own noise and shape.
std::vector<std::string> preset_names();

/// The default of `msmesh denoise --preset` and of Python's denoise(preset=...): "auto".
const char* default_preset();

/// Options of a named preset. Throws InvalidInput for "auto" (it needs the mesh: use
/// resolve_preset) and for unknown names, listing the valid ones.
DenoiseOptions preset_options(const std::string& name);

/// The noise-adaptive options of "auto" for a shape class ("cad" or "smooth") and a noise level
/// σ (mean edge lengths, as NoiseEstimate::sigma_rms): the class's preset with α and the
/// pre-filter following σ (docs/presets.md, "--preset auto"). `detail` (NoiseEstimate::detail,
/// the shape's own fine detail) raises the closeness weight of the class smooth, so that the
/// vertex update keeps it. `alpha_max` caps α (0: the class's cap, 10 for cad and 5 for smooth;
/// resolve_preset gives 5 for scan-like cad meshes). Throws InvalidInput for an unknown class or a
/// negative σ, detail or cap.
DenoiseOptions adaptive_options(const std::string& shape_class, double sigma, double detail = 0, double alpha_max = 0);

/// What the shape rule saw on a mesh, and the class it picked.
struct PresetChoice {
  std::string preset;         ///< "cad" or "smooth"
  double sharp_fraction = 0;  ///< fraction of edge length with dihedral > 30° after pre-smoothing
  /// The part of sharp_fraction on lines of creases at least 40 mean edge lengths long: what the
  /// class rule counts (noise and fine detail make short scattered creases).
  double crease_line_fraction = 0;
  /// The part of crease_line_fraction steeper than 60° (a part's edges; an organic shape's long
  /// creases are mostly gentler): cad when at least 0.012 and 80 % of crease_line_fraction.
  double steep_line_fraction = 0;
  double flat_fraction = 0;  ///< fraction of edge length with dihedral < 1° after pre-smoothing
  double noise_level = 0;    ///< mean angle (radians) between input and pre-smoothed normals
  std::string reason;        ///< one line: the figures and the thresholds that decided
};

/// The shape rule: picks the class "cad" or "smooth" for a mesh (#V by 3, #F by 3) from the
/// mesh itself (docs/presets.md, "--preset auto"). resolve_preset("auto") applies it to the
/// pre-filtered mesh, so that heavy noise does not look like creases.
PresetChoice choose_preset(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

/// The range of resolve_preset's `strength`.
constexpr double kMinStrength = 0.1, kMaxStrength = 10.0;

/// A preset name resolved for one mesh.
struct ResolvedPreset {
  std::string requested;   ///< what was asked for: "auto" or a preset name
  std::string preset;      ///< the preset whose values were used: "cad", "smooth" or "paper"
  bool automatic = false;  ///< requested == "auto"
  PresetChoice choice;     ///< what the shape rule saw (when automatic)
  NoiseEstimate noise;     ///< the noise estimate of the input (when automatic)
  /// Impulsive noise (auto): when the input's outlier fraction called for spike removal
  /// (options.despike_threshold > 0), the estimate of the despiked mesh, from which the rules took
  /// σ; the fraction of vertices the spike removal moved.
  bool despiked = false;
  NoiseEstimate noise_despiked;
  double despiked_fraction = 0;
  double strength = 1.0;  ///< how much to remove: 1 the default, larger smooths more
  /// The noise level the rules used: strength × σ_rms of the estimate (despiked ? noise_despiked
  /// : noise), for the class smooth without its detail d: strength × √(σ_rms² − d²), d² =
  /// max(0, detail² − (0.5 sigma_noise)²) of the same estimate; for class cad with few creases
  /// (not despiked) with its detail counted as noise: strength × √(σ_rms² + 8 w detail²),
  /// w = detail_as_noise; and for the class smooth divided by detail_ease.
  double sigma = 0;
  /// Class smooth, not despiked, noise alone at least 0.1 (auto): 1 + 2 d' / max(sigma_noise,
  /// 0.15), d'² = max(0, detail² − (0.3 sigma_noise)²): detail that stands out of the noise
  /// eases every rule, σ divided by it (docs/presets.md, "Detail that stands out of the noise").
  /// 1 otherwise.
  double detail_ease = 1;
  /// Class cad by its flat areas alone, not despiked (auto): how much of the detail counts as
  /// (correlated) noise in sigma, clamp((detail / sigma_noise − 0.5) / 0.5, 0, 1): 1 for a
  /// scan-like mesh, 0 where the detail is at most half the noise (docs/presets.md, "Correlated
  /// noise"). 0 otherwise.
  double detail_as_noise = 0;
  /// Class cad by its flat areas alone, its low-pass residual more detail than noise (auto): read
  /// as a scan with correlated noise, whose fidelity α keeps the lower cap and whose detail counts
  /// as noise in full (detail_as_noise 1; docs/presets.md, "Correlated noise").
  bool scan_like = false;
  /// Class smooth by the shape rule (auto; measured on the despiked mesh when despiked): the
  /// quadric ring excess of the mesh (0 for white noise on a smooth surface, larger with detail)
  /// and the limit below which it is called featureless, clamp(0.0016 / σ_rms², 0.03, 0.3) (0:
  /// not measured). A featureless mesh is denoised as class cad with polish 100, range 1, ω₃ 0.1
  /// and ω₂ 3 (docs/presets.md, "Featureless smooth surfaces").
  double quadric_excess = 0, featureless_limit = 0;
  bool featureless = false;
  /// Heavy noise (auto): the weight of a second round, ramp(strength × noise.sigma_rms, 0.3, 0.4)
  /// (0 below 0.3, 1 from 0.4): auto again on the result, its positions blended into this round's
  /// with this weight (second_round.h; docs/presets.md, "A second round under heavy noise"). 0
  /// for a named preset.
  double second_round = 0;

  /// Large meshes (auto): the faces measured, the cores of sample_patches patches spread over
  /// the mesh (0: the whole mesh was measured).
  Eigen::Index sample_faces = 0, sample_patches = 0;
  /// Small components (auto, meshes measured whole): the faces of components of fewer than
  /// DenoiseOptions::min_component_faces faces are not measured (denoise() keeps them as they
  /// are, and the low pass would read their own shape as noise); how many, in how many.
  Eigen::Index unmeasured_faces = 0, unmeasured_components = 0;
  DenoiseOptions options;  ///< the options
  /// Why: "chosen automatically: ..." (auto) or "requested".
  std::string reason() const;
};

/// Resolves "auto" (from the mesh) or a preset name. `strength` in [kMinStrength, kMaxStrength]
/// scales how much is removed: "auto" uses strength × the estimated noise in its rules; a named
/// preset divides its α (the fidelity) by it. Throws InvalidInput for unknown names and a
/// strength out of range.
ResolvedPreset resolve_preset(const std::string& name, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                              double strength = 1.0);

/// Normal filter options of segmentation (SegmentOptions::normals): preset "cad"'s.
NormalFilterOptions segment_normal_options();

/// Normal filter and vertex update options of inpainting around the holes
/// (InpaintOptions::normals, ::vertices); measured with bench/inpaint (docs/inpainting.md).
NormalFilterOptions inpaint_normal_options();
VertexUpdateOptions inpaint_vertex_options();

}  // namespace msmesh
