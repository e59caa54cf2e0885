// `msmesh denoise` on the awkward meshes of docs/robustness.md ("Awkward meshes"): each is
// processed, keeping vertex count, face order and indices, with finite positions; `--repair`
// repairs first and says what it did. The same meshes through the library: test_denoise.cpp
// (AwkwardMeshes.*).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli_helpers.h"
#include "msmesh/io.h"
#include "msmesh/shapes.h"

using namespace msmesh;
using msmesh::test::run_cli;
using msmesh::test::TempDir;
namespace fs = std::filesystem;

namespace {

/// Writes `msmesh shape SHAPE` (e.g. "cube --resolution 12") to `clean` and its seeded noise
/// (`msmesh noise ... NOISE`, e.g. "--sigma 0.1 --seed 3") to `noisy`.
void noisy_shape(const std::string& shape, const std::string& noise, const std::string& clean,
                 const std::string& noisy) {
  const auto made = run_cli("shape " + shape + " -q -o " + clean);
  ASSERT_EQ(made.status, 0) << made.out;
  const auto noised = run_cli("noise " + clean + " -o " + noisy + " " + noise + " -q");
  ASSERT_EQ(noised.status, 0) << noised.out;
}

/// Runs `msmesh denoise in -o out` and checks success, then reads the result back.
Mesh cli_denoise_ok(const TempDir& d, const Mesh& m, const std::string& in_name, const std::string& out_name,
                    const std::string& extra = "") {
  const std::string in = d.file(in_name), out = d.file(out_name);
  write_mesh(in, m);
  const auto run = run_cli("denoise " + in + " -o " + out + " -q " + extra);
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_TRUE(fs::exists(out)) << run.out;
  if (!fs::exists(out)) return {};
  Mesh r = read_mesh(out);
  EXPECT_EQ(r.V.rows(), m.V.rows());
  EXPECT_EQ(r.F, m.F) << "face order and indices must be kept";
  EXPECT_TRUE(r.V.allFinite());
  return r;
}

}  // namespace

TEST(AwkwardMeshesCli, NonManifoldEdgeIsDenoisedWithoutNaN) {
  const Mesh m = test::fin();
  TempDir d;
  cli_denoise_ok(d, m, "fin.ply", "fin_out.ply");
  cli_denoise_ok(d, m, "fin2.obj", "fin2_out.obj", "--method bilateral");
}

TEST(AwkwardMeshesCli, NonManifoldVertexIsDenoisedWithoutNaN) {
  TempDir d;
  cli_denoise_ok(d, test::noisy(test::bow_tie_tetrahedra(), 0.02), "bowtie.off", "bowtie_out.off");
}

TEST(AwkwardMeshesCli, DuplicateFacesAreDenoisedWithoutNaN) {
  TempDir d;
  cli_denoise_ok(d, test::noisy(test::grid_with_duplicate_faces(), 0.01), "dup.ply", "dup_out.ply");
}

TEST(AwkwardMeshes, DenoiseRepairOptionRepairsFirstAndSaysWhat) {
  Mesh m = test::noisy(test::grid(6, 0.2), 0.01);
  const Eigen::Index nf = m.F.rows();
  m.F.conservativeResize(nf + 2, 3);
  m.F.row(nf) = m.F.row(5);
  m.F.row(nf + 1) << m.F(3, 0), m.F(3, 2), m.F(3, 1);
  std::swap(m.F(8, 1), m.F(8, 2));
  TempDir d;
  const std::string in = d.file("messy.ply"), out = d.file("clean.ply");
  write_mesh(in, m);
  const auto run = run_cli("denoise " + in + " -o " + out + " -q --repair");
  ASSERT_EQ(run.status, 0) << run.out;
  EXPECT_NE(run.out.find("repair: removed duplicate faces: 2"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("repair: flipped faces to orient components consistently: 1"), std::string::npos) << run.out;
  const Mesh r = read_mesh(out);
  EXPECT_EQ(r.V.rows(), m.V.rows());
  EXPECT_EQ(r.F, test::grid(6).F);
  EXPECT_TRUE(r.V.allFinite());
}

TEST(AwkwardMeshesCli, ZeroAreaFacesAreDenoisedWithoutNaN) {
  TempDir d;
  cli_denoise_ok(d, test::grid_with_zero_area_faces(), "zero.ply", "zero_out.ply");
}

TEST(AwkwardMeshesCli, FacesRepeatingAVertexAreDroppedOnReadingAndReported) {
  TempDir d;
  const std::string in = d.file("rep.obj"), out = d.file("rep_out.obj");
  test::write_bytes(in, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 2 4\nf 2 4 3\n");
  const auto run = run_cli("denoise " + in + " -o " + out + " -q");
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_NE(run.out.find("1 face"), std::string::npos) << run.out;  // the drop is reported
  const auto info = run_cli("info " + in);
  EXPECT_NE(info.out.find("dropped degenerate faces:      1"), std::string::npos) << info.out;
}

TEST(AwkwardMeshesCli, UnreferencedVerticesStayInPlaceAndInOrder) {
  const Mesh m = test::grid_with_unreferenced_vertices();
  const Eigen::Index n = m.V.rows() - 3;
  TempDir d;
  const Mesh out = cli_denoise_ok(d, m, "unref.ply", "unref_out.ply");
  for (Eigen::Index i : {Eigen::Index(0), 1 + n / 2, n + 2}) EXPECT_EQ(out.V.row(i), m.V.row(i)) << "vertex " << i;
  // Referenced vertices keep their order: each output vertex is closest to its own input.
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) {
    Eigen::Index nearest;
    (m.V.rowwise() - out.V.row(i)).rowwise().squaredNorm().minCoeff(&nearest);
    EXPECT_EQ(nearest, i);
  }
}

TEST(AwkwardMeshesCli, InconsistentOrientationIsDenoisedWithoutNaN) {
  TempDir d;
  cli_denoise_ok(d, test::grid_with_flipped_faces(), "flip.ply", "flip_out.ply");
}

TEST(AwkwardMeshesCli, EveryComponentIsDenoised) {
  const Mesh m = test::two_noisy_grids();
  const Eigen::Index na = test::grid(10).V.rows(), nb = test::grid(8).V.rows();
  TempDir d;
  const Mesh out = cli_denoise_ok(d, m, "two.ply", "two_out.ply");
  EXPECT_LT(test::z_rms(out.V, 0, na), 0.5 * test::z_rms(m.V, 0, na));
  EXPECT_LT(test::z_rms(out.V, na, nb), 0.5 * test::z_rms(m.V, na, nb));
}

TEST(AwkwardMeshesCli, OpenBoundariesAreKept) {
  TempDir d;
  cli_denoise_ok(d, test::grid_with_z_noise(), "open.obj", "open_out.obj");
}

TEST(AwkwardMeshesCli, SingleTriangle) {
  const Mesh m = test::single_triangle();
  TempDir d;
  cli_denoise_ok(d, m, "one.stl", "one_out.stl");
  cli_denoise_ok(d, m, "one.off", "one_out.off");
  const auto info = run_cli("info " + d.file("one.off"));
  EXPECT_EQ(info.status, 0) << info.out;
}

TEST(DenoiseCli, AFeaturelessSurfaceIsReported) {
  // A noisy torus has no detail and no creases: auto calls it featureless (class cad with the
  // strong polish) and says so in the JSON and the summary; a cube's creases are not.
  const TempDir d;
  const std::string torus = d.file("torus.obj"), cube = d.file("cube.obj"), noisy = d.file("noisy.obj"),
                    out = d.file("out.obj");
  ASSERT_NO_FATAL_FAILURE(noisy_shape("torus --resolution 16", "--sigma 0.1 --seed 3", torus, noisy));
  const auto json = run_cli("denoise " + noisy + " -o " + out + " --json");
  ASSERT_EQ(json.status, 0) << json.out;
  EXPECT_NE(json.out.find("\"auto_featureless\":true"), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("\"preset\":\"cad\""), std::string::npos) << json.out;
  const auto summary = run_cli("denoise " + noisy + " -o " + out);
  ASSERT_EQ(summary.status, 0) << summary.out;
  EXPECT_NE(summary.out.find("featureless"), std::string::npos) << summary.out;
  ASSERT_NO_FATAL_FAILURE(noisy_shape("cube --resolution 12", "--sigma 0.1 --seed 3", cube, noisy));
  const auto creases = run_cli("denoise " + noisy + " -o " + out + " --json");
  ASSERT_EQ(creases.status, 0) << creases.out;
  EXPECT_NE(creases.out.find("\"auto_featureless\":false"), std::string::npos) << creases.out;
}

TEST(DenoiseCli, SmallComponentsAreKeptAndReported) {
  // A sphere and a cube of 12 triangles beside it: the cube comes back as it was, the summary,
  // the preset's reason and the JSON say so; --min-component-faces 0 denoises it too.
  const TempDir d;
  const std::string in = d.file("two.obj"), out = d.file("out.obj");
  const Mesh m = test::noisy(test::join(make_sphere(3), make_cube(1), Eigen::RowVector3d(4, 0, 0)), 0.02, 7);
  write_mesh(in, m);
  const auto summary = run_cli("denoise " + in + " -o " + out);
  ASSERT_EQ(summary.status, 0) << summary.out;
  EXPECT_NE(summary.out.find("kept as they are: 1 component(s) of fewer than 40 faces (12 faces)"), std::string::npos)
      << summary.out;
  EXPECT_NE(summary.out.find("without the 12 faces of 1 component(s)"), std::string::npos) << summary.out;
  const Mesh r = read_mesh(out);
  const Eigen::Index n = m.V.rows();
  EXPECT_LT((r.V.bottomRows(8) - m.V.bottomRows(8)).cwiseAbs().maxCoeff(), 1e-6);  // (as written to the OBJ)
  EXPECT_GT((r.V.topRows(n - 8) - m.V.topRows(n - 8)).cwiseAbs().maxCoeff(), 1e-3);
  const auto json = run_cli("denoise " + in + " -o " + out + " --json");
  ASSERT_EQ(json.status, 0) << json.out;
  EXPECT_NE(json.out.find("\"kept_components\":1,\"kept_faces\":12"), std::string::npos) << json.out;
  const auto every = run_cli("denoise " + in + " -o " + out + " --json --min-component-faces 0");
  ASSERT_EQ(every.status, 0) << every.out;
  EXPECT_NE(every.out.find("\"kept_components\":0,\"kept_faces\":0"), std::string::npos) << every.out;
  EXPECT_GT((read_mesh(out).V.bottomRows(8) - m.V.bottomRows(8)).cwiseAbs().maxCoeff(), 1e-3);
  const auto bad = run_cli("denoise " + in + " -o " + out + " --min-component-faces -2");
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.out.find("min-component-faces"), std::string::npos) << bad.out;
}

TEST(DenoiseCli, JetFittedTargetsAreReportedAndCanBeSwitchedOff) {
  // A noisy torus is curved everywhere: the defaults give most of its faces jet-fitted targets
  // (--jet-rings 3), and the JSON and the summary say how many; --jet-rings 0, preset paper and
  // auto on correlated noise (its long waves are what a quadric would follow) give none.
  const TempDir d;
  const std::string clean = d.file("torus.obj"), noisy = d.file("noisy.obj"), out = d.file("out.obj");
  ASSERT_NO_FATAL_FAILURE(noisy_shape("torus --resolution 16", "--sigma 0.1 --seed 3", clean, noisy));
  const auto on = run_cli("denoise " + noisy + " -o " + out + " --json");
  ASSERT_EQ(on.status, 0) << on.out;
  EXPECT_EQ(on.out.find("\"jet_faces\":0,"), std::string::npos) << on.out;
  EXPECT_NE(on.out.find("\"jet_faces\":"), std::string::npos) << on.out;
  const auto summary = run_cli("denoise " + noisy + " -o " + out);
  ASSERT_EQ(summary.status, 0) << summary.out;
  EXPECT_NE(summary.out.find("jet-fitted:"), std::string::npos) << summary.out;
  for (const std::string extra : {"--jet-rings 0", "--preset paper"}) {
    const auto off = run_cli("denoise " + noisy + " -o " + out + " --json " + extra);
    ASSERT_EQ(off.status, 0) << off.out;
    EXPECT_NE(off.out.find("\"jet_faces\":0,"), std::string::npos) << extra << ": " << off.out;
  }
  const std::string waves = d.file("waves.obj");
  ASSERT_NO_FATAL_FAILURE(noisy_shape("cube --resolution 24", "--sigma 0.3 --correlation 3 --seed 17", clean, waves));
  const auto scan = run_cli("denoise " + waves + " -o " + out + " --json");
  ASSERT_EQ(scan.status, 0) << scan.out;
  EXPECT_NE(scan.out.find("\"jet_faces\":0,"), std::string::npos) << scan.out;
  EXPECT_NE(scan.out.find("no jet-fitted or dropped targets (long waves of noise)"), std::string::npos) << scan.out;
  EXPECT_NE(scan.out.find("\"unreachable_faces\":0,"), std::string::npos) << scan.out;
  const auto bad = run_cli("denoise " + noisy + " -o " + out + " --jet-rings 11");
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.out.find("jet-rings"), std::string::npos) << bad.out;
}

TEST(DenoiseCli, UnreachableTargetsAreReportedAndCanBeSwitchedOff) {
  // On a noisy fandisk (σ 0.25: one round) Algorithm 1 gives some faces beside its creases the
  // other side's normal: the defaults drop those targets (--unreachable-angle 10 for the class
  // cad), and the JSON and the summary say how many; --unreachable-angle 0, presets smooth and
  // paper drop none.
  const TempDir d;
  const std::string clean = d.file("fandisk.obj"), noisy = d.file("noisy.obj"), out = d.file("out.obj");
  ASSERT_NO_FATAL_FAILURE(noisy_shape("fandisk --resolution 16", "--sigma 0.25 --seed 3", clean, noisy));
  const auto on = run_cli("denoise " + noisy + " -o " + out + " --json");
  ASSERT_EQ(on.status, 0) << on.out;
  EXPECT_NE(on.out.find("\"preset\":\"cad\""), std::string::npos) << on.out;
  EXPECT_EQ(on.out.find("\"unreachable_faces\":0,"), std::string::npos) << on.out;
  EXPECT_NE(on.out.find("\"unreachable_faces\":"), std::string::npos) << on.out;
  const auto summary = run_cli("denoise " + noisy + " -o " + out);
  ASSERT_EQ(summary.status, 0) << summary.out;
  EXPECT_NE(summary.out.find("unreachable:"), std::string::npos) << summary.out;
  EXPECT_NE(summary.out.find("more than 10 deg from their targets"), std::string::npos) << summary.out;
  for (const std::string extra : {"--unreachable-angle 0", "--preset smooth", "--preset paper"}) {
    const auto off = run_cli("denoise " + noisy + " -o " + out + " --json " + extra);
    ASSERT_EQ(off.status, 0) << off.out;
    EXPECT_NE(off.out.find("\"unreachable_faces\":0,"), std::string::npos) << extra << ": " << off.out;
  }
  const auto bad = run_cli("denoise " + noisy + " -o " + out + " --unreachable-angle 181");
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.out.find("unreachable-angle"), std::string::npos) << bad.out;
}

TEST(DenoiseCli, PlanarRegionsAreReportedAndCanBeSwitchedOff) {
  // A noisy cube's sides are planar regions of the filtered normals (--planes 100, the default):
  // the JSON and the summary say how many were snapped; --planes 0 and preset paper snap none.
  const TempDir d;
  const std::string clean = d.file("cube.obj"), noisy = d.file("noisy.obj"), out = d.file("out.obj");
  ASSERT_NO_FATAL_FAILURE(noisy_shape("cube --resolution 12", "--sigma 0.2 --seed 3", clean, noisy));
  const auto on = run_cli("denoise " + noisy + " -o " + out + " --json");
  ASSERT_EQ(on.status, 0) << on.out;
  EXPECT_EQ(on.out.find("\"planar_regions\":0,"), std::string::npos) << on.out;
  EXPECT_NE(on.out.find("\"planar_regions\":"), std::string::npos) << on.out;
  const auto summary = run_cli("denoise " + noisy + " -o " + out);
  ASSERT_EQ(summary.status, 0) << summary.out;
  EXPECT_NE(summary.out.find("planar regions:"), std::string::npos) << summary.out;
  for (const std::string extra : {"--planes 0", "--preset paper"}) {
    const auto off = run_cli("denoise " + noisy + " -o " + out + " --json " + extra);
    ASSERT_EQ(off.status, 0) << off.out;
    EXPECT_NE(off.out.find("\"planar_regions\":0,\"planar_faces\":0"), std::string::npos) << extra << ": " << off.out;
  }
  const auto bad = run_cli("denoise " + noisy + " -o " + out + " --planes -1");
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.out.find("planes"), std::string::npos) << bad.out;
}

TEST(DenoiseCli, ASecondRoundUnderHeavyNoiseIsReported) {
  // A cube under σ 0.7: auto runs a second round on the result (weight 1) and says so in the
  // summary and the JSON; under σ 0.1 the JSON gives weight 0 and no second round.
  const TempDir d;
  const std::string cube = d.file("cube.obj"), noisy = d.file("noisy.obj"), out = d.file("out.obj");
  ASSERT_NO_FATAL_FAILURE(noisy_shape("cube --resolution 12", "--sigma 0.7 --seed 3", cube, noisy));
  const auto json = run_cli("denoise " + noisy + " -o " + out + " --json");
  ASSERT_EQ(json.status, 0) << json.out;
  EXPECT_NE(json.out.find("\"auto_second_round\":1"), std::string::npos) << json.out;
  EXPECT_NE(json.out.find("\"second_round_reason\":\"chosen automatically"), std::string::npos) << json.out;
  const auto summary = run_cli("denoise " + noisy + " -o " + out);
  ASSERT_EQ(summary.status, 0) << summary.out;
  EXPECT_NE(summary.out.find("second round:     weight 1, auto on the result"), std::string::npos) << summary.out;
  ASSERT_NO_FATAL_FAILURE(noisy_shape("cube --resolution 12", "--sigma 0.1 --seed 3", cube, noisy));
  const auto light = run_cli("denoise " + noisy + " -o " + out + " --json");
  ASSERT_EQ(light.status, 0) << light.out;
  EXPECT_NE(light.out.find("\"auto_second_round\":0"), std::string::npos) << light.out;
  EXPECT_EQ(light.out.find("second_round_reason"), std::string::npos) << light.out;
}
