// Small meshes built in code, shared by the tests.
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/noise.h"
#include "msmesh/shapes.h"

namespace msmesh::test {

/// A regular tetrahedron (closed, outward).
inline Mesh tetrahedron() {
  Mesh m;
  m.V.resize(4, 3);
  m.V << 1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1;
  m.F.resize(4, 3);
  m.F << 0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2;
  return m;
}

/// make_cube(n) with normal noise of `sigma` mean edge lengths (seed 7).
inline Mesh noisy_cube(int n, double sigma = 0.2) {
  Mesh m = make_cube(n);
  NoiseOptions no;
  no.sigma = sigma;
  no.seed = 7;
  m.V = add_noise(m.V, m.F, no);
  return m;
}

/// The right triangle (0,0,0), (1,0,0), (0,1,0).
inline Mesh right_triangle() {
  Mesh m;
  m.V.resize(3, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  m.F.resize(1, 3);
  m.F << 0, 1, 2;
  return m;
}

/// An n×n grid of the unit square in the plane z = 0 (open, with boundary), with an optional
/// height function applied.
inline Mesh grid(int n, double bump = 0.0) {
  Mesh m;
  m.V.resize((n + 1) * (n + 1), 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = double(i) / n, y = double(j) / n;
      m.V.row(j * (n + 1) + i) << x, y, bump * std::sin(3 * x + 1) * std::cos(2 * y);
    }
  m.F.resize(2 * n * n, 3);
  int f = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      m.F.row(f++) << a, b, d;
      m.F.row(f++) << a, d, c;
    }
  return m;
}

/// m with deterministic uniform noise in [-sigma, sigma] on every coordinate of every vertex.
inline Mesh noisy(Mesh m, double sigma, unsigned seed = 1) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-sigma, sigma);
  for (Eigen::Index i = 0; i < m.V.rows(); ++i)
    for (int c = 0; c < 3; ++c) m.V(i, c) += u(gen);
  return m;
}

/// Two meshes side by side in one (b moved by `offset`, its indices shifted).
inline Mesh join(const Mesh& a, const Mesh& b, const Eigen::RowVector3d& offset) {
  Mesh m;
  m.V.resize(a.V.rows() + b.V.rows(), 3);
  m.V << a.V, b.V.rowwise() + offset;
  m.F.resize(a.F.rows() + b.F.rows(), 3);
  m.F << a.F, (b.F.array() + static_cast<int>(a.V.rows())).matrix();
  return m;
}

/// Mean over the rows of the squared angle (radians) between the unit rows of A and B (the MSAE
/// of two sets of normals).
inline double mean_squared_angle(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  double s = 0;
  for (Eigen::Index f = 0; f < A.rows(); ++f) {
    const double t = std::acos(std::clamp(A.row(f).dot(B.row(f)), -1.0, 1.0));
    s += t * t;
  }
  return s / static_cast<double>(A.rows());
}

/// RMS of the z coordinate over `count` rows from `first` (a flat grid has 0).
inline double z_rms(const Eigen::MatrixXd& V, Eigen::Index first, Eigen::Index count) {
  return std::sqrt(V.middleRows(first, count).col(2).squaredNorm() / double(count));
}

/// A noisy 5×5 grid with per-vertex colours (exact in 8 bits), uv and vertex normals.
inline Mesh attributed_grid() {
  Mesh m = noisy(grid(5, 0.2), 0.01);
  const Eigen::Index n = m.V.rows();
  m.vertex_colors.resize(n, 3);
  m.uv.resize(n, 2);
  for (Eigen::Index i = 0; i < n; ++i) {
    m.vertex_colors.row(i) << (i % 7) * 40 / 255.0, (i % 5) * 60 / 255.0, (i % 3) * 120 / 255.0;
    m.uv.row(i) << m.V(i, 0) * 0.5, 1.0 - m.V(i, 1) * 0.25;
  }
  m.vertex_normals = vertex_normals(m.V, m.F);
  return m;
}

/// Three triangles sharing one edge (0,1): a non-manifold edge.
inline Mesh fin() {
  Mesh m;
  m.V.resize(5, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0.2, 0.5, 0, 1;
  m.F.resize(3, 3);
  m.F << 0, 1, 2, 1, 0, 3, 0, 1, 4;
  return m;
}

/// A fresh folder under the system temporary directory, removed with its content.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    std::random_device rd;
    path_ = std::filesystem::temp_directory_path() / ("msmesh_test_" + std::to_string(::getpid()) + "_" +
                                                      std::to_string(counter++) + "_" + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& path() const { return path_; }
  /// The names of the entries, sorted.
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(path_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  std::size_t entries() const { return listing().size(); }

 private:
  std::filesystem::path path_;
};

/// grid(n) without the cells (i, j) (column i, row j) for which drop(i, j) is true; every
/// vertex is kept.
template <class Drop>
inline Mesh grid_without_cells(int n, Drop drop) {
  Mesh g = grid(n);
  std::vector<int> keep;
  for (int f = 0; f < g.F.rows(); ++f) {
    const int cell = f / 2, i = cell % n, j = cell / n;
    if (drop(i, j)) continue;
    keep.push_back(f);
  }
  Mesh m;
  m.V = g.V;
  m.F.resize(static_cast<Eigen::Index>(keep.size()), 3);
  for (size_t k = 0; k < keep.size(); ++k) m.F.row(static_cast<Eigen::Index>(k)) = g.F.row(keep[k]);
  return m;
}

/// A 10×10 grid() with the four middle cells removed: a rim (40 edges) and a hole (8 edges).
inline Mesh grid_with_hole() {
  return grid_without_cells(10, [](int i, int j) { return (i == 4 || i == 5) && (j == 4 || j == 5); });
}

/// A 6×6 grid() with the two cells (2,2) and (3,3) removed: they share the vertex at grid point
/// (3,3), so the boundary around them touches itself there.
inline Mesh grid_with_touching_holes(int* touching) {
  const int n = 6;
  *touching = 3 * (n + 1) + 3;
  return grid_without_cells(n, [](int i, int j) { return (i == 2 && j == 2) || (i == 3 && j == 3); });
}

// ---- Awkward meshes of docs/robustness.md, shared by the library tests (test_denoise.cpp)
// and the command-line tests (cli/test_denoise_cli.cpp). ----

/// Two tetrahedra touching at one vertex (a bow tie): one non-manifold vertex; the second
/// tetrahedron's copy of it (vertex 4) is left unreferenced.
inline Mesh bow_tie_tetrahedra() {
  const Mesh t = tetrahedron();
  Mesh m = join(t, t, Eigen::RowVector3d(2, 2, 2));
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (m.F(f, k) == 4) m.F(f, k) = 0;  // vertex 4 (= 1,1,1 + offset) merged into vertex 0
  m.V.row(4) = m.V.row(0);                // now unreferenced
  return m;
}

/// grid(6, 0.2) with three duplicate faces: the same corners, reversed and rotated.
inline Mesh grid_with_duplicate_faces() {
  const Mesh m = grid(6, 0.2);
  Mesh dup = m;
  dup.F.conservativeResize(m.F.rows() + 3, 3);
  dup.F.row(m.F.rows()) = m.F.row(5);                            // same face
  dup.F.row(m.F.rows() + 1) << m.F(7, 0), m.F(7, 2), m.F(7, 1);  // reversed copy
  dup.F.row(m.F.rows() + 2) << m.F(9, 1), m.F(9, 2), m.F(9, 0);  // rotated copy
  return dup;
}

/// grid(6, 0.2) plus a sliver (a vertex at the midpoint of an edge, with a zero-area face on
/// that edge) and a face whose three corners coincide in space (distinct indices).
inline Mesh grid_with_zero_area_faces() {
  Mesh m = grid(6, 0.2);
  const Eigen::Index n = m.V.rows();
  m.V.conservativeResize(n + 3, 3);
  m.V.row(n) = 0.5 * (m.V.row(m.F(0, 0)) + m.V.row(m.F(0, 1)));
  m.V.row(n + 1) = m.V.row(10);
  m.V.row(n + 2) = m.V.row(10);
  m.F.conservativeResize(m.F.rows() + 2, 3);
  m.F.row(m.F.rows() - 2) << m.F(0, 0), m.F(0, 1), static_cast<int>(n);
  m.F.row(m.F.rows() - 1) << 10, static_cast<int>(n + 1), static_cast<int>(n + 2);
  return m;
}

/// A noisy grid(6) with unreferenced vertices at the front (0), in the middle (1 + n/2) and at
/// the end (n + 2), n being the grid's vertex count (#V - 3).
inline Mesh grid_with_unreferenced_vertices() {
  const Mesh g = noisy(grid(6), 0.02);
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
  return m;
}

/// A noisy grid(8, 0.1) with every third face flipped (inconsistent orientation).
inline Mesh grid_with_flipped_faces() {
  Mesh m = noisy(grid(8, 0.1), 0.01);
  for (Eigen::Index f = 0; f < m.F.rows(); f += 3) std::swap(m.F(f, 1), m.F(f, 2));
  return m;
}

/// grid(10) and grid(8) side by side, with noise in z only (the flat truth is z = 0 for both).
inline Mesh two_noisy_grids() {
  const Mesh a = grid(10), b = grid(8);
  Mesh m = noisy(join(a, b, Eigen::RowVector3d(3, 0, 0)), 0.01, 3);
  const Mesh flat = join(a, b, Eigen::RowVector3d(3, 0, 0));
  m.V.leftCols(2) = flat.V.leftCols(2);
  return m;
}

/// grid(10) with uniform noise in [-0.01, 0.01] in z only (an open mesh with one boundary loop).
inline Mesh grid_with_z_noise() {
  Mesh m = grid(10);
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(-0.01, 0.01);
  for (Eigen::Index i = 0; i < m.V.rows(); ++i) m.V(i, 2) += u(gen);
  return m;
}

/// One triangle, slightly tilted: right_triangle() with its third corner raised by 0.1.
inline Mesh single_triangle() {
  Mesh m = right_triangle();
  m.V(2, 2) = 0.1;
  return m;
}

/// An OBJ whose texture coordinates have a seam (vertex 1 has two), so uv cannot be per vertex.
inline constexpr const char* kObjWithUvSeams =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvt 0.5 0.5\n"
    "f 1/1 2/2 4/4\nf 1/5 4/4 3/3\n";

/// True when a and b have the same shape and the same bits.
inline bool bit_identical(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<size_t>(a.size())) == 0;
}

/// Writes `bytes` to `path` as they are (binary).
inline void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/// The whole content of `path` (empty when it cannot be read).
inline std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

/// Result of running a program (run_command, run_cli): exit status and combined stdout/stderr.
struct CliRun {
  int status = -1;
  std::string out;
};

/// Runs the shell command `cmd_line` and captures its exit status and output.
inline CliRun run_command(const std::string& cmd_line) {
  CliRun r;
  FILE* p = ::popen((cmd_line + " 2>&1").c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int st = ::pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

/// A new empty folder under the system's temporary folder, named after `tag` (remove it with
/// std::filesystem::remove_all).
inline std::filesystem::path temp_folder(const std::string& tag) {
  std::random_device rd;
  std::filesystem::path p = std::filesystem::temp_directory_path() /
                            ("msmesh_test_" + tag + "_" + std::to_string(::getpid()) + "_" + std::to_string(rd()));
  std::filesystem::create_directories(p);
  return p;
}

/// Path of the public test meshes, or "" when ../shared is absent (tests then skip).
inline std::string shared_mesh(const std::string& rel) {
  const std::string p = std::string(MSMESH_SHARED_MESHES) + "/" + rel;
  return std::filesystem::exists(p) ? p : std::string();
}

#define MSMESH_REQUIRE_SHARED(var, rel)                     \
  const std::string var = ::msmesh::test::shared_mesh(rel); \
  if (var.empty()) GTEST_SKIP() << "public test mesh " << rel << " not found (../shared absent)"

}  // namespace msmesh::test
