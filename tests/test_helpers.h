// Small meshes built in code, shared by the tests.
#pragma once
#include <sys/wait.h>
#include <unistd.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <atomic>
#include <cstdio>
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

/// Runs `msmesh ARGS` (the built program) and captures its output.
inline CliRun run_cli(const std::string& args) {
  CliRun r;
  const std::string cmd = std::string(MSMESH_CLI_PATH) + " " + args + " 2>&1";
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int st = ::pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
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
