// Small meshes built in code, shared by the tests.
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "msmesh/mesh.h"

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

/// Result of running the msmesh program: exit status and combined stdout/stderr.
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

/// Runs `msmesh ARGS` (the built program) and captures its output.
inline CliRun run_cli(const std::string& args) { return run_command(std::string(MSMESH_CLI_PATH) + " " + args); }

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

#define MSMESH_REQUIRE_SHARED(var, rel)                                                     \
  const std::string var = ::msmesh::test::shared_mesh(rel);                                \
  if (var.empty()) GTEST_SKIP() << "public test mesh " << rel << " not found (../shared absent)"

}  // namespace msmesh::test
