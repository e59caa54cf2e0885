// Scaling benchmark: one full default denoise (30 + 30 iterations) of a noisy procedural
// shape of a given face count, timed per stage, with the process's peak memory, and the
// binary-PLY and OBJ read/write speed at that size. Prints one JSON object.
//
//   build/bench/msmesh_scaling --faces 1000000 [--shape cube|sphere] [--preset cad] [--io DIR]
//
// One size per process, so that the peak resident memory belongs to that size alone;
// bench/scaling/run.py runs the sizes and writes the table and plot of docs/performance.md.
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numeric>
#include <string>

#include "msmesh/denoise.h"
#include "msmesh/geometry.h"
#include "msmesh/io.h"
#include "msmesh/noise.h"
#include "msmesh/operators.h"
#include "msmesh/presets.h"
#include "msmesh/shapes.h"
#include "msmesh/topology.h"

#ifdef _OPENMP
#include <omp.h>
#endif

using namespace msmesh;

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

double peak_rss_mb() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return ru.ru_maxrss / 1024.0;  // Linux: kilobytes
}

double cpu_seconds() {
  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  return ru.ru_utime.tv_sec + ru.ru_utime.tv_usec * 1e-6 + ru.ru_stime.tv_sec + ru.ru_stime.tv_usec * 1e-6;
}

[[noreturn]] void usage() {
  std::fprintf(stderr, "usage: msmesh_scaling --faces N [--shape cube|sphere] [--preset cad|smooth] [--io DIR]\n");
  std::exit(2);
}

}  // namespace

int main(int argc, char** argv) {
  double target = 0;
  std::string shape = "cube", preset = "cad", io_dir;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) usage();
    if (a == "--faces")
      target = std::atof(argv[++i]);
    else if (a == "--shape")
      shape = argv[++i];
    else if (a == "--preset")
      preset = argv[++i];
    else if (a == "--io")
      io_dir = argv[++i];
    else
      usage();
  }
  if (!(target >= 12)) usage();

  Mesh m;
  if (shape == "cube") {
    m = make_cube(std::max(1, static_cast<int>(std::lround(std::sqrt(target / 12.0)))));  // 12 n² faces
  } else if (shape == "sphere") {
    m = make_sphere(std::max(0, static_cast<int>(std::lround(std::log(target / 20.0) / std::log(4.0)))));  // 20·4^k
  } else {
    usage();
  }
  NoiseOptions no;
  no.sigma = 0.2;
  no.seed = 1;
  m.V = add_noise(m.V, m.F, no);
  const double rss_mesh = peak_rss_mb();

  // Stage 0 (also inside the filters): topology and operators.
  double t0 = now();
  {
    const Topology t = build_topology(m.F, m.V.rows());
    const Operators ops = build_operators(m.V, m.F, t);
    if (ops.G.rows() != t.num_edges()) return 1;
  }
  const double t_ops = now() - t0;

  const DenoiseOptions o = preset_options(preset);
  const double cpu0 = cpu_seconds();
  t0 = now();
  const DenoiseResult r = denoise(m.V, m.F, o);
  const double t_denoise = now() - t0;
  const double cpu_denoise = cpu_seconds() - cpu0;
  const double rss_denoise = peak_rss_mb();
  auto sum = [](const std::vector<int>& v) { return std::accumulate(v.begin(), v.end(), 0); };

  int threads = 1;
#ifdef _OPENMP
  threads = omp_get_max_threads();
#endif
  std::printf("{\"shape\":\"%s\",\"preset\":\"%s\",\"faces\":%lld,\"vertices\":%lld,\"threads\":%d,", shape.c_str(),
              preset.c_str(), static_cast<long long>(m.F.rows()), static_cast<long long>(m.V.rows()), threads);
  std::printf("\"seconds_operators\":%.4f,\"seconds_normals\":%.4f,\"seconds_vertices\":%.4f,\"seconds_denoise\":%.4f,",
              t_ops, r.seconds_normals, r.seconds_vertices, t_denoise);
  std::printf("\"cpu_seconds_denoise\":%.4f,\"normal_iterations\":%d,\"vertex_iterations\":%d,", cpu_denoise,
              r.normal_report.iterations, r.vertex_report.iterations);
  std::printf("\"n_step_cg_iterations\":%d,\"v_step_cg_iterations\":%d,", sum(r.normal_report.n_solver_iterations),
              sum(r.vertex_report.solver_iterations));
  std::printf("\"peak_mb_mesh\":%.1f,\"peak_mb_denoise\":%.1f", rss_mesh, rss_denoise);

  if (!io_dir.empty()) {
    Mesh out = m;
    out.V = r.V;
    for (const char* ext : {"ply", "obj"}) {
      const std::string path = (std::filesystem::path(io_dir) / (std::string("msmesh_scaling.") + ext)).string();
      t0 = now();
      write_mesh(path, out);
      const double tw = now() - t0;
      const double mb = std::filesystem::file_size(path) / 1e6;
      t0 = now();
      const Mesh back = read_mesh(path);
      const double tr = now() - t0;
      if (back.F.rows() != out.F.rows()) return 1;
      std::printf(",\"%s_mb\":%.1f,\"%s_write_mb_s\":%.1f,\"%s_read_mb_s\":%.1f", ext, mb, ext, mb / tw, ext, mb / tr);
      std::filesystem::remove(path);
    }
  }
  std::printf("}\n");
  return 0;
}
