// Presets (msmesh/presets.h): the named parameter sets, the auto rule, and that the structs'
// own defaults are the documented default (preset cad).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/inpaint.h"
#include "msmesh/metrics.h"
#include "msmesh/noise.h"
#include "msmesh/noise_estimate.h"
#include "msmesh/parameters.h"
#include "msmesh/presets.h"
#include "msmesh/read_mesh.h"
#include "msmesh/segment.h"
#include "msmesh/shapes.h"
#include "msmesh/taubin.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

/// Every parameter of the table has the same value in a and b.
template <class Options>
void expect_same_parameters(const ParameterTable<Options>& table, const Options& a, const Options& b,
                            const std::string& what) {
  for (const Parameter<Options>& p : table) EXPECT_EQ(p.get(a), p.get(b)) << what << ": " << p.info.name;
}

/// A sphere (`shape sphere 24`) with fine waves of its own: 12 plane waves 2.5 mean edges long,
/// RMS 0.25 mean edges, along the normals.
Eigen::MatrixXd wavy_sphere(const Mesh& sphere) {
  const double h = mean_edge_length(sphere.V, sphere.F);
  const double k = 2 * M_PI / (2.5 * h);
  Eigen::VectorXd wave = Eigen::VectorXd::Zero(sphere.V.rows());
  for (int i = 0; i < 12; ++i) {
    const Eigen::Vector3d d = Eigen::Vector3d(std::cos(2.4 * i), std::sin(1.7 * i + 0.3), std::cos(0.9 * i + 1.1))
                                  .normalized();  // 12 fixed directions
    wave += ((sphere.V * d).array() * k + 0.7 * i).sin().matrix();
  }
  wave *= 0.25 * h / std::sqrt(wave.squaredNorm() / static_cast<double>(wave.size()));
  return sphere.V + sphere.V.rowwise().normalized().cwiseProduct(wave.replicate(1, 3));
}

}  // namespace

TEST(Presets, StructDefaultsAreTheCadPreset) {
  expect_same_parameters(denoise_parameters(), DenoiseOptions{}, preset_options("cad"), "DenoiseOptions{}");
  expect_same_parameters(normal_filter_parameters(), NormalFilterOptions{}, preset_options("cad").normals,
                         "NormalFilterOptions{}");
  expect_same_parameters(vertex_update_parameters(), VertexUpdateOptions{}, preset_options("cad").vertices,
                         "VertexUpdateOptions{}");
  expect_same_parameters(normal_filter_parameters(), SegmentOptions{}.normals, segment_normal_options(),
                         "SegmentOptions{}.normals");
  expect_same_parameters(normal_filter_parameters(), InpaintOptions{}.normals, inpaint_normal_options(),
                         "InpaintOptions{}.normals");
  expect_same_parameters(vertex_update_parameters(), InpaintOptions{}.vertices, inpaint_vertex_options(),
                         "InpaintOptions{}.vertices");
}

TEST(Presets, NamesAndTheirOptionsAreValid) {
  const std::vector<std::string> names = preset_names();
  ASSERT_EQ(names, (std::vector<std::string>{"cad", "smooth", "paper"}));
  for (const std::string& name : names) EXPECT_NO_THROW(preset_options(name).validate()) << name;
  EXPECT_STREQ(default_preset(), "auto");
  // The presets differ where docs/presets.md says they do.
  EXPECT_NE(preset_options("cad").normals.beta, preset_options("smooth").normals.beta);
  EXPECT_NE(preset_options("cad").normals.rho, preset_options("smooth").normals.rho);
  // paper: the published Algorithm 1 (projection after every N-step) with §5.1's r_p and ρ.
  const DenoiseOptions paper = preset_options("paper");
  EXPECT_TRUE(paper.normals.project_each_iteration);
  EXPECT_EQ(paper.normals.penalty, 1.0);
  EXPECT_EQ(paper.normals.rho, 0.9);
  EXPECT_EQ(paper.normals.epsilon, 1e-3);
  EXPECT_EQ(paper.normals.relaxation, 1.618);
  EXPECT_EQ(paper.normals.max_iterations, 30);
  EXPECT_EQ(paper.vertices.omega1, 1.0);
  EXPECT_EQ(paper.vertices.max_iterations, 30);
  EXPECT_EQ(paper.prefilter_iterations, 0);
}

TEST(Presets, AutoNeedsAMeshAndUnknownNamesListTheValidOnes) {
  try {
    preset_options("auto");
    FAIL() << "auto accepted without a mesh";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("resolve_preset"), std::string::npos) << e.what();
  }
  try {
    preset_options("sharp");
    FAIL() << "unknown preset accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("auto, cad, smooth, paper"), std::string::npos) << e.what();
  }
  const Mesh m = test::grid(6, 0.1);
  EXPECT_THROW(resolve_preset("sharp", m.V, m.F), InvalidInput);
}

TEST(Presets, AutoChoosesFromTheMeshAndSaysWhy) {
  // A CAD part: creases and flat faces -> cad; a bumpy organic sheet -> smooth.
  const Mesh part = make_shape("fandisk", 8);
  const ResolvedPreset cad = resolve_preset("auto", part.V, part.F);
  EXPECT_TRUE(cad.automatic);
  EXPECT_EQ(cad.preset, "cad");
  EXPECT_EQ(cad.choice.preset, "cad");
  EXPECT_NE(cad.reason().find("chosen automatically"), std::string::npos) << cad.reason();
  EXPECT_NE(cad.reason().find("crease fraction"), std::string::npos) << cad.reason();
  EXPECT_NE(cad.reason().find("noise sigma"), std::string::npos) << cad.reason();
  // The options are the adaptive ones for the class and the estimated noise.
  expect_same_parameters(denoise_parameters(), cad.options, adaptive_options("cad", cad.sigma), "auto -> cad");
  EXPECT_EQ(cad.sigma, cad.noise.sigma_rms);

  const Mesh sphere = make_shape("sphere", 8);
  const PresetChoice c = choose_preset(sphere.V, sphere.F);
  EXPECT_EQ(c.preset, "smooth") << c.reason;
  EXPECT_NE(c.reason.find(": smooth"), std::string::npos) << c.reason;

  const ResolvedPreset asked = resolve_preset("smooth", part.V, part.F);
  EXPECT_FALSE(asked.automatic);
  EXPECT_EQ(asked.preset, "smooth");
  EXPECT_EQ(asked.reason(), "requested");
}

TEST(Presets, AutoRemovesSpikesUnderImpulsiveNoiseOnly) {
  const Mesh sphere = make_shape("sphere", 16);
  NoiseOptions no;
  no.sigma = 0.5;
  no.seed = 9;
  const Eigen::MatrixXd gauss = add_noise(sphere.V, sphere.F, no);
  no.impulsive_fraction = 0.2;
  const Eigen::MatrixXd spiky = add_noise(sphere.V, sphere.F, no);
  const ResolvedPreset g = resolve_preset("auto", gauss, sphere.F);
  EXPECT_FALSE(g.despiked);
  EXPECT_EQ(g.options.despike_threshold, 0);
  EXPECT_EQ(g.reason().find("despiked"), std::string::npos) << g.reason();
  const ResolvedPreset s = resolve_preset("auto", spiky, sphere.F);
  EXPECT_TRUE(s.despiked) << s.reason();
  EXPECT_GT(s.options.despike_threshold, 0);
  EXPECT_GT(s.despiked_fraction, 0.05);
  // The rules take σ from the despiked mesh, which reads far less noisy than the spiky input.
  EXPECT_LT(s.noise_despiked.sigma_rms, 0.7 * s.noise.sigma_rms);
  // The despiked sphere is a featureless surface (docs/presets.md, "Featureless surfaces under
  // impulsive noise"): class cad with the featureless options, σ the despiked mesh's.
  EXPECT_EQ(s.choice.preset, "smooth");
  EXPECT_TRUE(s.featureless) << s.reason();
  EXPECT_EQ(s.preset, "cad");
  EXPECT_EQ(s.options.vertices.omega2, 3);
  EXPECT_DOUBLE_EQ(s.sigma, s.noise_despiked.sigma_rms);
  EXPECT_NE(s.reason().find("despiked at"), std::string::npos) << s.reason();
  EXPECT_NE(s.reason().find("featureless, cad"), std::string::npos) << s.reason();
}

TEST(Presets, AdaptiveOptionsFollowTheNoise) {
  // Less fidelity and more pre-filtering as the noise grows; within the documented limits.
  double last_alpha = 1e300;
  int last_prefilter = -1;
  double last_closeness[2] = {1e300, 1e300};
  for (const double sigma : {0.0, 0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0, 5.0}) {
    for (const char* cls : {"cad", "smooth"}) {
      const DenoiseOptions o = adaptive_options(cls, sigma);
      EXPECT_NO_THROW(o.validate()) << cls << " " << sigma;
      EXPECT_GE(o.normals.alpha, 1.5);
      EXPECT_LE(o.normals.alpha, std::string(cls) == "cad" ? 10.0 : 5.0);
      EXPECT_GE(o.prefilter_iterations, 0);
      EXPECT_LE(o.prefilter_iterations, std::string(cls) == "cad" ? 5 : 10);
      // Everything but α, the pre-filter, the closeness weight, (smooth) the fairness weight and
      // (cad) its share along the surface is the class's preset.
      DenoiseOptions p = preset_options(cls);
      p.normals.alpha = o.normals.alpha;
      p.prefilter_iterations = o.prefilter_iterations;
      EXPECT_LE(o.vertices.omega2, p.vertices.omega2);
      EXPECT_GE(o.vertices.omega2, 0.1 * p.vertices.omega2);
      p.vertices.omega2 = o.vertices.omega2;
      // ω₃ grows as 1/σ² below σ 0.13, up to 3× the class's: never less than the class's, never
      // rising with the noise.
      EXPECT_GE(o.vertices.omega3, p.vertices.omega3) << cls << " " << sigma;
      EXPECT_LE(o.vertices.omega3, 3 * p.vertices.omega3 * (1 + 1e-12)) << cls << " " << sigma;
      double& last = last_closeness[std::string(cls) == "cad" ? 0 : 1];
      EXPECT_LE(o.vertices.omega3, last) << cls << " " << sigma;
      last = o.vertices.omega3;
      p.vertices.omega3 = o.vertices.omega3;
      // The polish (cad only) grows with σ up to preset cad's, never below a quarter of it; its
      // range too, between 0.15 and preset cad's 0.3.
      EXPECT_LE(o.normals.polish, p.normals.polish) << cls << " " << sigma;
      EXPECT_GE(o.normals.polish, 0.25 * p.normals.polish) << cls << " " << sigma;
      EXPECT_LE(o.normals.polish_range, p.normals.polish_range) << cls << " " << sigma;
      EXPECT_GE(o.normals.polish_range, std::min(0.15, p.normals.polish_range)) << cls << " " << sigma;
      p.normals.polish = o.normals.polish;
      p.normals.polish_range = o.normals.polish_range;
      // The fairness along the surface (cad only): 0.15 up to σ 0.08, the whole term from 0.12.
      EXPECT_LE(o.vertices.fairness_tangential, 1.0) << cls << " " << sigma;
      EXPECT_GE(o.vertices.fairness_tangential, std::string(cls) == "cad" ? 0.15 : 1.0) << cls << " " << sigma;
      p.vertices.fairness_tangential = o.vertices.fairness_tangential;
      expect_same_parameters(denoise_parameters(), o, p, std::string(cls) + " at " + std::to_string(sigma));
    }
    const DenoiseOptions o = adaptive_options("cad", sigma);
    EXPECT_LE(o.normals.alpha, last_alpha) << sigma;
    EXPECT_GE(o.prefilter_iterations, last_prefilter) << sigma;
    last_alpha = o.normals.alpha;
    last_prefilter = o.prefilter_iterations;
  }
  EXPECT_EQ(adaptive_options("cad", 0.05).prefilter_iterations, 0);  // low noise: the input's own normals
  // The class smooth pre-filters more: round(40 (σ − 0.1)) passes, at most 10 (cad: 8 (σ − 0.1), 5).
  EXPECT_EQ(adaptive_options("smooth", 0.1).prefilter_iterations, 0);
  EXPECT_EQ(adaptive_options("smooth", 0.2).prefilter_iterations, 4);
  EXPECT_EQ(adaptive_options("cad", 0.2).prefilter_iterations, 1);
  EXPECT_EQ(adaptive_options("smooth", 0.3).prefilter_iterations, 8);
  EXPECT_EQ(adaptive_options("smooth", 0.7).prefilter_iterations, 10);
  EXPECT_EQ(adaptive_options("cad", 0.7).prefilter_iterations, 5);
  EXPECT_LT(adaptive_options("smooth", 0.1).vertices.omega2, adaptive_options("smooth", 0.5).vertices.omega2);
  EXPECT_EQ(adaptive_options("cad", 0.1).vertices.omega2, preset_options("cad").vertices.omega2);
  EXPECT_EQ(adaptive_options("cad", 0.05).vertices.fairness_tangential, 0.15);
  EXPECT_NEAR(adaptive_options("cad", 0.1).vertices.fairness_tangential, 0.575, 1e-12);
  EXPECT_EQ(adaptive_options("cad", 0.12).vertices.fairness_tangential, 1.0);
  EXPECT_EQ(preset_options("cad").vertices.fairness_tangential, 1.0);
  EXPECT_EQ(preset_options("paper").vertices.fairness_tangential, 1.0);
  for (const char* cls : {"cad", "smooth"}) {
    const double omega3 = preset_options(cls).vertices.omega3;
    EXPECT_DOUBLE_EQ(adaptive_options(cls, 0.0).vertices.omega3, 3 * omega3) << cls;       // clean: the most closeness
    EXPECT_DOUBLE_EQ(adaptive_options(cls, 0.05).vertices.omega3, 3 * omega3) << cls;      // capped below σ 0.075
    EXPECT_NEAR(adaptive_options(cls, 0.1).vertices.omega3, 1.69 * omega3, 1e-12) << cls;  // (0.13 / 0.1)²
    EXPECT_DOUBLE_EQ(adaptive_options(cls, 0.13).vertices.omega3, omega3) << cls;
    EXPECT_DOUBLE_EQ(adaptive_options(cls, 0.5).vertices.omega3, omega3) << cls;  // the class's from σ 0.13 up
  }
  EXPECT_GT(adaptive_options("cad", 0.6).prefilter_iterations, 0);
  // The polish: the full one from σ 0.2, a quarter below σ 0.05, none for the class smooth.
  EXPECT_DOUBLE_EQ(adaptive_options("cad", 0.3).normals.polish, preset_options("cad").normals.polish);
  EXPECT_DOUBLE_EQ(adaptive_options("cad", 0.3).normals.polish_range, 0.3);
  EXPECT_DOUBLE_EQ(adaptive_options("cad", 0.1).normals.polish, 0.5 * preset_options("cad").normals.polish);
  EXPECT_DOUBLE_EQ(adaptive_options("cad", 0.1).normals.polish_range, 0.15);
  EXPECT_DOUBLE_EQ(adaptive_options("cad", 0.0).normals.polish, 0.25 * preset_options("cad").normals.polish);
  EXPECT_EQ(adaptive_options("smooth", 0.3).normals.polish, 0.0);
  EXPECT_EQ(preset_options("paper").normals.polish, 0.0);
  // The shape's own detail raises the closeness of the class smooth by 1 + 3 (d/σ)², at most 10×,
  // and changes nothing else; the class cad ignores it (its detail is its creases).
  const DenoiseOptions plain = adaptive_options("smooth", 0.2);
  DenoiseOptions kept = adaptive_options("smooth", 0.2, 0.1);
  EXPECT_NEAR(kept.vertices.omega3, plain.vertices.omega3 * (1 + 3 * 0.25), 1e-12);
  kept.vertices.omega3 = plain.vertices.omega3;
  expect_same_parameters(denoise_parameters(), kept, plain, "detail");
  EXPECT_NEAR(adaptive_options("smooth", 0.0, 0.1).vertices.omega3,
              10 * adaptive_options("smooth", 0.0).vertices.omega3, 1e-12);
  expect_same_parameters(denoise_parameters(), adaptive_options("cad", 0.2, 0.1), adaptive_options("cad", 0.2), "cad");
  EXPECT_THROW(adaptive_options("organic", 0.3), InvalidInput);
  EXPECT_THROW(adaptive_options("cad", -1), InvalidInput);
  EXPECT_THROW(adaptive_options("smooth", 0.3, -0.1), InvalidInput);
}

TEST(Presets, StrengthScalesWhatIsRemoved) {
  const Mesh part = make_shape("fandisk", 8);
  const ResolvedPreset one = resolve_preset("auto", part.V, part.F);
  const ResolvedPreset more = resolve_preset("auto", part.V, part.F, 4.0);
  EXPECT_DOUBLE_EQ(more.sigma, 4.0 * one.sigma);
  EXPECT_LE(more.options.normals.alpha, one.options.normals.alpha);
  EXPECT_NE(more.reason().find("strength 4.00"), std::string::npos) << more.reason();
  const ResolvedPreset cad2 = resolve_preset("cad", part.V, part.F, 2.0);
  EXPECT_DOUBLE_EQ(cad2.options.normals.alpha, preset_options("cad").normals.alpha / 2);
  EXPECT_EQ(cad2.reason(), "requested, strength 2.00");
  EXPECT_THROW(resolve_preset("auto", part.V, part.F, 0.0), InvalidInput);
  EXPECT_THROW(resolve_preset("auto", part.V, part.F, 11.0), InvalidInput);
  EXPECT_THROW(resolve_preset("cad", part.V, part.F, std::nan("")), InvalidInput);
}

TEST(Presets, AutoIsInvariantUnderScaleRotationAndTranslation) {
  const Mesh part = make_shape("fandisk", 8);
  Eigen::Matrix3d R;
  R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized());
  const Eigen::MatrixXd moved = ((part.V * R.transpose()) * 1e3).rowwise() + Eigen::RowVector3d(5, -7, 9);
  const PresetChoice a = choose_preset(part.V, part.F), b = choose_preset(moved, part.F);
  EXPECT_EQ(a.preset, b.preset);
  EXPECT_NEAR(a.sharp_fraction, b.sharp_fraction, 1e-9);
  EXPECT_NEAR(a.crease_line_fraction, b.crease_line_fraction, 1e-9);
  EXPECT_NEAR(a.flat_fraction, b.flat_fraction, 1e-9);
}

TEST(Presets, SteepCreaseLinesMakeAPartCad) {
  // A capped cylinder: its two rims are its only creases (90°), too little of its edge length
  // for the crease-line rule (< 0.03) and its caps too little for the flat rule, but all of
  // them steep: class cad. A torus has none; a noisy one stays smooth by the shape rule.
  const Mesh cylinder = make_shape("cylinder", 32);
  for (const double sigma : {0.0, 0.1, 0.3}) {
    NoiseOptions no;
    no.sigma = sigma;
    no.seed = 4;
    const PresetChoice c = choose_preset(sigma > 0 ? add_noise(cylinder.V, cylinder.F, no) : cylinder.V, cylinder.F);
    EXPECT_LT(c.crease_line_fraction, 0.03) << c.reason;
    EXPECT_LT(c.flat_fraction, 0.5) << c.reason;
    EXPECT_GE(c.steep_line_fraction, 0.012) << c.reason;
    EXPECT_LE(c.steep_line_fraction, c.crease_line_fraction) << c.reason;
    EXPECT_EQ(c.preset, "cad") << "sigma " << sigma << ": " << c.reason;
    EXPECT_NE(c.reason.find("steeper than 60 deg"), std::string::npos) << c.reason;
  }
  const Mesh torus = make_shape("torus", 32);
  NoiseOptions no;
  no.sigma = 0.1;
  no.seed = 4;
  const PresetChoice t = choose_preset(add_noise(torus.V, torus.F, no), torus.F);
  EXPECT_EQ(t.steep_line_fraction, 0) << t.reason;
  EXPECT_EQ(t.preset, "smooth") << t.reason;
}

TEST(Presets, AutoDoesNotMeasureTheComponentsDenoiseKeeps) {
  // A noisy sphere and a cube of 12 triangles beside it: the low pass would read the cube's own
  // shape as noise (σ_rms ~1 where the sphere reads ~0.1); auto measures the sphere alone.
  const Mesh sphere = test::noisy(make_shape("sphere", 12), 0.002, 5);
  const Mesh both = test::join(sphere, make_cube(1), Eigen::RowVector3d(3, 0, 0));
  const ResolvedPreset alone = resolve_preset("auto", sphere.V, sphere.F);
  const ResolvedPreset r = resolve_preset("auto", both.V, both.F);
  EXPECT_EQ(r.unmeasured_faces, 12);
  EXPECT_EQ(r.unmeasured_components, 1);
  EXPECT_EQ(alone.unmeasured_faces, 0);
  EXPECT_NEAR(r.noise.sigma_rms, alone.noise.sigma_rms, 1e-9);  // (the sphere's vertices renumbered)
  EXPECT_EQ(r.preset, alone.preset);
  expect_same_parameters(denoise_parameters(), r.options, alone.options, "sphere + cube against the sphere");
  EXPECT_NE(r.reason().find("without the 12 faces of 1 component(s) of fewer than 40 faces"), std::string::npos)
      << r.reason();
  // Measured whole, the cube would have been read as heavy noise.
  EXPECT_GT(estimate_noise(both.V, both.F).sigma_rms, 3 * alone.noise.sigma_rms);
}

TEST(Presets, LargeMeshesAreMeasuredOnASampleWithTheSameFigures) {
  // 491K faces (above the sampling size): the noise estimate and the shape figures of the
  // patch sample agree with those of the whole mesh, and the reason says what was measured.
  Mesh m = make_torus(640, 384);
  NoiseOptions no;
  no.sigma = 0.3;
  no.seed = 3;
  m.V = add_noise(m.V, m.F, no);
  const ResolvedPreset r = resolve_preset("auto", m.V, m.F);
  ASSERT_GT(r.sample_faces, 50000);
  EXPECT_LE(r.sample_faces, 32 * 6000);  // 32 patches of 6000 faces
  EXPECT_EQ(r.sample_patches, 32);
  EXPECT_NE(r.reason().find("measured on " + std::to_string(r.sample_faces) + " faces of 32 patches"),
            std::string::npos)
      << r.reason();
  const NoiseEstimate whole = estimate_noise(m.V, m.F);
  EXPECT_NEAR(r.noise.sigma, whole.sigma, 0.03 * whole.sigma);
  EXPECT_NEAR(r.noise.sigma_rms, whole.sigma_rms, 0.03 * whole.sigma_rms);
  TaubinOptions to;
  to.iterations = r.options.prefilter_iterations;
  const PresetChoice c = choose_preset(taubin_smooth(m.V, m.F, to), m.F);
  EXPECT_EQ(r.preset, c.preset);
  EXPECT_NEAR(r.choice.flat_fraction, c.flat_fraction, 0.03);
  EXPECT_NEAR(r.choice.sharp_fraction, c.sharp_fraction, 0.01);
  // A small mesh is measured whole.
  const Mesh part = make_shape("fandisk", 8);
  EXPECT_EQ(resolve_preset("auto", part.V, part.F).sample_faces, 0);
}

TEST(Presets, FidelityCapIsTenForCadFiveForSmoothAndForScanLikeMeshes) {
  // α = 0.75 / σ between the class's bounds: cad up to 10 (a CAD part's tessellation is kept at
  // low noise), smooth up to 5; an explicit cap (resolve_preset gives 5 to scan-like cad meshes)
  // lowers it, never below the class's minimum.
  EXPECT_DOUBLE_EQ(adaptive_options("cad", 0.05).normals.alpha, 10.0);
  EXPECT_DOUBLE_EQ(adaptive_options("cad", 0.1).normals.alpha, 7.5);
  EXPECT_DOUBLE_EQ(adaptive_options("cad", 0.0).normals.alpha, 10.0);
  EXPECT_DOUBLE_EQ(adaptive_options("smooth", 0.05).normals.alpha, 5.0);
  EXPECT_DOUBLE_EQ(adaptive_options("cad", 0.05, 0, 5.0).normals.alpha, 5.0);
  EXPECT_DOUBLE_EQ(adaptive_options("cad", 0.5, 0, 5.0).normals.alpha, 2.0);
  EXPECT_DOUBLE_EQ(adaptive_options("cad", 0.05, 0, 1.0).normals.alpha, 2.0);  // the class's minimum
  EXPECT_THROW(adaptive_options("cad", 0.05, 0, -1.0), InvalidInput);
  // A CAD part with creases at low noise is not scan-like and gets more fidelity than 5.
  Mesh fandisk = make_shape("fandisk", 24);
  NoiseOptions no;
  no.sigma = 0.05;  // mean edge lengths, along the normals
  fandisk.V = add_noise(fandisk.V, fandisk.F, no);
  const ResolvedPreset r = resolve_preset("auto", fandisk.V, fandisk.F);
  ASSERT_EQ(r.preset, "cad") << r.reason();
  EXPECT_FALSE(r.scan_like) << r.reason();
  EXPECT_GT(r.options.normals.alpha, 5.0) << r.reason();
}

TEST(Presets, TheKinectConeIsScanLikeAndCountsItsDetailAsNoise) {
  // The meshtgv Cone (a Kinect scan): classed cad by its flat areas (crease fraction 0.002),
  // the estimate reads more detail (0.070) than noise (0.035), σ_rms 0.097: α 0.75/σ_rms would be
  // 7.7 (MSAE 67.9). Scan-like, its correlated noise is counted by the detail too, 3 times:
  // σ = √(σ_rms² + 8 detail²) ≈ 0.22, α ≈ 3.4 (MSAE 57.1; 63.1 at α 5), and the reason says so.
  MSMESH_REQUIRE_SHARED(path, "meshtgv_liu2021/cone/noisy.obj");
  const Mesh cone = read_mesh(path);
  const ResolvedPreset r = resolve_preset("auto", cone.V, cone.F);
  EXPECT_EQ(r.preset, "cad");
  EXPECT_TRUE(r.scan_like) << r.reason();
  EXPECT_FALSE(r.despiked) << r.reason();
  const double rms = r.noise.sigma_rms, d = r.noise.detail;
  EXPECT_GT(d, r.noise.sigma_noise);
  EXPECT_DOUBLE_EQ(r.detail_as_noise, 1.0);
  EXPECT_NEAR(r.sigma, std::sqrt(rms * rms + 8 * d * d), 1e-12);
  EXPECT_DOUBLE_EQ(r.options.normals.alpha, adaptive_options("cad", r.sigma, 0, 5.0).normals.alpha);
  EXPECT_LT(r.options.normals.alpha, 4.0) << r.reason();
  EXPECT_NE(r.reason().find("scan-like"), std::string::npos) << r.reason();
  EXPECT_NE(r.reason().find("detail counted 3.00 times"), std::string::npos) << r.reason();
}

TEST(Presets, CorrelatedNoiseOnAFlatPartIsScanLikeAndSmoothedMore) {
  // Not from ../shared: msmesh's own pyramid with correlated noise (σ 0.2, averaged over 2 rings),
  // which the low pass reads mostly as detail. Scan-like, σ counts the detail 3 times, and the
  // result is better than with σ_rms alone at the scan-like cap (what auto did before; measured
  // 2.68 -> 1.64 MSAE x1e-3; docs/presets.md, "Correlated noise").
  const Mesh clean = make_shape("pyramid", 24);
  NoiseOptions no;
  no.sigma = 0.2;
  no.correlation = 2;
  no.seed = 11;
  const Eigen::MatrixXd noisy = add_noise(clean.V, clean.F, no);
  const ResolvedPreset r = resolve_preset("auto", noisy, clean.F);
  ASSERT_EQ(r.preset, "cad") << r.reason();
  ASSERT_TRUE(r.scan_like) << r.reason();
  EXPECT_GT(r.sigma, 1.5 * r.noise.sigma_rms) << r.reason();
  DenoiseOptions before = adaptive_options("cad", r.noise.sigma_rms, 0, 5.0);
  const double now = normal_errors(denoise(noisy, clean.F, r.options).V, clean.F, clean.V, clean.F).msae;
  const double then = normal_errors(denoise(noisy, clean.F, before).V, clean.F, clean.V, clean.F).msae;
  EXPECT_LT(now, 0.8 * then) << now << " " << then;
  // White noise of the same σ on the same part is not scan-like and keeps σ_rms.
  no.correlation = 0;
  const Eigen::MatrixXd white = add_noise(clean.V, clean.F, no);
  const ResolvedPreset w = resolve_preset("auto", white, clean.F);
  EXPECT_FALSE(w.scan_like) << w.reason();
  EXPECT_DOUBLE_EQ(w.detail_as_noise, 0.0) << w.reason();
  EXPECT_DOUBLE_EQ(w.sigma, w.noise.sigma_rms) << w.reason();
}

TEST(Presets, TheKinectPyramidCountsPartOfItsDetailAsNoise) {
  // The meshtgv pyramid (a Kinect scan): few creases (0.009), detail 0.106 against noise alone
  // 0.151 - not scan-like, but more than half as much detail as noise: weight (0.70 - 0.5) / 0.5
  // = 0.40 of the 3 times, σ = √(σ_rms² + 8 × 0.40 d²) ≈ 0.28 (MSAE 61.8 -> 53.8).
  MSMESH_REQUIRE_SHARED(path, "meshtgv_liu2021/pyramid/noisy.obj");
  const Mesh pyramid = read_mesh(path);
  const ResolvedPreset r = resolve_preset("auto", pyramid.V, pyramid.F);
  ASSERT_EQ(r.preset, "cad") << r.reason();
  EXPECT_FALSE(r.scan_like) << r.reason();
  const double rms = r.noise.sigma_rms, d = r.noise.detail, n = r.noise.sigma_noise;
  EXPECT_NEAR(r.detail_as_noise, (d / n - 0.5) / 0.5, 1e-12);
  EXPECT_GT(r.detail_as_noise, 0.2);
  EXPECT_LT(r.detail_as_noise, 0.6);
  EXPECT_NEAR(r.sigma, std::sqrt(rms * rms + 8 * r.detail_as_noise * d * d), 1e-12);
  // A stronger run scales all of it.
  EXPECT_NEAR(resolve_preset("auto", pyramid.V, pyramid.F, 2.0).sigma, 2 * r.sigma, 1e-12);
}

TEST(Presets, DetailThatStandsOutOfTheNoiseEasesTheRules) {
  // A sphere with fine waves of its own (12 plane waves 2.5 mean edges long, RMS 0.25 mean
  // edges, along the normals) under σ 0.15: the class smooth reads detail well above its doubt,
  // every rule takes a lower σ, and the result keeps more of the waves than at the σ without
  // the ease (strength = the ease undoes it). The plain sphere with the same noise is not eased.
  const Mesh sphere = make_shape("sphere", 24);
  const Eigen::MatrixXd detailed = wavy_sphere(sphere);
  NoiseOptions no;
  no.sigma = 0.15;
  no.seed = 3;
  const Eigen::MatrixXd noisy = add_noise(detailed, sphere.F, no);
  const ResolvedPreset eased = resolve_preset("auto", noisy, sphere.F);
  ASSERT_EQ(eased.preset, "smooth") << eased.reason();
  EXPECT_GT(eased.detail_ease, 1.5) << eased.reason();
  EXPECT_NE(eased.reason().find("x for the detail"), std::string::npos) << eased.reason();
  const ResolvedPreset undone = resolve_preset("auto", noisy, sphere.F, eased.detail_ease);
  EXPECT_NEAR(undone.sigma, eased.detail_ease * eased.sigma, 1e-12);
  const double e_eased = normal_errors(denoise(noisy, sphere.F, eased.options).V, sphere.F, detailed, sphere.F).msae;
  const double e_undone = normal_errors(denoise(noisy, sphere.F, undone.options).V, sphere.F, detailed, sphere.F).msae;
  EXPECT_LT(e_eased, 0.8 * e_undone) << e_undone << " -> " << e_eased;

  const ResolvedPreset plain = resolve_preset("auto", add_noise(sphere.V, sphere.F, no), sphere.F);
  EXPECT_EQ(plain.detail_ease, 1.0) << plain.reason();
  EXPECT_EQ(plain.reason().find("x for the detail"), std::string::npos) << plain.reason();
}

TEST(Presets, HeavyNoiseAcrossTheNormalsRaisesAPartsFairness) {
  // A CAD part under heavy noise in random directions: the class cad's fairness ω₂ rises from
  // 0.03 to 0.1 (σ_rms ≥ 0.4), and the summary says why; the same σ along the normals, or a
  // lighter noise, keep 0.03.
  const Mesh m = make_shape("fandisk", 24);
  const auto resolved = [&](double sigma, NoiseDirection d) {
    NoiseOptions no;
    no.sigma = sigma;
    no.direction = d;
    no.seed = 3;
    return resolve_preset("auto", add_noise(m.V, m.F, no), m.F);
  };
  const ResolvedPreset random = resolved(0.7, NoiseDirection::Random);
  ASSERT_EQ(random.preset, "cad") << random.reason();
  ASSERT_GE(random.noise.sigma_rms, 0.4) << random.reason();
  EXPECT_NEAR(random.options.vertices.omega2, 0.1, 1e-12) << random.reason();
  EXPECT_NE(random.reason().find("noise across the normals"), std::string::npos) << random.reason();
  const ResolvedPreset along = resolved(0.7, NoiseDirection::Normal);
  ASSERT_EQ(along.preset, "cad") << along.reason();
  EXPECT_EQ(along.options.vertices.omega2, preset_options("cad").vertices.omega2) << along.reason();
  EXPECT_EQ(along.reason().find("noise across the normals"), std::string::npos) << along.reason();
  const ResolvedPreset light = resolved(0.2, NoiseDirection::Random);
  ASSERT_LT(light.noise.sigma_rms, 0.25) << light.reason();
  EXPECT_EQ(light.options.vertices.omega2, preset_options("cad").vertices.omega2) << light.reason();
}

TEST(Presets, ModerateNoiseAlongTheNormalsOfAnOrganicShapeKeepsItsTrianglesInPlace) {
  // The wavy sphere (class smooth) under σ 0.3 along the normals: the fairness acts mostly
  // along the normals (τ well below 1), the summary says why, and the result keeps more of the
  // waves than with the whole fairness term; the same surface under noise in random directions
  // of about the same σ_rms keeps τ 1.
  const Mesh sphere = make_shape("sphere", 24);
  const Eigen::MatrixXd detailed = wavy_sphere(sphere);
  const auto resolved = [&](double sigma, NoiseDirection d) {
    NoiseOptions no;
    no.sigma = sigma;
    no.direction = d;
    no.seed = 5;
    return resolve_preset("auto", add_noise(detailed, sphere.F, no), sphere.F);
  };
  const ResolvedPreset along = resolved(0.3, NoiseDirection::Normal);
  ASSERT_EQ(along.preset, "smooth") << along.reason();
  ASSERT_LT(along.noise.across_ratio, 0.8) << along.reason();
  EXPECT_LT(along.options.vertices.fairness_tangential, 0.5) << along.reason();
  EXPECT_NE(along.reason().find("(noise along the normals"), std::string::npos) << along.reason();
  NoiseOptions no;
  no.sigma = 0.3;
  no.seed = 5;
  const Eigen::MatrixXd noisy = add_noise(detailed, sphere.F, no);
  DenoiseOptions whole = along.options;
  whole.vertices.fairness_tangential = 1;
  const double e_rule = normal_errors(denoise(noisy, sphere.F, along.options).V, sphere.F, detailed, sphere.F).msae;
  const double e_whole = normal_errors(denoise(noisy, sphere.F, whole).V, sphere.F, detailed, sphere.F).msae;
  EXPECT_LT(e_rule, e_whole) << e_whole << " -> " << e_rule;
  const ResolvedPreset random = resolved(0.5, NoiseDirection::Random);
  ASSERT_EQ(random.preset, "smooth") << random.reason();
  ASSERT_GT(random.noise.sigma_rms, 0.25) << random.reason();
  EXPECT_EQ(random.options.vertices.fairness_tangential, 1.0) << random.reason();
}
