// Denoising (denoise.h): invariances, convergence behaviour, the edge field on a noisy cube,
// quality on a noisy cube (issue 3's test targets), and the awkward meshes of
// docs/robustness.md through the library.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/metrics.h"
#include "msmesh/noise.h"
#include "msmesh/presets.h"
#include "msmesh/repair.h"
#include "msmesh/shapes.h"
#include "msmesh/topology.h"
#include "test_helpers.h"

using namespace msmesh;

namespace {

struct NoisyCube {
  Mesh clean;
  Eigen::MatrixXd noisy;
};

NoisyCube noisy_cube(int n = 10, double sigma = 0.2, std::uint64_t seed = 3) {
  NoisyCube c;
  c.clean = make_cube(n);
  NoiseOptions no;
  no.sigma = sigma;
  no.seed = seed;
  c.noisy = add_noise(c.clean.V, c.clean.F, no);
  return c;
}

Eigen::Matrix3d some_rotation() {
  return (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
          Eigen::AngleAxisd(-1.1, Eigen::Vector3d::UnitZ()))
      .toRotationMatrix();
}

}  // namespace

TEST(Denoise, NoisyCubeWithinTwoDegreesOfClean) {
  const NoisyCube c = noisy_cube(12, 0.2);
  const DenoiseResult r = denoise(c.noisy, c.clean.F, preset_options("cad"));
  const NormalErrors before = normal_errors(c.noisy, c.clean.F, c.clean.V, c.clean.F);
  const NormalErrors after = normal_errors(r.V, c.clean.F, c.clean.V, c.clean.F);
  EXPECT_GT(before.mean_angle_deg, 8.0);  // the noise is real
  EXPECT_LT(after.mean_angle_deg, 2.0);
  EXPECT_EQ(after.flipped, 0);
}

TEST(Denoise, PrefilteredFirstNormalsHelpUnderHeavyNoise) {
  // σ = 0.6: the input's face normals are ~40° off; a few Taubin passes before N⁰ is taken
  // make the first normals usable (docs/presets.md). The vertex update still starts from the input.
  const NoisyCube c = noisy_cube(10, 0.6, 5);
  DenoiseOptions plain;
  DenoiseOptions pre = plain;
  pre.prefilter_iterations = 4;
  const double e_plain = normal_errors(denoise(c.noisy, c.clean.F, plain).V, c.clean.F, c.clean.V, c.clean.F).msae;
  const double e_pre = normal_errors(denoise(c.noisy, c.clean.F, pre).V, c.clean.F, c.clean.V, c.clean.F).msae;
  EXPECT_LT(e_pre, 0.8 * e_plain) << e_plain << " -> " << e_pre;
  DenoiseOptions bad;
  bad.prefilter_iterations = -1;
  EXPECT_THROW(denoise(c.noisy, c.clean.F, bad), InvalidInput);
}

TEST(Denoise, DespikingHelpsUnderImpulsiveNoise) {
  // A fifth of the vertices displaced along the normals (impulsive noise): moving the spikes
  // back first (despike.h) gives better normals than filtering them (docs/presets.md).
  const Mesh sphere = make_shape("sphere", 16);
  NoiseOptions no;
  no.sigma = 0.5;
  no.impulsive_fraction = 0.2;
  no.seed = 3;
  const Eigen::MatrixXd noisy = add_noise(sphere.V, sphere.F, no);
  DenoiseOptions plain = preset_options("smooth");
  DenoiseOptions spikes = plain;
  spikes.despike_threshold = 3;
  const DenoiseResult a = denoise(noisy, sphere.F, plain), b = denoise(noisy, sphere.F, spikes);
  EXPECT_EQ(a.despiked_vertices, 0);
  EXPECT_GT(b.despiked_vertices, sphere.V.rows() / 20);
  const double e_plain = normal_errors(a.V, sphere.F, sphere.V, sphere.F).msae;
  const double e_spikes = normal_errors(b.V, sphere.F, sphere.V, sphere.F).msae;
  EXPECT_LT(e_spikes, 0.8 * e_plain) << e_plain << " -> " << e_spikes;
  DenoiseOptions bad;
  bad.despike_threshold = -1;
  EXPECT_THROW(denoise(noisy, sphere.F, bad), InvalidInput);
}

TEST(Denoise, InvariantUnderScaleRotationTranslation) {
  const NoisyCube c = noisy_cube(8, 0.25);
  const DenoiseOptions o = preset_options("cad");
  const DenoiseResult r0 = denoise(c.noisy, c.clean.F, o);
  const Eigen::Matrix3d R = some_rotation();
  const double s = 1234.5;
  const Eigen::RowVector3d t(1e3, -2e4, 5e2);
  const Eigen::MatrixXd X = ((s * c.noisy * R.transpose()).rowwise() + t).eval();
  const DenoiseResult r1 = denoise(X, c.clean.F, o);
  const Eigen::MatrixXd back = ((r1.V.rowwise() - t) / s) * R;  // undo: R orthogonal
  EXPECT_LT((back - r0.V).cwiseAbs().maxCoeff(), 1e-7);
  EXPECT_LT((r1.v - r0.v).cwiseAbs().maxCoeff(), 1e-7);
  EXPECT_LT((r1.normals * R - r0.normals).cwiseAbs().maxCoeff(), 1e-7);
}

TEST(Denoise, ResidualRisesThenFallsAndEnergyDrops) {
  // DESIGN.md step 4: ‖p − ∇N‖ starts at 0 (v⁰ = 0: no shrinkage), rises, then falls and
  // plateaus; it must stay bounded. The energy (15) ends below its peak.
  const NoisyCube c = noisy_cube(10, 0.3);
  NormalFilterOptions o = preset_options("cad").normals;
  o.tolerance = 0;
  o.record_energy = true;
  const NormalFilterResult r = filter_normals(c.noisy, c.clean.F, o);
  ASSERT_EQ(r.iterations, o.max_iterations);
  const auto& h = r.residual_history;
  const double peak = *std::max_element(h.begin(), h.end());
  EXPECT_TRUE(std::isfinite(peak));
  EXPECT_LT(h.back(), peak);
  const auto& e = r.energy_history;
  EXPECT_LT(e.back(), *std::max_element(e.begin(), e.end()));
  // The normals settle: the last change is far below the first.
  EXPECT_LT(r.change_history.back(), 0.2 * r.change_history.front());
}

TEST(Denoise, EdgeFieldLowOnCreasesHighOnFlatFaces) {
  const NoisyCube c = noisy_cube(10, 0.2);
  const NormalFilterResult r = filter_normals(c.noisy, c.clean.F, preset_options("cad").normals);
  const Topology t = build_topology(c.clean.F, c.clean.V.rows());
  const Eigen::VectorXd dihedral = dihedral_angles(c.clean.V, c.clean.F, t);
  // The paper normalises v to [0, 1] before using it (§6.3).
  const double lo = r.v.minCoeff(), hi = r.v.maxCoeff();
  ASSERT_GT(hi - lo, 1e-6);
  double crease = 0, flat = 0;
  int nc = 0, nflat = 0;
  for (Eigen::Index e = 0; e < t.num_edges(); ++e) {
    const double vn = (r.v(e) - lo) / (hi - lo);
    if (dihedral(e) > M_PI / 4) {
      crease += vn;
      ++nc;
    } else {
      flat += vn;
      ++nflat;
    }
  }
  ASSERT_GT(nc, 0);
  EXPECT_LT(crease / nc, 0.35);
  EXPECT_GT(flat / nflat, 0.9);
}

TEST(Denoise, MstvIsTheSameLoopWithoutReweighting) {
  const NoisyCube c = noisy_cube(8, 0.2);
  DenoiseOptions o = preset_options("cad");
  o.plane_min_faces = 0;  // both loops' normals as they come (the planar regions would make both the cube's)
  o.method = DenoiseMethod::MSTV;
  const DenoiseResult mstv = denoise(c.noisy, c.clean.F, o);
  o.method = DenoiseMethod::NMSTV;
  const DenoiseResult nmstv = denoise(c.noisy, c.clean.F, o);
  EXPECT_GT((mstv.normals - nmstv.normals).norm(), 1e-3);
  // Both denoise.
  const double noisy_err = normal_errors(c.noisy, c.clean.F, c.clean.V, c.clean.F).msae;
  EXPECT_LT(normal_errors(mstv.V, c.clean.F, c.clean.V, c.clean.F).msae, 0.2 * noisy_err);
}

TEST(Denoise, BilateralBaselineDenoises) {
  const NoisyCube c = noisy_cube(10, 0.2);
  DenoiseOptions o;
  o.method = DenoiseMethod::Bilateral;
  const DenoiseResult r = denoise(c.noisy, c.clean.F, o);
  const double before = normal_errors(c.noisy, c.clean.F, c.clean.V, c.clean.F).msae;
  EXPECT_LT(normal_errors(r.V, c.clean.F, c.clean.V, c.clean.F).msae, 0.3 * before);
}

TEST(Denoise, VertexUpdateFallbackAvoidsFlips) {
  // Target normals opposite to a face's current normal trigger the degenerate projection
  // (eq. 25) and the face must not end up inverted with respect to its neighbours' targets.
  const NoisyCube c = noisy_cube(8, 0.2);
  const DenoiseResult r = denoise(c.noisy, c.clean.F, preset_options("cad"));
  EXPECT_EQ(normal_errors(r.V, c.clean.F, c.clean.V, c.clean.F).flipped, 0);
}

TEST(Denoise, RejectsBadParametersWithTheirRange) {
  const Mesh m = make_cube(2);
  DenoiseOptions o = preset_options("cad");
  o.normals.alpha = -1;
  try {
    denoise(m.V, m.F, o);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("alpha"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("> 0"), std::string::npos);
  }
  o = preset_options("cad");
  o.normals.relaxation = 2.0;
  EXPECT_THROW(denoise(m.V, m.F, o), InvalidInput);
  o = preset_options("cad");
  o.vertices.omega3 = 0;
  EXPECT_THROW(denoise(m.V, m.F, o), InvalidInput);
  EXPECT_THROW(preset_options("nonsense"), InvalidInput);
}

TEST(Denoise, ProgressIsReportedAndCanCancel) {
  const Mesh m = make_cube(4);
  int calls = 0;
  denoise(m.V, m.F, preset_options("cad"), [&](const ProgressEvent&) {
    ++calls;
    return true;
  });
  EXPECT_GT(calls, 2);
  EXPECT_THROW(denoise(m.V, m.F, preset_options("cad"), [](const ProgressEvent&) { return false; }), Cancelled);
}

// ---------------------------------------------------------------------------------------------
// Awkward but valid meshes (docs/robustness.md, "Awkward meshes"): processed, nothing lost.
// The same meshes through `msmesh denoise`: cli/test_denoise_cli.cpp (AwkwardMeshesCli.*).

namespace {

// A sphere of 1280 faces and, beside it, a cube of 12 triangles (the volgallery cubesphere's
// situation), both noisy.
Mesh sphere_beside_a_small_cube() {
  const Mesh sphere = make_sphere(3), cube = make_cube(1);
  return test::noisy(test::join(sphere, cube, Eigen::RowVector3d(4, 0, 0)), 0.02, 7);
}

/// Denoising through the library must keep #V, F and order, and give finite positions. Every
/// component is denoised (some of these meshes are smaller than min_component_faces).
DenoiseResult denoise_checked(const Mesh& m, const std::string& preset = "cad") {
  DenoiseOptions o = preset_options(preset);
  o.min_component_faces = 0;
  const DenoiseResult r = denoise(m.V, m.F, o);
  EXPECT_EQ(r.V.rows(), m.V.rows());
  EXPECT_TRUE(r.V.allFinite());
  return r;
}

}  // namespace

TEST(Denoise, SmallComponentsAreKeptAsTheyAre) {
  const Mesh m = sphere_beside_a_small_cube();
  const Eigen::Index ns = make_sphere(3).V.rows(), fs = make_sphere(3).F.rows();
  const DenoiseOptions o = preset_options("cad");
  ASSERT_EQ(o.min_component_faces, 40);
  const DenoiseResult r = denoise(m.V, m.F, o);
  EXPECT_EQ(r.kept_components, 1);
  EXPECT_EQ(r.kept_faces, 12);
  // The cube's vertices and face normals as they were, its edges no feature.
  EXPECT_EQ(r.V.bottomRows(8), m.V.bottomRows(8));
  EXPECT_EQ(r.normals.bottomRows(12), face_normals(m.V, m.F).bottomRows(12));
  const Topology topo = build_topology(m.F, m.V.rows());
  ASSERT_EQ(r.v.size(), topo.num_edges());
  ASSERT_EQ(r.edges.rows(), topo.num_edges());
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e)
    if (r.edges(e, 0) >= ns) EXPECT_EQ(r.v(e), 1.0) << "edge " << e;
  // The sphere as denoised alone (to round-off: the part's vertices are renumbered in order of
  // first use).
  const DenoiseResult alone = denoise(m.V.topRows(ns), m.F.topRows(fs), o);
  EXPECT_LT((r.V.topRows(ns) - alone.V).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((r.normals.topRows(fs) - alone.normals).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_EQ(r.normal_report.iterations, alone.normal_report.iterations);
  // With the rule off (the paper's way) the cube is denoised too.
  DenoiseOptions every = o;
  every.min_component_faces = 0;
  const DenoiseResult all = denoise(m.V, m.F, every);
  EXPECT_EQ(all.kept_faces, 0);
  EXPECT_GT((all.V.bottomRows(8) - m.V.bottomRows(8)).norm(), 1e-3);
  EXPECT_EQ(preset_options("paper").min_component_faces, 0);
  // A mesh of small components only comes back as it is.
  const Mesh cube = test::noisy(make_cube(1), 0.02, 3);
  const DenoiseResult kept = denoise(cube.V, cube.F, o);
  EXPECT_EQ(kept.V, cube.V);
  EXPECT_EQ(kept.kept_faces, 12);
  EXPECT_EQ(kept.normal_report.iterations, 0);
}

TEST(AwkwardMeshes, NonManifoldEdgeIsDenoisedWithoutNaN) {
  Mesh m = test::fin();
  denoise_checked(m);
  denoise_checked(m, "smooth");
}

TEST(AwkwardMeshes, NonManifoldVertexIsDenoisedWithoutNaN) {
  const Mesh m = test::bow_tie_tetrahedra();
  const TopologySummary s = summarize_topology(m.F, build_topology(m.F, m.V.rows()));
  EXPECT_EQ(s.non_manifold_vertices, 1);
  const DenoiseResult r = denoise_checked(test::noisy(m, 0.02));
}

TEST(AwkwardMeshes, DuplicateFacesAreDenoisedWithoutNaN) {
  const Mesh dup = test::grid_with_duplicate_faces();
  denoise_checked(test::noisy(dup, 0.01));
  denoise_checked(test::noisy(dup, 0.01), "smooth");
}

TEST(AwkwardMeshes, ZeroAreaFacesAreDenoisedWithoutNaN) {
  const Mesh m = test::grid_with_zero_area_faces();
  for (const std::string preset : {"cad", "smooth"}) denoise_checked(m, preset);
  DenoiseOptions bil = preset_options("cad");
  bil.method = DenoiseMethod::Bilateral;
  EXPECT_TRUE(denoise(m.V, m.F, bil).V.allFinite());
}

TEST(AwkwardMeshes, UnreferencedVerticesStayInPlaceAndInOrder) {
  const Mesh m = test::grid_with_unreferenced_vertices();
  const Eigen::Index n = m.V.rows() - 3;
  const DenoiseResult r = denoise_checked(m);
  for (Eigen::Index i : {Eigen::Index(0), 1 + n / 2, n + 2}) EXPECT_EQ(r.V.row(i), m.V.row(i)) << "vertex " << i;
}

TEST(AwkwardMeshes, InconsistentOrientationIsDenoisedWithoutNaNAndRepaired) {
  const Mesh m = test::grid_with_flipped_faces();
  EXPECT_GT(summarize_topology(m.F, build_topology(m.F, m.V.rows())).inconsistently_oriented_edges, 0);
  denoise_checked(m);
  Mesh fixed = m;
  const RepairReport rep = repair_mesh(fixed);
  EXPECT_EQ(rep.flipped_faces, (m.F.rows() + 2) / 3);  // the first face sets the orientation
  EXPECT_EQ(summarize_topology(fixed.F, build_topology(fixed.F, fixed.V.rows())).inconsistently_oriented_edges, 0);
}

TEST(AwkwardMeshes, EveryComponentIsDenoised) {
  const Mesh m = test::two_noisy_grids();
  const Eigen::Index na = test::grid(10).V.rows(), nb = test::grid(8).V.rows();
  EXPECT_EQ(summarize_topology(m.F, build_topology(m.F, m.V.rows())).components, 2);
  const DenoiseResult r = denoise_checked(m);
  EXPECT_LT(test::z_rms(r.V, 0, na), 0.5 * test::z_rms(m.V, 0, na));
  EXPECT_LT(test::z_rms(r.V, na, nb), 0.5 * test::z_rms(m.V, na, nb));
}

TEST(AwkwardMeshes, OpenBoundariesAreKept) {
  const Mesh m = test::grid_with_z_noise();
  const DenoiseResult r = denoise_checked(m);
  // The boundary is not pulled in: the bounding box in x and y stays (within a tenth of an edge).
  const Eigen::RowVector3d lo = r.V.colwise().minCoeff(), hi = r.V.colwise().maxCoeff();
  EXPECT_NEAR(lo(0), 0.0, 0.01);
  EXPECT_NEAR(lo(1), 0.0, 0.01);
  EXPECT_NEAR(hi(0), 1.0, 0.01);
  EXPECT_NEAR(hi(1), 1.0, 0.01);
  EXPECT_LT(test::z_rms(r.V, 0, r.V.rows()), 0.5 * test::z_rms(m.V, 0, m.V.rows()));
  const auto s = summarize_topology(m.F, build_topology(m.F, m.V.rows()));
  EXPECT_EQ(s.boundary_loops.size(), 1u);
}

TEST(AwkwardMeshes, SingleTriangle) {
  const Mesh m = test::single_triangle();
  const DenoiseResult r = denoise_checked(m);
  EXPECT_LT((r.V - m.V).norm(), 1e-6) << "a lone triangle has nothing to smooth";
}

TEST(AwkwardMeshes, NoFacesThroughTheLibraryIsANoOp) {
  Eigen::MatrixXd V(2, 3);
  V << 0, 0, 0, 1, 2, 3;
  const DenoiseResult r = denoise(V, Eigen::MatrixXi(0, 3));
  EXPECT_EQ(r.V, V);
}

TEST(AwkwardMeshes, NonFiniteOrOutOfRangeInputIsRejectedByTheLibrary) {
  Mesh m = test::tetrahedron();
  Mesh nan = m;
  nan.V(2, 1) = std::nan("");
  try {
    denoise(nan.V, nan.F);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 2 has a non-finite coordinate"), std::string::npos) << e.what();
  }
  Mesh inf = m;
  inf.V(0, 0) = INFINITY;
  EXPECT_THROW(denoise(inf.V, inf.F), InvalidInput);
  EXPECT_THROW(repair_mesh(inf), InvalidInput);
  Mesh oob = m;
  oob.F(3, 2) = 4;
  try {
    denoise(oob.V, oob.F);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("face 3 refers to vertex 4, out of range [0, 4)"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(repair_mesh(oob), InvalidInput);
}
