// The catalogue of awkward meshes (issue 9, docs/robustness.md "Awkward meshes"): each case
// either processes correctly through the library and the CLI, or fails with a clear error
// naming the file and the problem, a non-zero exit code and no output file left behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "msmesh/denoise.h"
#include "msmesh/presets.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/io.h"
#include "msmesh/memory.h"
#include "msmesh/repair.h"
#include "msmesh/topology.h"
#include "test_helpers.h"

using namespace msmesh;
using msmesh::test::read_bytes;
using msmesh::test::run_cli;
using msmesh::test::write_bytes;
using msmesh::test::TempDir;
namespace fs = std::filesystem;

namespace {

/// Deterministic noise of amplitude `sigma` on every vertex (all three coordinates).
Mesh noisy(Mesh m, double sigma, unsigned seed = 1) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-sigma, sigma);
  for (Eigen::Index i = 0; i < m.V.rows(); ++i)
    for (int c = 0; c < 3; ++c) m.V(i, c) += u(gen);
  return m;
}

/// Two meshes side by side in one (b's indices shifted).
Mesh join(const Mesh& a, const Mesh& b, const Eigen::RowVector3d& offset) {
  Mesh m;
  m.V.resize(a.V.rows() + b.V.rows(), 3);
  m.V << a.V, b.V.rowwise() + offset;
  m.F.resize(a.F.rows() + b.F.rows(), 3);
  m.F << a.F, (b.F.array() + static_cast<int>(a.V.rows())).matrix();
  return m;
}

bool all_finite(const Eigen::MatrixXd& M) { return M.allFinite(); }

/// RMS of the z coordinate over the given rows (a flat grid has 0).
double z_rms(const Eigen::MatrixXd& V, Eigen::Index first, Eigen::Index count) {
  return std::sqrt(V.middleRows(first, count).col(2).squaredNorm() / double(count));
}

/// Denoising through the library must keep #V, F and order, and give finite positions.
DenoiseResult denoise_checked(const Mesh& m, const std::string& preset = "cad") {
  const DenoiseResult r = denoise(m.V, m.F, preset_options(preset));
  EXPECT_EQ(r.V.rows(), m.V.rows());
  EXPECT_TRUE(all_finite(r.V));
  return r;
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
  EXPECT_TRUE(all_finite(r.V));
  return r;
}

// ---------------------------------------------------------------------------------------------
// Awkward but valid meshes: processed, nothing lost.

TEST(AwkwardMeshes, NonManifoldEdgeIsDenoisedWithoutNaN) {
  Mesh m = test::fin();
  denoise_checked(m);
  denoise_checked(m, "smooth");
  TempDir d;
  cli_denoise_ok(d, m, "fin.ply", "fin_out.ply");
  cli_denoise_ok(d, m, "fin2.obj", "fin2_out.obj", "--method bilateral");
}

TEST(AwkwardMeshes, NonManifoldVertexIsDenoisedWithoutNaN) {
  // Two tetrahedra touching at one vertex (a bow tie).
  const Mesh t = test::tetrahedron();
  Mesh m = join(t, t, Eigen::RowVector3d(2, 2, 2));
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (m.F(f, k) == 4) m.F(f, k) = 0;  // vertex 4 (= 1,1,1 + offset) merged into vertex 0
  m.V.row(4) = m.V.row(0);                // now unreferenced
  const TopologySummary s = summarize_topology(m.F, build_topology(m.F, m.V.rows()));
  EXPECT_EQ(s.non_manifold_vertices, 1);
  const DenoiseResult r = denoise_checked(noisy(m, 0.02));
  TempDir d;
  cli_denoise_ok(d, noisy(m, 0.02), "bowtie.off", "bowtie_out.off");
}

TEST(AwkwardMeshes, DuplicateFacesAreDenoisedWithoutNaN) {
  Mesh m = test::grid(6, 0.2);
  Mesh dup = m;
  dup.F.conservativeResize(m.F.rows() + 3, 3);
  dup.F.row(m.F.rows()) = m.F.row(5);                                           // same face
  dup.F.row(m.F.rows() + 1) << m.F(7, 0), m.F(7, 2), m.F(7, 1);                 // reversed copy
  dup.F.row(m.F.rows() + 2) << m.F(9, 1), m.F(9, 2), m.F(9, 0);                 // rotated copy
  denoise_checked(noisy(dup, 0.01));
  denoise_checked(noisy(dup, 0.01), "smooth");
  TempDir d;
  cli_denoise_ok(d, noisy(dup, 0.01), "dup.ply", "dup_out.ply");
}

TEST(AwkwardMeshes, DenoiseRepairOptionRepairsFirstAndSaysWhat) {
  Mesh m = noisy(test::grid(6, 0.2), 0.01);
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

TEST(AwkwardMeshes, ZeroAreaFacesAreDenoisedWithoutNaN) {
  Mesh m = test::grid(6, 0.2);
  // A sliver: vertex at the midpoint of an edge, with a zero-area face on that edge, plus a
  // face whose three corners coincide in space (distinct indices, same position).
  const Eigen::Index n = m.V.rows();
  m.V.conservativeResize(n + 3, 3);
  m.V.row(n) = 0.5 * (m.V.row(m.F(0, 0)) + m.V.row(m.F(0, 1)));
  m.V.row(n + 1) = m.V.row(10);
  m.V.row(n + 2) = m.V.row(10);
  m.F.conservativeResize(m.F.rows() + 2, 3);
  m.F.row(m.F.rows() - 2) << m.F(0, 0), m.F(0, 1), static_cast<int>(n);
  m.F.row(m.F.rows() - 1) << 10, static_cast<int>(n + 1), static_cast<int>(n + 2);
  for (const std::string preset : {"cad", "smooth"}) denoise_checked(m, preset);
  DenoiseOptions bil = preset_options("cad");
  bil.method = DenoiseMethod::Bilateral;
  EXPECT_TRUE(denoise(m.V, m.F, bil).V.allFinite());
  TempDir d;
  cli_denoise_ok(d, m, "zero.ply", "zero_out.ply");
}

TEST(AwkwardMeshes, FacesRepeatingAVertexAreDroppedOnReadingAndReported) {
  TempDir d;
  const std::string in = d.file("rep.obj"), out = d.file("rep_out.obj");
  write_bytes(in, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 2 4\nf 2 4 3\n");
  Eigen::Index dropped = 0;
  const Mesh m = read_mesh(in, &dropped);
  EXPECT_EQ(dropped, 1);
  EXPECT_EQ(m.F.rows(), 2);
  const auto run = run_cli("denoise " + in + " -o " + out + " -q");
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_NE(run.out.find("1 face"), std::string::npos) << run.out;  // the drop is reported
  const auto info = run_cli("info " + in);
  EXPECT_NE(info.out.find("dropped degenerate faces:      1"), std::string::npos) << info.out;
}

TEST(AwkwardMeshes, UnreferencedVerticesStayInPlaceAndInOrder) {
  Mesh g = noisy(test::grid(6), 0.02);
  // Unreferenced vertices at the front, in the middle and at the end.
  Mesh m;
  const Eigen::Index n = g.V.rows();
  m.V.resize(n + 3, 3);
  m.V.row(0) << 7, 7, 7;
  m.V.middleRows(1, n / 2) = g.V.topRows(n / 2);
  m.V.row(1 + n / 2) << -3, 4, 5;
  m.V.bottomRows(n - n / 2 + 1).topRows(n - n / 2) = g.V.bottomRows(n - n / 2);
  m.V.row(n + 2) << 1e3, -1e3, 0.5;
  m.F = g.F;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k) m.F(f, k) = m.F(f, k) < n / 2 ? m.F(f, k) + 1 : m.F(f, k) + 2;
  const DenoiseResult r = denoise_checked(m);
  for (Eigen::Index i : {Eigen::Index(0), 1 + n / 2, n + 2}) EXPECT_EQ(r.V.row(i), m.V.row(i)) << "vertex " << i;
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

TEST(AwkwardMeshes, InconsistentOrientationIsDenoisedWithoutNaNAndRepaired) {
  Mesh m = noisy(test::grid(8, 0.1), 0.01);
  for (Eigen::Index f = 0; f < m.F.rows(); f += 3) std::swap(m.F(f, 1), m.F(f, 2));
  EXPECT_GT(summarize_topology(m.F, build_topology(m.F, m.V.rows())).inconsistently_oriented_edges, 0);
  denoise_checked(m);
  TempDir d;
  cli_denoise_ok(d, m, "flip.ply", "flip_out.ply");
  Mesh fixed = m;
  const RepairReport rep = repair_mesh(fixed);
  EXPECT_EQ(rep.flipped_faces, (m.F.rows() + 2) / 3);  // the first face sets the orientation
  EXPECT_EQ(summarize_topology(fixed.F, build_topology(fixed.F, fixed.V.rows())).inconsistently_oriented_edges, 0);
}

TEST(AwkwardMeshes, EveryComponentIsDenoised) {
  const Mesh a = test::grid(10), b = test::grid(8);
  Mesh m = noisy(join(a, b, Eigen::RowVector3d(3, 0, 0)), 0.01, 3);
  // Only z noise, so that the flat truth is z = 0 for both components.
  const Mesh flat = join(a, b, Eigen::RowVector3d(3, 0, 0));
  m.V.leftCols(2) = flat.V.leftCols(2);
  const Eigen::Index na = a.V.rows(), nb = b.V.rows();
  EXPECT_EQ(summarize_topology(m.F, build_topology(m.F, m.V.rows())).components, 2);
  const DenoiseResult r = denoise_checked(m);
  EXPECT_LT(z_rms(r.V, 0, na), 0.5 * z_rms(m.V, 0, na));
  EXPECT_LT(z_rms(r.V, na, nb), 0.5 * z_rms(m.V, na, nb));
  TempDir d;
  const Mesh out = cli_denoise_ok(d, m, "two.ply", "two_out.ply");
  EXPECT_LT(z_rms(out.V, 0, na), 0.5 * z_rms(m.V, 0, na));
  EXPECT_LT(z_rms(out.V, na, nb), 0.5 * z_rms(m.V, na, nb));
}

TEST(AwkwardMeshes, OpenBoundariesAreKept) {
  const Mesh clean = test::grid(10);
  Mesh m = clean;
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-0.01, 0.01);
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) m.V(i, 2) += u(gen);
  const DenoiseResult r = denoise_checked(m);
  // The boundary is not pulled in: the bounding box in x and y stays (within a tenth of an edge).
  const Eigen::RowVector3d lo = r.V.colwise().minCoeff(), hi = r.V.colwise().maxCoeff();
  EXPECT_NEAR(lo(0), 0.0, 0.01);
  EXPECT_NEAR(lo(1), 0.0, 0.01);
  EXPECT_NEAR(hi(0), 1.0, 0.01);
  EXPECT_NEAR(hi(1), 1.0, 0.01);
  EXPECT_LT(z_rms(r.V, 0, r.V.rows()), 0.5 * z_rms(m.V, 0, m.V.rows()));
  const auto s = summarize_topology(m.F, build_topology(m.F, m.V.rows()));
  EXPECT_EQ(s.boundary_loops.size(), 1u);
  TempDir d;
  cli_denoise_ok(d, m, "open.obj", "open_out.obj");
}

TEST(AwkwardMeshes, SingleTriangle) {
  Mesh m;
  m.V.resize(3, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0.1;
  m.F.resize(1, 3);
  m.F << 0, 1, 2;
  const DenoiseResult r = denoise_checked(m);
  EXPECT_LT((r.V - m.V).norm(), 1e-6) << "a lone triangle has nothing to smooth";
  TempDir d;
  cli_denoise_ok(d, m, "one.stl", "one_out.stl");
  cli_denoise_ok(d, m, "one.off", "one_out.off");
  const auto info = run_cli("info " + d.file("one.off"));
  EXPECT_EQ(info.status, 0) << info.out;
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

// ---------------------------------------------------------------------------------------------
// Broken files: a clear error naming the file and the problem, exit code 1, no output.

struct BadFile {
  const char* name;     ///< file name (the extension picks the reader)
  std::string content;  ///< file bytes
  const char* problem;  ///< expected in the message
};

std::string binary_ply_header(const std::string& counts) {
  return "ply\nformat binary_little_endian 1.0\n" + counts +
         "property float x\nproperty float y\nproperty float z\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
}

std::vector<BadFile> bad_files() {
  std::vector<BadFile> c;
  const std::string tet_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  c.push_back({"nofaces.obj", tet_obj, "no faces"});
  c.push_back({"nofaces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", "no faces"});
  c.push_back({"nofaces.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                              "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n",
               "no faces"});
  c.push_back({"novertices.off", "OFF\n0 0 0\n", "no vertices"});
  c.push_back({"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "non-finite"});
  c.push_back({"inf.off", "OFF\n3 1 0\n0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n", "non-finite"});
  c.push_back({"nan.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n",
               "non-finite"});
  c.push_back({"oob.obj", tet_obj + "f 1 2 5\n", "refers to vertex 5"});
  c.push_back({"oob.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "refers to vertex 3"});
  c.push_back({"oob.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
               "refers to vertex 7"});
  c.push_back({"huge.ply", binary_ply_header("element vertex 1000000000000\n") + std::string(60, '\0'),
               "header declares 1000000000000 vertex"});
  c.push_back({"huge.off", "OFF\n2000000000 1 0\n0 0 0\n", "header declares 2000000000 vertices"});
  {
    std::string stl(80, ' ');
    const std::uint32_t n = 4000000000u;
    stl.append(reinterpret_cast<const char*>(&n), 4);
    stl.append(50, '\0');
    c.push_back({"huge.stl", stl, "header declares 4000000000 triangles"});
  }
  {
    std::string ply = binary_ply_header("element vertex 3\n");
    for (int i = 0; i < 5; ++i) ply.append(4, '\0');  // 5 of 9 floats
    c.push_back({"truncated.ply", ply, "truncated"});
    std::string stl(80, ' ');
    const std::uint32_t n = 2;
    stl.append(reinterpret_cast<const char*>(&n), 4);
    stl.append(70, '\0');  // 1.4 of 2 triangles
    c.push_back({"truncated.stl", stl, "truncated"});
    c.push_back({"truncated.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n", "truncated"});
  }
  c.push_back({"magic.ply", "plx\nformat ascii 1.0\nend_header\n", "not a PLY file"});
  c.push_back({"magic.off", "FOO\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "not an OFF file"});
  c.push_back({"magic.stl", "this is not an stl", "not an STL file"});
  c.push_back({"empty.obj", "", "empty file"});
  c.push_back({"garbage.obj", "v 0 0 0\nv 1 0\nf 1 2 3\n", "fewer than 3 coordinates"});
  c.push_back({"mesh.xyz", "0 0 0\n", "unknown mesh format"});
  return c;
}

TEST(BrokenFiles, LibraryThrowsIoErrorNamingFileAndProblem) {
  TempDir d;
  for (const BadFile& b : bad_files()) {
    const std::string path = d.file(b.name);
    write_bytes(path, b.content);
    try {
      read_mesh(path);
      ADD_FAILURE() << b.name << ": expected IoError";
    } catch (const IoError& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.rfind(path, 0), 0u) << b.name << ": " << msg;
      EXPECT_NE(msg.find(b.problem), std::string::npos) << b.name << ": " << msg;
    }
  }
}

TEST(BrokenFiles, CliExitsNonZeroNamesFileAndProblemAndWritesNothing) {
  TempDir d;
  for (const BadFile& b : bad_files()) {
    const std::string path = d.file(b.name);
    write_bytes(path, b.content);
    for (const std::string cmd : {"denoise", "repair", "info", "eval"}) {
      const std::string out = d.file(std::string("out_") + cmd + ".ply");
      std::string args = cmd + " " + path;
      if (cmd == "denoise" || cmd == "repair") args += " -o " + out;
      if (cmd == "eval") args += " --truth " + path;
      const auto run = run_cli(args);
      EXPECT_EQ(run.status, 1) << cmd << " " << b.name << ": " << run.out;
      EXPECT_NE(run.out.find("msmesh: error: " + path), std::string::npos) << cmd << " " << b.name << ": " << run.out;
      EXPECT_NE(run.out.find(b.problem), std::string::npos) << cmd << " " << b.name << ": " << run.out;
      EXPECT_FALSE(fs::exists(out)) << cmd << " " << b.name;
    }
  }
  // Only the inputs remain: no output and no temporary file.
  EXPECT_EQ(d.entries(), bad_files().size());
}

TEST(BrokenFiles, MissingInputAndUnwritableOutput) {
  TempDir d;
  const std::string missing = d.file("missing.ply");
  auto run = run_cli("denoise " + missing + " -o " + d.file("o.ply"));
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.out.find(missing + ": no such file"), std::string::npos) << run.out;
  const std::string in = d.file("tet.ply");
  write_mesh(in, test::tetrahedron());
  const std::string bad_out = d.file("no/such/folder/out.ply");
  run = run_cli("denoise " + in + " -o " + bad_out + " -q");
  EXPECT_EQ(run.status, 1) << run.out;
  EXPECT_NE(run.out.find(bad_out), std::string::npos) << run.out;
  EXPECT_EQ(d.entries(), 1u);
}

// ---------------------------------------------------------------------------------------------
// Nothing lost: order, attributes, the input file, atomic outputs.

TEST(NothingLost, InputIsNeverOverwrittenWithoutInPlace) {
  TempDir d;
  const std::string in = d.file("m.ply");
  write_mesh(in, noisy(test::grid(5, 0.1), 0.01));
  const std::string before = read_bytes(in);
  for (const std::string cmd : {"denoise", "repair"}) {
    for (const std::string& out : {in, d.file("./m.ply")}) {
      const auto run = run_cli(cmd + " " + in + " -o " + out + " -q");
      EXPECT_EQ(run.status, 2) << run.out;  // a usage error (more cases: test_outputs_cli.cpp)
      EXPECT_NE(run.out.find("refusing to overwrite the input file"), std::string::npos) << run.out;
      EXPECT_EQ(read_bytes(in), before);
    }
  }
  const auto run = run_cli("denoise " + in + " -o " + in + " -q --in-place");
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_NE(read_bytes(in), before);
  EXPECT_EQ(d.entries(), 1u);
}

TEST(NothingLost, FailedRunKeepsAnExistingOutput) {
  TempDir d;
  const std::string in = d.file("m.ply"), out = d.file("out.ply");
  write_mesh(in, test::grid(4, 0.1));
  write_bytes(out, "previous result");
  const auto run = run_cli("denoise " + in + " -o " + out + " --alpha -1");
  EXPECT_EQ(run.status, 2);  // a usage error
  EXPECT_EQ(read_bytes(out), "previous result");
  EXPECT_EQ(d.entries(), 2u);
}

Mesh attributed_grid() {
  Mesh m = noisy(test::grid(5, 0.2), 0.01);
  const Eigen::Index n = m.V.rows();
  m.vertex_colors.resize(n, 3);
  m.uv.resize(n, 2);
  for (Eigen::Index i = 0; i < n; ++i) {
    m.vertex_colors.row(i) << (i % 7) * 40 / 255.0, (i % 5) * 60 / 255.0, (i % 3) * 120 / 255.0;  // exact in 8 bits
    m.uv.row(i) << m.V(i, 0) * 0.5, 1.0 - m.V(i, 1) * 0.25;
  }
  m.vertex_normals = vertex_normals(m.V, m.F);
  return m;
}

void expect_attributes_kept(const Mesh& in, const Mesh& out, bool colors, bool uv, bool normals,
                            const std::string& what) {
  SCOPED_TRACE(what);
  ASSERT_EQ(out.V.rows(), in.V.rows());
  EXPECT_EQ(out.F, in.F);
  if (colors) {
    ASSERT_EQ(out.vertex_colors.rows(), in.V.rows());
    EXPECT_LT((out.vertex_colors - in.vertex_colors).cwiseAbs().maxCoeff(), 0.5 / 255);
  }
  if (uv) {
    ASSERT_EQ(out.uv.rows(), in.V.rows());
    EXPECT_LT((out.uv - in.uv).cwiseAbs().maxCoeff(), 1e-6);
  }
  if (normals) {
    ASSERT_EQ(out.vertex_normals.rows(), in.V.rows());
    // Recomputed for the result, not copied from the input.
    const Eigen::MatrixXd expected = vertex_normals(out.V, out.F);
    EXPECT_LT((out.vertex_normals - expected).cwiseAbs().maxCoeff(), 1e-5);
  }
}

TEST(NothingLost, AttributesRoundTripThroughEachFormat) {
  TempDir d;
  const Mesh m = attributed_grid();
  for (const std::string name : {"a.ply", "b.obj"}) {
    write_mesh(d.file(name), m);
    const Mesh r = read_mesh(d.file(name));
    SCOPED_TRACE(name);
    EXPECT_EQ(r.vertex_colors.rows(), m.V.rows());
    EXPECT_EQ(r.uv.rows(), m.V.rows());
    EXPECT_EQ(r.vertex_normals.rows(), m.V.rows());
    EXPECT_LT((r.uv - m.uv).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((r.vertex_normals - m.vertex_normals).cwiseAbs().maxCoeff(), 1e-12);
  }
  WriteOptions ascii;
  ascii.binary = false;
  write_mesh(d.file("c.ply"), m, ascii);
  const Mesh r = read_mesh(d.file("c.ply"));
  EXPECT_LT((r.uv - m.uv).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((r.vertex_colors - m.vertex_colors).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(NothingLost, DenoiseCarriesColoursUvAndRecomputedNormals) {
  TempDir d;
  const Mesh m = attributed_grid();
  for (const std::string ext : {"ply", "obj"}) {
    const std::string in = d.file("in." + ext), out = d.file("out." + ext);
    write_mesh(in, m);
    for (const std::string method : {"nmstv", "bilateral"}) {
      const auto run = run_cli("denoise " + in + " -o " + out + " -q --method " + method);
      ASSERT_EQ(run.status, 0) << run.out;
      expect_attributes_kept(m, read_mesh(out), true, true, true, ext + " " + method);
    }
  }
  // OFF has colours (COFF) but no uv; normals (NOFF) are not written.
  Mesh c = m;
  c.uv.resize(0, 0);
  c.vertex_normals.resize(0, 0);
  write_mesh(d.file("in.off"), c);
  const auto run = run_cli("denoise " + d.file("in.off") + " -o " + d.file("out.off") + " -q");
  ASSERT_EQ(run.status, 0) << run.out;
  expect_attributes_kept(c, read_mesh(d.file("out.off")), true, false, false, "off");
}

TEST(NothingLost, HandWrittenObjWithColoursTexturesAndNormals) {
  TempDir d;
  const std::string in = d.file("hand.obj");
  write_bytes(in,
              "mtllib x.mtl\n"
              "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nv 1 1 0.1 1 1 1\n"
              "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"
              "vn 0 0 1\n"
              "f 1/1/1 2/2/1 4/4/1\nf 1/1/1 4/4/1 3/3/1\n");
  const Mesh m = read_mesh(in);
  ASSERT_EQ(m.vertex_colors.rows(), 4);
  EXPECT_EQ(m.vertex_colors.row(1), Eigen::RowVector3d(0, 1, 0));
  ASSERT_EQ(m.uv.rows(), 4);
  EXPECT_EQ(m.uv.row(3), Eigen::RowVector2d(1, 1));
  ASSERT_EQ(m.vertex_normals.rows(), 4);
  EXPECT_EQ(m.vertex_normals.row(2), Eigen::RowVector3d(0, 0, 1));
  // uv with seams (one vertex, two texture coordinates) cannot be per-vertex: dropped, and
  // `info` says so.
  write_bytes(d.file("seam.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvt 0.5 0.5\n"
                                  "f 1/1 2/2 4/4\nf 1/5 4/4 3/3\n");
  const Mesh s = read_mesh(d.file("seam.obj"));
  EXPECT_EQ(s.uv.size(), 0);
  const auto info = run_cli("info " + d.file("seam.obj"));
  EXPECT_NE(info.out.find("seams"), std::string::npos) << info.out;
}

// ---------------------------------------------------------------------------------------------
// Repair.

TEST(Repair, MergesDuplicateVerticesWithoutRenumbering) {
  Mesh m = test::tetrahedron();
  m.V.conservativeResize(6, 3);
  m.V.row(4) = m.V.row(1);                                    // exact copy
  m.V.row(5) = m.V.row(2) + Eigen::RowVector3d(1e-4, 0, 0);   // close copy
  m.F(1, 2) = 4;                                              // face 1 uses the exact copy
  m.F(3, 2) = 5;                                              // face 3 uses the close copy
  Mesh exact = m;
  RepairReport r = repair_mesh(exact);
  EXPECT_EQ(r.merged_vertices, 1);
  EXPECT_EQ(exact.V, m.V) << "the vertex array is kept";
  EXPECT_EQ(exact.F(1, 2), 1);
  EXPECT_EQ(exact.F(3, 2), 5);
  Mesh welded = m;
  RepairOptions o;
  o.weld_tolerance = 0.01;
  r = repair_mesh(welded, o);
  EXPECT_EQ(r.merged_vertices, 2);
  EXPECT_EQ(welded.F, test::tetrahedron().F);
  EXPECT_EQ(r.unreferenced_vertices, 2);
  o.remove_unreferenced = true;
  Mesh compact = m;
  r = repair_mesh(compact, o);
  EXPECT_EQ(r.unreferenced_vertices_removed, 2);
  EXPECT_EQ(compact.V, test::tetrahedron().V);
  EXPECT_EQ(r.vertex_map, (Eigen::VectorXi(6) << 0, 1, 2, 3, -1, -1).finished());
}

TEST(Repair, RemovesDegenerateZeroAreaAndDuplicateFacesKeepingFaceOrder) {
  Mesh m = test::grid(3);
  const Eigen::Index nf = m.F.rows();
  m.V.conservativeResize(m.V.rows() + 1, 3);
  m.V.row(m.V.rows() - 1) = 0.5 * (m.V.row(0) + m.V.row(1));  // on the edge 0-1
  m.F.conservativeResize(nf + 4, 3);
  m.F.row(nf) << 0, 1, static_cast<int>(m.V.rows() - 1);    // zero area
  m.F.row(nf + 1) = m.F.row(2);                              // duplicate
  m.F.row(nf + 2) << 3, 3, 4;                                // repeats a vertex
  m.F.row(nf + 3) << m.F(4, 2), m.F(4, 1), m.F(4, 0);        // reversed duplicate
  RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.zero_area_faces_removed, 1);
  EXPECT_EQ(r.duplicate_faces_removed, 2);
  EXPECT_EQ(r.degenerate_faces_removed, 1);
  EXPECT_EQ(r.flipped_faces, 0);
  EXPECT_EQ(m.F, test::grid(3).F);
  EXPECT_EQ(r.face_origin, Eigen::VectorXi::LinSpaced(nf, 0, static_cast<int>(nf - 1)));
  EXPECT_EQ(r.actions().size(), 3u);
  // A clean mesh is left alone.
  Mesh clean = test::grid(3);
  r = repair_mesh(clean);
  EXPECT_FALSE(r.changed());
  EXPECT_TRUE(r.actions().empty());
}

TEST(Repair, OrientsComponentsClosedOnesOutwards) {
  Mesh inside_out = test::tetrahedron();
  for (Eigen::Index f = 0; f < 4; ++f) std::swap(inside_out.F(f, 1), inside_out.F(f, 2));
  Mesh two = join(inside_out, test::grid(4), Eigen::RowVector3d(5, 0, 0));
  std::swap(two.F(6, 1), two.F(6, 2));  // one face of the grid flipped
  const RepairReport r = repair_mesh(two);
  EXPECT_EQ(r.flipped_faces, 5);
  EXPECT_EQ(r.components, 2);
  EXPECT_EQ(two.F.topRows(4), test::tetrahedron().F);
  EXPECT_EQ(two.F.bottomRows(32), (test::grid(4).F.array() + 4).matrix());
}

TEST(Repair, NonOrientableComponentIsCounted) {
  // A Moebius strip: a band of 5 quads whose ends are joined with a half twist.
  const int n = 5;
  Mesh m;
  m.V.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n;
    for (int s = 0; s < 2; ++s) {
      const double w = s ? 0.3 : -0.3, h = t / 2;
      m.V.row(2 * i + s) << (1 + w * std::cos(h)) * std::cos(t), (1 + w * std::cos(h)) * std::sin(t), w * std::sin(h);
    }
  }
  m.F.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    int a = 2 * i, b = 2 * i + 1, c = 2 * (i + 1), d = 2 * (i + 1) + 1;
    if (i == n - 1) c = 1, d = 0;  // the twist
    m.F.row(2 * i) << a, c, b;
    m.F.row(2 * i + 1) << b, c, d;
  }
  const RepairReport r = repair_mesh(m);
  EXPECT_EQ(r.non_orientable_components, 1);
  EXPECT_TRUE(m.V.allFinite());
}

TEST(Repair, SplitsNonManifoldVerticesAndEdgesCarryingAttributes) {
  Mesh fin = test::fin();
  fin.vertex_colors = Eigen::MatrixXd::Random(5, 3).cwiseAbs();
  RepairOptions o;
  o.split_non_manifold = true;
  RepairReport r = repair_mesh(fin, o);
  EXPECT_EQ(r.split_vertices, 4);
  EXPECT_EQ(r.non_manifold_edges, 0);
  EXPECT_EQ(r.non_manifold_vertices, 0);
  EXPECT_EQ(r.components, 3);
  ASSERT_EQ(fin.V.rows(), 9);
  EXPECT_EQ(fin.V.topRows(5), test::fin().V) << "existing vertices keep their index";
  ASSERT_EQ(fin.vertex_colors.rows(), 9);
  for (Eigen::Index i = 5; i < 9; ++i) {
    Eigen::Index src;
    (test::fin().V.rowwise() - fin.V.row(i)).rowwise().squaredNorm().minCoeff(&src);
    EXPECT_EQ(fin.vertex_colors.row(i), fin.vertex_colors.row(src));
  }
  // A bow tie: two fans around one vertex.
  Mesh bow;
  bow.V.resize(5, 3);
  bow.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0;
  bow.F.resize(2, 3);
  bow.F << 0, 1, 2, 0, 3, 4;
  r = repair_mesh(bow, o);
  EXPECT_EQ(r.split_vertices, 1);
  EXPECT_EQ(bow.F(1, 0), 5);
}

TEST(Repair, CliSummaryJsonAndErrors) {
  TempDir d;
  const std::string in = d.file("messy.obj"), out = d.file("fixed.ply");
  write_bytes(in,
              "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 1 0 0\n"
              "f 1 2 3\nf 5 3 4\nf 1 2 3\nf 1 1 2\n");
  auto run = run_cli("repair " + in + " -o " + out);
  ASSERT_EQ(run.status, 0) << run.out;
  for (const char* line : {"dropped on reading, faces repeating a vertex: 1", "merged duplicate vertices: 1",
                           "removed duplicate faces: 1", "flipped faces to orient components consistently: 1",
                           "remaining: 1 components", "--remove-unreferenced"})
    EXPECT_NE(run.out.find(line), std::string::npos) << line << "\n" << run.out;
  const Mesh fixed = read_mesh(out);
  EXPECT_EQ(fixed.V.rows(), 5);
  EXPECT_EQ(fixed.F.rows(), 2);
  EXPECT_EQ(summarize_topology(fixed.F, build_topology(fixed.F, 5)).inconsistently_oriented_edges, 0);
  run = run_cli("repair " + in + " --dry-run --json --remove-unreferenced");
  ASSERT_EQ(run.status, 0) << run.out;
  EXPECT_NE(run.out.find("\"vertices_after\":4"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("\"unreferenced_vertices_removed\":1"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("\"faces_after\":2"), std::string::npos) << run.out;
  // A file whose every face goes: error, nothing written.
  const std::string all_dup = d.file("flat.obj"), out2 = d.file("flat_out.obj");
  write_bytes(all_dup, "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  run = run_cli("repair " + all_dup + " -o " + out2);
  EXPECT_EQ(run.status, 1) << run.out;
  EXPECT_NE(run.out.find(all_dup + ": repair removed every face"), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(out2));
  run = run_cli("repair " + in);
  EXPECT_EQ(run.status, 1) << run.out;
  EXPECT_NE(run.out.find("--dry-run"), std::string::npos) << run.out;
}

// ---------------------------------------------------------------------------------------------
// Limits.

TEST(Limits, ParametersOutOfRangeNameTheValidRange) {
  TempDir d;
  const std::string in = d.file("m.ply"), out = d.file("o.ply");
  write_mesh(in, test::grid(4, 0.1));
  const std::pair<std::string, std::string> cases[] = {
      {"--alpha -1", "> 0"},
      {"--alpha nan", "> 0"},
      {"--epsilon 0", "> 0"},
      {"--nu 2", "(0, 1.618"},
      {"--v0 1.5", "[0, 1]"},
      {"--normal-iterations 0", "[1, 100000]"},
      {"--vertex-iterations 1000000", "[1, 100000]"},
      {"--omega2 -1", ">= 0"},
      {"--method bilateral --sigma-r 3", "(0, 2]"},
  };
  for (const auto& [args, range] : cases) {
    const auto run = run_cli("denoise " + in + " -o " + out + " " + args);
    EXPECT_EQ(run.status, 2) << args << ": " << run.out;  // a usage error
    EXPECT_NE(run.out.find("out of range"), std::string::npos) << args << ": " << run.out;
    EXPECT_NE(run.out.find(range), std::string::npos) << args << ": " << run.out;
    EXPECT_FALSE(fs::exists(out));
  }
  const auto run = run_cli("repair " + in + " -o " + out + " --weld 2");
  EXPECT_EQ(run.status, 2) << run.out;  // a usage error, as every number out of range
  EXPECT_NE(run.out.find("[0, 1]"), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(out));
}

TEST(Limits, ForeseeableAllocationBeyondAvailableMemoryFailsCleanly) {
  EXPECT_GT(available_memory_bytes(), 0u);
  EXPECT_NO_THROW(check_memory(1000, "small"));
  try {
    check_memory(1e18, "denoise of huge.ply");
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("denoise of huge.ply: needs about"), std::string::npos) << e.what();
  }
  // Through the CLI, with the limit lowered by the environment.
  TempDir d;
  const std::string in = d.file("m.ply"), out = d.file("o.ply");
  write_mesh(in, test::grid(20, 0.1));
  ::setenv("MSMESH_MEMORY_LIMIT", "100000", 1);
  const auto run = run_cli("denoise " + in + " -o " + out + " -q");
  ::unsetenv("MSMESH_MEMORY_LIMIT");
  EXPECT_EQ(run.status, 1) << run.out;
  EXPECT_NE(run.out.find("needs about"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("MSMESH_MEMORY_LIMIT"), std::string::npos) << run.out;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
