#include "msmesh/presets.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "bilateral_pairs.h"
#include "crease_lines.h"
#include "featureless.h"
#include "low_pass_residuals.h"
#include "masked_measures.h"
#include "mesh_components.h"
#include "msmesh/bilateral.h"
#include "msmesh/despike.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/noise_estimate.h"
#include "msmesh/taubin.h"
#include "msmesh/topology.h"
#include "parallel.h"
#include "patch_sample.h"
#include "sub_mesh.h"

namespace msmesh {

namespace {

// The "auto" rule's thresholds (docs/presets.md, measured on the 17 public noisy meshes).
constexpr double kCreaseAngleDeg = 30.0;     // a pre-smoothed dihedral above this is a crease
constexpr double kFlatAngleDeg = 1.0;        // ... below this, flat
constexpr double kCadCreaseFraction = 0.03;  // cad when creases make at least this much edge length
// ... counting only creases on lines at least this many mean edge lengths long (crease edges
// meeting at vertices): a CAD part's creases run on as lines, while noise, above all in random
// directions, and an organic shape's fine detail make short scattered ones (docs/presets.md,
// "Crease lines": sweep geometric mean 0.961x, 13 more cases below both baselines).
constexpr double kCreaseLineMinEdges = 40.0;
// ... and at least kCadLinesSteepShare of those lines steep (below): a part's crease lines are
// mostly its edges, while the long creases an organic shape reads (the DeepMeshPrior dragon's
// ridges, every fold under heavy noise in random directions) are mostly gentler: 0.29–0.56 of
// them steep where the class cad lost to smooth by up to 3.4x, 0.64–1.0 on the parts
// (docs/presets.md, "Gentle crease lines").
constexpr double kCadLinesSteepShare = 0.6;
// ... or steep creases (a pre-smoothed dihedral above kSteepAngleDeg) on such lines at least
// kCadSteepFraction of the edge length and kCadSteepShare of the creases on lines: fewer crease
// lines, but a part's edges (grooves, the rims of a capped cylinder), where an organic shape's
// long creases are mostly gentler folds (docs/presets.md, "Steep crease lines").
constexpr double kSteepAngleDeg = 60.0;
constexpr double kCadSteepFraction = 0.012;
constexpr double kCadSteepShare = 0.8;
constexpr double kCadFlatFraction = 0.5;  // ... or flat edges at least this much
constexpr int kPreSmoothingPasses = 15;   // bilateral passes before measuring

// The noise-adaptive rules of "auto" (docs/presets.md, measured on seeded noise of σ 0.1, 0.3
// and 0.6 on six clean public meshes, then checked on the public noisy inputs):
//   α = clamp(kAlphaTimesSigma / σ, α_min(class), kAlphaMax): more fidelity at low noise, so
//   that detail the input still has is kept; less at heavy noise;
//   pre-filter = round(clamp((σ − kPrefilterFrom) · kPrefilterSlope, 0, kPrefilterMax)) Taubin
//   passes before N⁰ is taken: the first normals are usable under heavy noise. The class smooth
//   takes kPrefilterSlopeSmooth and kPrefilterMaxSmooth instead (4 passes at σ 0.2, 8 at 0.3, 10
//   from 0.35): without creases to keep, Taubin's low pass is a better start than the noisy
//   normals (docs/presets.md, "More pre-filtering for the class smooth"; sweep 0.991×, public
//   pairs 0.984×; the shape class is still judged on the copy of the general rule).
//   α_max is 10 for the class cad and 5 for smooth: at σ below 0.15 more fidelity keeps what a
//   CAD part's tessellation carries (coarse fillets, small features), while organic shapes lost
//   with more (sweep cases at σ 0.05 and 0.1: cad geometric mean 0.89 of α_max 5, 0 of 86 cases
//   worse by more than 2 %; smooth 1.00, 23 of 82 worse); but a mesh classed cad by its flat
//   areas alone (crease fraction below kCadCreaseFraction) whose low-pass residual is more
//   detail than noise reads like a scan with correlated noise (the Kinect Cone: 63.1 at α 5,
//   67.9 at 7.7), which keeps α_max 5 (kAlphaMaxScanLike; docs/presets.md, "The fidelity cap"),
//   as does a mesh whose spikes were removed.
constexpr double kAlphaTimesSigma = 0.75;
constexpr double kAlphaMinCad = 2.0, kAlphaMinSmooth = 1.5, kAlphaMaxCad = 10.0, kAlphaMaxSmooth = 5.0;
constexpr double kAlphaMaxScanLike = 5.0;
//   A cad mesh with few creases (crease fraction below kCadCreaseFraction; not despiked) counts its
//   detail d as noise, up to kScanDetailAsNoise times: σ = strength × √(σ_rms² + w (k² − 1) d²),
//   w = clamp((d / noise alone − kScanDetailRampFrom) / (1 − kScanDetailRampFrom), 0, 1), so 1 for
//   a scan-like mesh (more detail than noise) and 0 below half as much, without a jump between.
//   Correlated noise (a depth camera's, or white noise averaged over a few rings) is long-waved,
//   so the low pass reads most of it as detail and σ_rms alone asks for too little smoothing
//   (docs/presets.md, "Correlated noise"): the Kinect Cone 63.1 → 57.1 (w 1; TGV's released
//   59.8), the Kinect pyramid 61.8 → 53.8 (w 0.40; TGV's 49.6); procedural cube, fandisk and
//   pyramid (not in ../shared) with correlated noise: 0.27–0.95× the MSAE, none worse; the sweep
//   (white noise) 1.001× in geometric mean, no case newly above a baseline.
constexpr double kScanDetailAsNoise = 3.0, kScanDetailRampFrom = 0.5;
// How many times the detail counts as noise at weight w: √(1 + w (k² − 1)), 1 at w 0, k at w 1.
double detail_counted_times(double w) { return std::sqrt(1 + w * (kScanDetailAsNoise * kScanDetailAsNoise - 1)); }
constexpr double kPrefilterFrom = 0.1, kPrefilterSlope = 8.0, kPrefilterSlopeSmooth = 40.0;
constexpr int kPrefilterMax = 5, kPrefilterMaxSmooth = 10;
//   ω₂ (smooth class) = preset smooth's ω₂ × clamp((σ − kFairnessFrom) / kFairnessSpan, kFairnessMinShare, 1):
//   the fairness term (v ≈ 1 everywhere on organic shapes) flattens curvature the input still has,
//   so it is weak at low noise and reaches its full weight at σ 0.4.
constexpr double kFairnessFrom = 0.1, kFairnessSpan = 0.3, kFairnessMinShare = 0.1;
//   ω₂ (class cad; not despiked, not featureless) where the noise goes across the normals
//   (NoiseEstimate::across_ratio ≥ kAcrossRatio): from preset cad's up to kAcrossFairness as
//   strength × σ_rms goes from kAcrossFairnessFrom to kAcrossFairnessTo. Heavy noise in random
//   directions leaves the triangles of a CAD part tangled across the surface, which the weak
//   fairness of the class cad (0.03) does not undo (the Nousias casting at random 0.7: 343 flipped
//   faces, 51 at 0.1); noise along the normals of the same σ does not want it (docs/presets.md,
//   "Heavy noise in random directions on CAD parts").
constexpr double kAcrossRatio = 1.25, kAcrossFairness = 0.1, kAcrossFairnessFrom = 0.25, kAcrossFairnessTo = 0.4;
//   τ (class smooth; not despiked, not featureless) where moderate noise goes along the normals:
//   1 − (1 − kAlongTangential) · w_d · w_σ, w_d = clamp((kAlongRatioTo − across_ratio) /
//   (kAlongRatioTo − kAlongRatioFrom), 0, 1) and w_σ rising from 0 to 1 as strength × σ_rms goes
//   from kAlongSigmaFrom to kAlongSigmaFull, 1 up to kAlongSigmaFade, 0 again at kAlongSigmaTo. The
//   fairness's pull along the surface moves the vertices where the noise did not, and flattens
//   the detail with them (the NLLR igea: 73.9 → 62 with 91 → 59 flipped faces); under heavier
//   noise along the normals the triangles tangle and want it back, and the ratio reads the
//   direction only above σ ≈ 0.25 (docs/presets.md, "Moderate noise along the normals on organic
//   shapes"). Random noise must keep τ 1 (τ 0.1 at random 0.3: 2–5× the MSAE).
constexpr double kAlongTangential = 0.1, kAlongRatioFrom = 0.8, kAlongRatioTo = 1.0;
constexpr double kAlongSigmaFrom = 0.2, kAlongSigmaFull = 0.25, kAlongSigmaFade = 0.35, kAlongSigmaTo = 0.5;
//   τ (class cad), the share of the fairness term that acts along the surface
//   (VertexUpdateOptions::fairness_tangential) = kTangentialMin up to σ kTangentialFrom, rising
//   linearly to 1 (the paper's whole term) at kTangentialTo: the term's pull along the surface
//   evens out the triangles, which heavier noise in random directions needs (sweep at τ 0.3
//   everywhere: random σ 0.2–0.7 1.17–2.07× the MSAE), but at low noise it moves a CAD
//   tessellation's own triangles off their places, tilting their normals (cad σ ≤ 0.1 read:
//   0.79–0.94×). The class smooth keeps 1: on organic meshes random noise of σ 0.1 already lost
//   (1.09×); so do featureless surfaces (below; procedural spheres at σ 0.05–0.1 lost 1.3–1.9×).
//   Sweep 12.54 → 12.44 (docs/presets.md, "Fairness along the normals").
constexpr double kTangentialMin = 0.15, kTangentialFrom = 0.08, kTangentialTo = 0.12;
//   ω₃ (both classes) = the class's ω₃ × clamp((kClosenessSigma / σ)², 1, kClosenessMaxGain): the
//   closeness to the input is a Gaussian-likelihood weight, ∝ 1/σ², so below σ 0.13 it grows and
//   the vertex update keeps the detail a nearly clean input still has (up to 3×, reached at σ 0.075).
constexpr double kClosenessSigma = 0.13, kClosenessMaxGain = 3.0;
//   Class smooth, the shape's own detail (d, below): σ is the RMS without it,
//   √(σ_rms² − d²), and ω₃ is multiplied by 1 + kDetailCloseness (d/σ)², at most kDetailMaxGain:
//   an organic surface with fine detail of its own (the DeepMeshPrior dragon and sheep, the
//   statues) keeps it where the noise alone would be smoothed (docs/presets.md, "Noise and
//   detail"; measured on the sweep: gain 3 against 10; on CAD parts the detail is their creases
//   and more closeness loses, so the class cad is unchanged).
//   d is the estimate's detail less kDetailDoubt × its noise alone, in quadrature: the split reads
//   0.3–0.4 σ of noise as detail where a mesh's noise ratio ρ is 3 % off the median
//   (noise_estimate.cpp), which raised the closeness on smooth meshes with little detail (seeded
//   σ 0.05–0.1 on a procedural torus with waves 4–16 edges long, not in ../shared: up to 1.25× the
//   MSAE of before; with 0.5: up to 1.09×, and on the sweep 511 → 514 cases with flips no more
//   than the fewer of the baselines').
constexpr double kDetailCloseness = 3.0, kDetailMaxGain = 10.0, kDetailDoubt = 0.5;
//   Class smooth, not despiked, noise alone σ_n ≥ kDetailEaseFrom: σ is divided by
//   1 + kDetailEase · d' / max(σ_n, kDetailEaseFloor), d' the detail less kDetailEaseDoubt · σ_n
//   in quadrature. Where a surface's own fine detail stands out of the noise (the DeepMeshPrior
//   dragon and sheep, statues at σ 0.1) every rule smooths less, not only the closeness: at the
//   σ the estimate reads, α, the pre-filter and the fairness took the detail for noise (the dragon
//   at normal σ 0.2 114 at strength 1, 89 at 0.5; Taubin ×10 92). Below σ_n 0.1 the split of
//   noise and detail is not to be trusted (long waves on a torus lost up to 1.23×), and a
//   despiked mesh's detail is what the spikes left (docs/presets.md, "Detail that stands out of
//   the noise").
constexpr double kDetailEase = 2.0, kDetailEaseDoubt = 0.3, kDetailEaseFloor = 0.15, kDetailEaseFrom = 0.1;
//   Impulsive noise: when at least kDespikeFromOutliers of the vertices are outliers of the noise
//   estimate (beyond 4 robust σ) and σ_rms is at least kDespikeFromSigmaRms, the spikes are first
//   moved onto a low-pass copy (despike.h) at kDespikeThreshold robust σ, and the rules above take σ
//   from the despiked mesh (docs/presets.md, "Impulsive noise"). Measured on the sweep: 20 % spikes
//   read 4–9 % outliers and σ_rms >= 0.217; the outliers of low-noise CAD parts (3–9 %, σ_rms up to
//   0.13; a clean coarse fandisk: 0.18) are their creases, which despiking would round off.
constexpr double kDespikeFromOutliers = 0.03, kDespikeFromSigmaRms = 0.2, kDespikeThreshold = 3.0;
//   The polish of the filtered normals (class cad; NormalFilterOptions::polish): λ = preset cad's
//   3 × clamp(σ / kPolishFullSigma, kPolishMinShare, 1) and range clamp(kPolishRangePerSigma σ,
//   kPolishRangeMin, preset cad's 0.3): what the fidelity term leaves of the noise, and how far
//   apart it leaves neighbouring normals, both shrink with σ, while the bias of averaging over a
//   curved part does not (docs/presets.md, "The polish"; at σ 0.05 the full polish lost on CAD
//   parts with seeded noise, up to 1.36x, and on the dragon, which auto classes cad, 1.21x).
constexpr double kPolishFullSigma = 0.2, kPolishMinShare = 0.25, kPolishRangePerSigma = 1.5, kPolishRangeMin = 0.15;

// Featureless smooth surfaces (docs/presets.md, "Featureless smooth surfaces"): a mesh the
// shape rule classes smooth (after the spike removal, if any), whose quadric ring excess
// (featureless.h) is below clamp(kFeaturelessPerSigma2 / σ_rms², kFeaturelessMin,
// kFeaturelessMax) — about half the least that the organic meshes of ../shared read at that
// noise (0.24 at σ 0.11, 0.083 at 0.2, 0.051 at 0.3 and above), and more than spheres and tori
// read (0.04 at most) — is denoised as class cad with a strong polish: on such a surface the
// class smooth's early-stopped TV flow leaves most of the noise, and the polish's screened
// smoothing of the normals is the better filter.
constexpr double kFeaturelessPerSigma2 = 0.0016, kFeaturelessMin = 0.03, kFeaturelessMax = 0.3;
constexpr double kFeaturelessPolish = 100.0, kFeaturelessPolishRange = 1.0;
//   Its vertex update: the class cad's closeness ω₃ without the low-noise gain (which keeps
//   detail, and there is none) and fairness ω₂ = kFeaturelessFairness (the procedural sphere and
//   torus, σ 0.05–0.3, 16 cases: 0.214 → 0.077; ω₂ 0.3, 1, 10, 30: 0.138, 0.111, 0.065, 0.098,
//   30 bending the coarse sphere; the cubesphere loses a little at σ 0.05, 0.14 → 0.16).
constexpr double kFeaturelessFairness = 3.0;

// A second round under heavy noise (docs/presets.md, "A second round under heavy noise"): from
// strength × σ_rms (of the input, spikes and all) kSecondRoundFrom up to kSecondRoundTo, auto is
// run again on the result and its positions blended in with a weight rising from 0 to 1. The
// first round leaves the noise a first normal filter could not tell from the shape; measured
// again on the result it is moderate noise, which the rules handle well (sweep 0.968×, worse by
// more than 5 % in 12 of 588 cases; procedural shapes 0.90×, none worse).
constexpr double kSecondRoundFrom = 0.3, kSecondRoundTo = 0.4;

// Meshes above kSampleAboveFaces faces are measured on kSamplePatches patches of
// kSamplePatchFaces faces, away from the cuts by kSampleMargin rings (about as far as the
// Taubin low pass and the bilateral pre-smoothing reach). 32 x 6000 faces: ~90K core faces.
constexpr Eigen::Index kSampleAboveFaces = 400000, kSamplePatches = 32, kSamplePatchFaces = 6000;
constexpr int kSampleMargin = 10;

/// Taubin passes before N⁰ is taken, at noise σ; `smooth` for the class smooth's steeper rule.
int prefilter_for(double sigma, bool smooth = false) {
  const double slope = smooth ? kPrefilterSlopeSmooth : kPrefilterSlope;
  const int most = smooth ? kPrefilterMaxSmooth : kPrefilterMax;
  return static_cast<int>(std::lround(std::clamp((sigma - kPrefilterFrom) * slope, 0.0, double(most))));
}

/// 0 at `from`, 1 at `to`, linear between and clamped outside (falling where to < from).
double ramp(double x, double from, double to) { return std::clamp((x - from) / (to - from), 0.0, 1.0); }

std::string fixed(double x, int digits) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(digits);
  os << x;
  return os.str();
}

}  // namespace

std::vector<std::string> preset_names() { return {"cad", "smooth", "paper"}; }

const char* default_preset() { return "auto"; }

DenoiseOptions preset_options(const std::string& name) {
  // Units: mean edge length 1 (DESIGN.md §"Scale"). docs/presets.md says how these values were
  // chosen on the public test meshes.
  DenoiseOptions o;  // the struct defaults are "cad": α 2.5, β 0.02, γ 2, ρ 0.1, r 2, ω₂ 0.03, ω₃ 0.1
  if (name == "cad") return o;
  if (name == "smooth") {
    o.normals.alpha = 2.0;
    o.normals.beta = 2.0;  // v ≈ 1 everywhere: the edge field only hurts organic shapes
    o.normals.gamma = 2.0;
    o.normals.rho = 0.9;
    o.normals.penalty = 0.1;  // slow ADMM = 30 iterations stop well short of the TV staircase
    o.vertices.omega2 = 0.3;
    o.vertices.omega3 = 0.3;
    o.normals.polish = 0;     // averages the detail of organic shapes away (docs/presets.md, "The polish")
    o.unreachable_angle = 0;  // lost on organic shapes (docs/presets.md, "Unreachable targets")
    return o;
  }
  if (name == "paper") {
    // Algorithms 1 and 2 as published. §5.1: ε 0.001, ν 1.618, r_p 1, ε₁ 1e-6, k 30, ω₁ 1,
    // ε₂ 1e-6, k 30, ρ 0.9 for CAD meshes (0.1 for organic ones: --rho 0.1), the normals
    // projected onto the sphere after every N-step. §5.2 gives ranges for α, β, γ, ω₂, ω₃ rather
    // than values; these are preset cad's, inside those ranges.
    o.normals.rho = 0.9;
    o.normals.penalty = 1.0;
    o.normals.project_each_iteration = true;
    o.vertices.tolerance = 1e-6;
    o.vertices.acceleration = 0;                                      // Algorithm 2's plain alternation
    o.normals.polish = 0;                                             // Algorithm 1's normals as they come
    o.plane_min_faces = 0;                                            // and no planar regions
    o.jet_rings = 0;                                                  // nor jet-fitted targets
    o.unreachable_angle = 0;                                          // nor dropped ones
    o.min_component_faces = 0;                                        // every component denoised
    o.normals.solver_tolerance = o.vertices.solver_tolerance = 1e-8;  // exact solves, as the paper's
    return o;
  }
  if (name == "auto") throw InvalidInput("preset 'auto' is chosen from the mesh: use resolve_preset(\"auto\", V, F)");
  throw InvalidInput("unknown preset '" + name + "'; valid: auto, cad, smooth, paper");
}

DenoiseOptions adaptive_options(const std::string& shape_class, double sigma, double detail, double alpha_max) {
  if (shape_class != "cad" && shape_class != "smooth")
    throw InvalidInput("adaptive options: shape class must be cad or smooth, got '" + shape_class + "'");
  if (!(sigma >= 0)) throw InvalidInput("adaptive options: noise level must be >= 0");
  if (!(detail >= 0)) throw InvalidInput("adaptive options: detail must be >= 0");
  if (!(alpha_max >= 0)) throw InvalidInput("adaptive options: the cap on alpha must be >= 0 (0: the class's)");
  DenoiseOptions o = preset_options(shape_class);
  const double alpha_min = shape_class == "cad" ? kAlphaMinCad : kAlphaMinSmooth;
  if (alpha_max == 0) alpha_max = shape_class == "cad" ? kAlphaMaxCad : kAlphaMaxSmooth;
  alpha_max = std::max(alpha_max, alpha_min);
  o.normals.alpha = sigma > 0 ? std::clamp(kAlphaTimesSigma / sigma, alpha_min, alpha_max) : alpha_max;
  o.prefilter_iterations = prefilter_for(sigma, shape_class == "smooth");
  if (shape_class == "smooth")
    o.vertices.omega2 *= std::clamp((sigma - kFairnessFrom) / kFairnessSpan, kFairnessMinShare, 1.0);
  if (shape_class == "cad") {
    o.normals.polish *= std::clamp(sigma / kPolishFullSigma, kPolishMinShare, 1.0);
    o.normals.polish_range = std::clamp(kPolishRangePerSigma * sigma, kPolishRangeMin, o.normals.polish_range);
  }
  if (shape_class == "cad")
    o.vertices.fairness_tangential = std::clamp(
        kTangentialMin + (1 - kTangentialMin) * (sigma - kTangentialFrom) / (kTangentialTo - kTangentialFrom),
        kTangentialMin, 1.0);
  const double closeness = sigma > 0 ? kClosenessSigma / sigma : 1e300;
  o.vertices.omega3 *= std::clamp(closeness * closeness, 1.0, kClosenessMaxGain);
  if (shape_class == "smooth" && detail > 0) {
    const double q = sigma > 0 ? detail / sigma : 1e300;
    o.vertices.omega3 *= std::min(1 + kDetailCloseness * q * q, kDetailMaxGain);
  }
  return o;
}

PresetChoice choose_preset(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  validate_mesh(V, F, "preset choice");
  return detail::choose_preset_masked(V, F, nullptr);
}

PresetChoice detail::choose_preset_masked(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                          const std::vector<char>* measured) {
  PresetChoice c;
  const auto counts = [&](Eigen::Index f) { return !measured || (*measured)[static_cast<std::size_t>(f)]; };
  // Pre-smooth the normals with bilateral passes, then look at the dihedral angles of the
  // smoothed normals, weighted by edge length. CAD parts (and scans of them) have either a
  // clear set of strong creases or mostly flat regions; organic shapes have neither.
  // (bilateral_filter_normals with sigma_s 0 and the default sigma_r, to round-off; computed
  // per pair of faces, which is three times cheaper.)
  const Eigen::MatrixXd N = detail::bilateral_normals_by_pairs(V, F, kPreSmoothingPasses, BilateralOptions{}.sigma_r);
  const Eigen::MatrixXd N0 = face_normals(V, F);
  const Topology t = build_topology(F, V.rows());
  const Eigen::VectorXd len = edge_lengths(V, t);
  // An angle below (above) a threshold is a cosine above (below) the threshold's cosine: no
  // arccosine per edge.
  const double cos_flat = std::cos(kFlatAngleDeg * M_PI / 180), cos_sharp = std::cos(kCreaseAngleDeg * M_PI / 180);
  std::vector<char> crease(static_cast<std::size_t>(t.num_edges()), 0);
  std::vector<char> steep(static_cast<std::size_t>(t.num_edges()), 0);
  const double cos_steep = std::cos(kSteepAngleDeg * M_PI / 180);
  const auto edge_sums =
      detail::deterministic_sums<4>(t.num_edges(), [&](Eigen::Index e0, Eigen::Index e1, std::array<double, 4>& s) {
        for (Eigen::Index e = e0; e < e1; ++e) {
          if (!t.edge_is_interior[e] || !counts(t.edge_faces(e, 0)) || !counts(t.edge_faces(e, 1))) continue;
          const double d = N.row(t.edge_faces(e, 0)).dot(N.row(t.edge_faces(e, 1)));
          s[0] += len(e);
          s[3] += 1;
          if (d > cos_flat) s[1] += len(e);
          if (d < cos_sharp) {
            s[2] += len(e);
            crease[static_cast<std::size_t>(e)] = 1;
          }
          if (d < cos_steep) steep[static_cast<std::size_t>(e)] = 1;
        }
      });
  const double total = edge_sums[0], flat = edge_sums[1], sharp = edge_sums[2];
  const double mean_length = edge_sums[3] > 0 ? total / edge_sums[3] : 0;
  // In a patch sample a line may go on beyond the measured faces: one that reaches a vertex of an
  // unmeasured face counts as long.
  std::vector<char> open;
  if (measured && sharp > 0) {
    open.assign(static_cast<std::size_t>(V.rows()), 0);
    for (Eigen::Index f = 0; f < F.rows(); ++f)
      if (!counts(f))
        for (int k = 0; k < 3; ++k) open[static_cast<std::size_t>(F(f, k))] = 1;
  }
  const double on_lines = sharp > 0
                              ? detail::crease_line_length(t, len, crease, V.rows(), kCreaseLineMinEdges * mean_length,
                                                           measured ? &open : nullptr)
                              : 0;
  const double steep_lines =
      sharp > 0 ? detail::crease_line_length(t, len, steep, V.rows(), kCreaseLineMinEdges * mean_length,
                                             measured ? &open : nullptr)
                : 0;
  const auto face_sums = detail::deterministic_sums<2>(
      F.rows(),
      [&](Eigen::Index f0, Eigen::Index f1, std::array<double, 2>& s) {
        for (Eigen::Index f = f0; f < f1; ++f)
          if (counts(f)) {
            s[0] += std::acos(std::clamp(N.row(f).dot(N0.row(f)), -1.0, 1.0));
            s[1] += 1;
          }
      },
      8);
  const double raw_dev = face_sums[0];
  const auto measured_faces = static_cast<Eigen::Index>(face_sums[1]);
  c.sharp_fraction = total > 0 ? sharp / total : 0;
  c.crease_line_fraction = total > 0 ? on_lines / total : 0;
  c.flat_fraction = total > 0 ? flat / total : 0;
  c.noise_level = measured_faces ? raw_dev / double(measured_faces) : 0;
  c.steep_line_fraction = total > 0 ? steep_lines / total : 0;
  const bool steep_lines_rule =
      c.steep_line_fraction >= kCadSteepFraction && c.steep_line_fraction >= kCadSteepShare * c.crease_line_fraction;
  const bool lines_rule = c.crease_line_fraction >= kCadCreaseFraction &&
                          c.steep_line_fraction >= kCadLinesSteepShare * c.crease_line_fraction;
  const bool creases = lines_rule || steep_lines_rule;
  const bool flats = c.flat_fraction >= kCadFlatFraction;
  c.preset = (creases || flats) ? "cad" : "smooth";
  c.reason =
      "crease fraction " + fixed(c.sharp_fraction, 3) + ", on lines of " + fixed(kCreaseLineMinEdges, 0) +
      " edges or more " + fixed(c.crease_line_fraction, 3) +
      (c.crease_line_fraction >= kCadCreaseFraction ? " >= " : " < ") + fixed(kCadCreaseFraction, 2) +
      (c.crease_line_fraction >= kCadCreaseFraction
           ? (lines_rule ? " (" : " but only ") + fixed(100 * c.steep_line_fraction / c.crease_line_fraction, 0) +
                 " % of them steep" + (lines_rule ? ", >= " : " (< ") + fixed(100 * kCadLinesSteepShare, 0) + " %)"
           : "") +
      ", steeper than " + fixed(kSteepAngleDeg, 0) + " deg " + fixed(c.steep_line_fraction, 4) +
      (steep_lines_rule ? " (>= " : " (not >= ") + fixed(kCadSteepFraction, 3) + " and " +
      fixed(100 * kCadSteepShare, 0) + " % of those)" + ", flat fraction " + fixed(c.flat_fraction, 2) +
      (flats ? " >= " : " < ") + fixed(kCadFlatFraction, 2) + (c.preset == "cad" ? ": cad" : ": smooth");
  return c;
}

std::string ResolvedPreset::reason() const {
  const std::string s = strength != 1.0 ? ", strength " + fixed(strength, 2) : "";
  if (!automatic) return "requested" + s;
  const std::string sampled = sample_faces > 0 ? "measured on " + std::to_string(sample_faces) + " faces of " +
                                                     std::to_string(sample_patches) + " patches; "
                                               : "";
  const std::string spikes = despiked
                                 ? ", outliers >= " + fixed(100 * kDespikeFromOutliers, 0) +
                                       " % and rms >= " + fixed(kDespikeFromSigmaRms, 2) + ": " +
                                       fixed(100 * despiked_fraction, 1) + " % of the vertices despiked at " +
                                       fixed(options.despike_threshold, 1) + " sigma, then " + noise_despiked.summary()
                                 : "";
  const std::string eased = detail_ease > 1 ? ", eased " + fixed(detail_ease, 2) + "x for the detail" : "";
  const std::string detail = preset == "smooth" ? ", sigma without the detail" + eased + " " + fixed(sigma, 3)
                             : detail_as_noise > 0
                                 ? ", sigma with the detail counted " +
                                       fixed(detail_counted_times(detail_as_noise), 2) + " times " + fixed(sigma, 3)
                                 : "";
  const std::string polish = options.normals.polish > 0 ? ", polish " + fixed(options.normals.polish, 2) + " (range " +
                                                              fixed(options.normals.polish_range, 2) + ")"
                                                        : "";
  const std::string tangential =
      options.vertices.fairness_tangential < 1
          ? ", fairness along the surface " + fixed(options.vertices.fairness_tangential, 2) +
                (preset == "smooth" ? " (noise along the normals: " + fixed(noise.across_ratio, 2) + " as much across)"
                                    : "")
          : "";
  const std::string jets = options.jet_rings > 0 ? "" : ", no jet-fitted or dropped targets (long waves of noise)";
  const std::string across =
      preset == "cad" && !featureless && options.vertices.omega2 > preset_options("cad").vertices.omega2
          ? ", fairness " + fixed(options.vertices.omega2, 3) +
                " (noise across the normals: " + fixed(noise.across_ratio, 2) + " times as much as along)"
          : "";
  const std::string cap =
      scan_like  ? " (at most " + fixed(kAlphaMaxScanLike, 0) + ": scan-like, few creases and more detail than noise)"
      : despiked ? " (at most " + fixed(kAlphaMaxScanLike, 0) + " after the spike removal)"
                 : "";
  const std::string quadric = featureless_limit > 0 ? "; quadric ring excess " + fixed(quadric_excess, 3) +
                                                          (featureless ? " < " : " >= ") + fixed(featureless_limit, 3) +
                                                          (featureless ? ": featureless, cad" : "")
                                                    : "";
  const std::string small = unmeasured_faces > 0
                                ? "without the " + std::to_string(unmeasured_faces) + " faces of " +
                                      std::to_string(unmeasured_components) + " component(s) of fewer than " +
                                      std::to_string(options.min_component_faces) + " faces; "
                                : "";
  const std::string second = second_round > 0 ? ", second round " + fixed(second_round, 2) +
                                                    " (rms >= " + fixed(kSecondRoundFrom, 2) + ", full from " +
                                                    fixed(kSecondRoundTo, 2) + ")"
                                              : "";
  return "chosen automatically (" + sampled + small + noise.summary() + spikes + s + detail + ": alpha " +
         fixed(options.normals.alpha, 2) + cap + ", prefilter " + std::to_string(options.prefilter_iterations) +
         polish + tangential + across + jets + second + "; " + choice.reason + quadric + ")";
}

ResolvedPreset resolve_preset(const std::string& name, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                              double strength) {
  if (!(strength >= kMinStrength && strength <= kMaxStrength))
    throw InvalidInput("strength must be in [" + fixed(kMinStrength, 1) + ", " + fixed(kMaxStrength, 1) + "], got " +
                       fixed(strength, 3));
  ResolvedPreset r;
  r.requested = name;
  r.strength = strength;
  if (name != "auto") {
    r.preset = name;
    r.options = preset_options(name);
    r.options.normals.alpha /= strength;
    return r;
  }
  r.automatic = true;
  validate_mesh(V, F, "preset choice");
  if (F.rows() == 0) {  // nothing to measure: preset cad, as the struct defaults
    r.preset = "cad";
    r.choice.preset = "cad";
    r.options = preset_options("cad");
    return r;
  }
  // A large mesh is measured on the cores of patches spread over it: the same figures to the
  // printed digits (tests/test_presets.cpp), for a fraction of the time (docs/performance.md).
  const bool sampled = F.rows() > kSampleAboveFaces;
  // Components that denoise() keeps as they are are not measured either: the low pass reads a
  // small part's own shape as noise (a cube of 12 triangles beside a sphere of 20K faces: σ_rms
  // 1.06 where the sphere alone reads 0.03). (A sample's patches never have a core there.)
  if (!sampled) {
    int components = 0;
    const std::vector<int> label = detail::face_component_labels(F, V.rows(), components);
    const int min_faces = preset_options("cad").min_component_faces;
    detail::ComponentSplit split = detail::split_small_components(label, components, min_faces);
    if (split.small_faces > 0 && !split.large_faces.empty()) {
      std::vector<int> local(static_cast<std::size_t>(V.rows()), -1);
      const detail::SubMesh large = detail::sub_mesh(V, F, split.large_faces, local);
      ResolvedPreset measured = resolve_preset(name, large.V, large.F, strength);
      measured.unmeasured_faces = split.small_faces;
      measured.unmeasured_components = split.small_components;
      return measured;
    }
  }
  detail::PatchSample sample;
  if (sampled) {
    sample = detail::sample_patches(V, F, kSamplePatches, kSamplePatchFaces, kSampleMargin);
    r.sample_patches = sample.patches;
    r.sample_faces = sample.core_faces;
  }
  const Eigen::MatrixXd& SV = sampled ? sample.mesh.V : V;
  const Eigen::MatrixXi& SF = sampled ? sample.mesh.F : F;
  const std::vector<char>* core_vertices = sampled ? &sample.core_vertex : nullptr;
  // One low pass serves the noise estimate and, under impulsive noise, the spike removal.
  const detail::LowPassResiduals low_pass = detail::low_pass_residuals(SV, SF);
  r.noise = detail::estimate_noise_from(low_pass, core_vertices);
  // Impulsive noise: the spikes are removed first, and everything after is measured on the
  // despiked mesh, as denoise() will see it.
  r.despiked = r.noise.outlier_fraction >= kDespikeFromOutliers && r.noise.sigma_rms >= kDespikeFromSigmaRms;
  DespikeResult spikes;
  if (r.despiked) {
    spikes = detail::despike_from(SV, low_pass, kDespikeThreshold);
    r.despiked_fraction = static_cast<double>(spikes.moved) / static_cast<double>(std::max<Eigen::Index>(1, SV.rows()));
    r.noise_despiked = detail::estimate_noise_masked(spikes.V, SF, core_vertices);
  }
  const Eigen::MatrixXd& MV = r.despiked ? spikes.V : SV;
  const NoiseEstimate& measured = r.despiked ? r.noise_despiked : r.noise;
  r.sigma = strength * measured.sigma_rms;
  r.second_round = ramp(strength * r.noise.sigma_rms, kSecondRoundFrom, kSecondRoundTo);
  // The shape is judged on the mesh the first normals come from, so that heavy noise does not
  // count as creases.
  const int prefilter = prefilter_for(r.sigma);
  TaubinOptions to;
  to.iterations = prefilter;
  r.choice = detail::choose_preset_masked(prefilter > 0 ? taubin_smooth(MV, SF, to) : MV, SF,
                                          sampled ? &sample.core_face : nullptr);
  r.preset = r.choice.preset;
  if (r.preset == "smooth") {
    const detail::QuadricRingExcess q = detail::quadric_ring_excess(MV, SF);
    const double s2 = std::max(measured.sigma_rms * measured.sigma_rms, std::numeric_limits<double>::min());
    r.quadric_excess = q.excess;
    r.featureless_limit = std::clamp(kFeaturelessPerSigma2 / s2, kFeaturelessMin, kFeaturelessMax);
    r.featureless = q.samples > 0 && q.excess < r.featureless_limit;
    if (r.featureless) r.preset = "cad";
  }
  // The class smooth: the noise without the shape's own detail, and the detail kept (the class
  // was judged on the copy pre-filtered for σ_rms; the options may pre-filter less).
  double detail = 0;
  if (r.preset == "smooth") {
    // The detail less `doubt` times the noise alone, in quadrature.
    const auto detail_beyond = [&](double doubt) {
      const double d = measured.detail, n = doubt * measured.sigma_noise;
      return std::sqrt(std::max(0.0, d * d - n * n));
    };
    const double rms = measured.sigma_rms;
    detail = detail_beyond(kDetailDoubt);
    r.sigma = strength * std::sqrt(std::max(0.0, rms * rms - detail * detail));
    if (!r.despiked && measured.sigma_noise >= kDetailEaseFrom) {
      r.detail_ease =
          1 + kDetailEase * detail_beyond(kDetailEaseDoubt) / std::max(measured.sigma_noise, kDetailEaseFloor);
      r.sigma /= r.detail_ease;
    }
  }
  // A scan-like cad mesh keeps the lower cap on the fidelity (kAlphaMaxScanLike), and so does a
  // despiked one: what the spike removal leaves reads as little noise, but the vertices it moved
  // onto the low pass are not clean (cad impulsive 0.5 on the sweep: up to 1.4x the MSAE with the
  // higher cap).
  const bool few_creases = r.preset == "cad" && r.choice.sharp_fraction < kCadCreaseFraction;
  r.scan_like = few_creases && measured.detail > measured.sigma_noise;
  // Few creases and flat areas: the more of the low-pass residual reads as detail, the more of it
  // is taken for correlated noise (weight 0 up to half as much detail as noise, 1 from as much).
  if (few_creases && !r.despiked) {
    const double rms = measured.sigma_rms, d = measured.detail;
    const double ratio = d / std::max(measured.sigma_noise, std::numeric_limits<double>::min());
    r.detail_as_noise = ramp(ratio, kScanDetailRampFrom, 1.0);
    const double k = detail_counted_times(r.detail_as_noise);
    r.sigma = strength * std::sqrt(rms * rms + (k * k - 1) * d * d);
  }
  r.options = adaptive_options(r.preset, r.sigma, detail, r.scan_like || r.despiked ? kAlphaMaxScanLike : 0.0);
  if (r.despiked) r.options.despike_threshold = kDespikeThreshold;
  // Where detail is taken for correlated noise, the first update's positions keep long waves
  // that quadrics would follow (docs/presets.md, "Jet-fitted targets"), and that keep faces from
  // their targets without a crease between (no second update there: "Unreachable targets").
  if (r.detail_as_noise > 0) {
    r.options.jet_rings = 0;
    r.options.unreachable_angle = 0;
  }
  if (r.preset == "cad" && !r.featureless && !r.despiked && measured.across_ratio >= kAcrossRatio) {
    const double share = ramp(strength * measured.sigma_rms, kAcrossFairnessFrom, kAcrossFairnessTo);
    double& omega2 = r.options.vertices.omega2;
    omega2 += share * std::max(0.0, kAcrossFairness - omega2);
  }
  if (r.preset == "smooth" && !r.despiked) {
    const double s = strength * measured.sigma_rms;
    const double w_sigma = ramp(s, kAlongSigmaFrom, kAlongSigmaFull) * ramp(s, kAlongSigmaTo, kAlongSigmaFade);
    const double w_direction = ramp(measured.across_ratio, kAlongRatioTo, kAlongRatioFrom);
    r.options.vertices.fairness_tangential = 1 - (1 - kAlongTangential) * w_sigma * w_direction;
  }
  if (r.featureless) {
    r.options.normals.polish = kFeaturelessPolish;
    r.options.normals.polish_range = kFeaturelessPolishRange;
    r.options.vertices.omega3 = preset_options("cad").vertices.omega3;
    r.options.vertices.omega2 = kFeaturelessFairness;
    r.options.vertices.fairness_tangential = 1;  // all of it: nothing to keep between the triangles
  }
  return r;
}

NormalFilterOptions segment_normal_options() {
  NormalFilterOptions o = preset_options("cad").normals;
  o.polish = 0;  // segmentation reads v; the polish only changes N (not measured there)
  return o;
}

NormalFilterOptions inpaint_normal_options() {
  NormalFilterOptions o;
  o.alpha = 2.0;
  o.beta = 0.02;
  o.gamma = 0.5;
  o.rho = 0.1;
  o.penalty = 1.0;
  // Inside a hole the fidelity is ~0, so only the unit-length projection keeps the normals
  // from shrinking towards their average across a crease (the relaxed problem is then a
  // vector TV whose minimiser blends the two sides): project after every N-step, as the paper.
  o.project_each_iteration = true;
  o.polish = 0;  // not measured on holes
  return o;
}

VertexUpdateOptions inpaint_vertex_options() {
  VertexUpdateOptions o;
  o.omega1 = 1.0;
  o.omega2 = 0.0;
  o.omega3 = 0.1;
  o.max_iterations = 60;
  o.tolerance = 1e-6;  // new vertices travel far, slowly: all 60 iterations
  o.acceleration = 0;  // measured on denoising only (docs/presets.md)
  return o;
}

}  // namespace msmesh
