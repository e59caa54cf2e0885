// msmesh_io_bench: read_mesh and write_mesh speed per format (bench/io/README.md).
//
// Writes a procedural mesh (an icosphere with noise, so that coordinates have full digits) to a
// folder in each format, then times write_mesh and read_mesh there, each several times with the
// page cache warm (every file is read once before timing). Prints per format the file size, the
// median time and the spread (min..max) of the repeats, MB/s of the file size and faces/s, and
// MB/s of the CPU time (user + system: what the speed is on an idle core); with --samples, one
// line per timed run as well ("sample <format> <read|write> <wall seconds> <CPU seconds>").
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "msmesh/read_mesh.h"
#include "msmesh/shapes.h"
#include "msmesh/write_mesh.h"

namespace {

struct Format {
  const char* name;  // as printed
  const char* file;  // file name in the folder (its extension picks the format)
  bool binary;       // WriteOptions::binary (PLY and STL)
};

const Format kFormats[] = {{"obj", "mesh.obj", false},         {"off", "mesh.off", false},
                           {"ply-ascii", "ascii.ply", false},  {"ply-binary", "binary.ply", true},
                           {"stl-binary", "binary.stl", true}, {"stl-ascii", "ascii.stl", false}};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// CPU time of the process (user + system): on a loaded machine the wall time also holds the
/// time spent waiting for a core, the CPU time does not.
double cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

void usage() {
  std::fprintf(stderr,
               "usage: msmesh_io_bench [--subdivisions S (8: 1.3M faces)] [--repeats N (5)] [--dir DIR]\n"
               "                       [--formats obj,off,ply-ascii,ply-binary,stl-binary,stl-ascii] [--samples]\n"
               "                       [--reuse (time no writes: read the files DIR has)]\n");
}

}  // namespace

int main(int argc, char** argv) {
  int subdivisions = 8, repeats = 5;
  bool samples = false, reuse = false;
  std::string dir, formats = "obj,off,ply-ascii,ply-binary,stl-binary,stl-ascii";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        usage();
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--subdivisions") {
      subdivisions = std::atoi(value().c_str());
    } else if (a == "--repeats") {
      repeats = std::max(1, std::atoi(value().c_str()));
    } else if (a == "--dir") {
      dir = value();
    } else if (a == "--formats") {
      formats = "," + value() + ",";
    } else if (a == "--reuse") {
      reuse = true;
    } else if (a == "--samples") {
      samples = true;
    } else {
      usage();
      return 2;
    }
  }
  if (formats.front() != ',') formats = "," + formats + ",";
  namespace fs = std::filesystem;
  const bool own_dir = dir.empty();
  if (own_dir) dir = (fs::temp_directory_path() / ("msmesh_io_bench_" + std::to_string(::getpid()))).string();
  fs::create_directories(dir);

  msmesh::Mesh mesh = msmesh::make_sphere(subdivisions);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1e-3);
  for (Eigen::Index i = 0; i < mesh.V.rows(); ++i)
    for (int c = 0; c < 3; ++c) mesh.V(i, c) += noise(rng);
  const double faces = static_cast<double>(mesh.F.rows());
  std::printf("mesh: icosphere, %lld vertices, %lld faces; %d repeats; folder %s\n",
              static_cast<long long>(mesh.V.rows()), static_cast<long long>(mesh.F.rows()), repeats, dir.c_str());
  std::printf("%-11s %9s | %-26s %8s %8s %8s | %-26s %8s %8s %8s\n", "format", "MB", "read s: median (min..max)",
              "MB/s", "Mface/s", "cpu MB/s", "write s: median (min..max)", "MB/s", "Mface/s", "cpu MB/s");
  int status = 0;
  for (const Format& f : kFormats) {
    if (formats.find("," + std::string(f.name) + ",") == std::string::npos) continue;
    const std::string path = (fs::path(dir) / f.file).string();
    msmesh::WriteOptions options;
    options.binary = f.binary;
    try {
      std::vector<double> wt, rt, wc, rc;  // wall and CPU seconds of the writes and reads
      for (int r = 0; r < (reuse && fs::exists(path) ? 0 : repeats); ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = cpu_seconds();
        msmesh::write_mesh(path, mesh, options);
        wc.push_back(cpu_seconds() - c0);
        wt.push_back(seconds_since(t0));
        if (samples) std::printf("sample %s write %.6f %.6f\n", f.name, wt.back(), wc.back());
      }
      {  // warm the page cache
        std::ifstream in(path, std::ios::binary);
        std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      }
      const double mb = static_cast<double>(fs::file_size(path)) / 1e6;
      for (int r = 0; r < repeats; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        const double c0 = cpu_seconds();
        const msmesh::Mesh back = msmesh::read_mesh(path);
        rc.push_back(cpu_seconds() - c0);
        rt.push_back(seconds_since(t0));
        if (samples) std::printf("sample %s read %.6f %.6f\n", f.name, rt.back(), rc.back());
        if (back.F.rows() != mesh.F.rows()) {
          std::fprintf(stderr, "%s: read %lld faces, wrote %lld\n", path.c_str(), static_cast<long long>(back.F.rows()),
                       static_cast<long long>(mesh.F.rows()));
          status = 1;
        }
      }
      if (wt.empty()) wt.push_back(std::nan("")), wc.push_back(std::nan(""));
      const double rm = median(rt), wm = median(wt);
      char rs[64], ws[64];
      std::snprintf(rs, sizeof rs, "%.3f (%.3f..%.3f)", rm, *std::min_element(rt.begin(), rt.end()),
                    *std::max_element(rt.begin(), rt.end()));
      std::snprintf(ws, sizeof ws, "%.3f (%.3f..%.3f)", wm, *std::min_element(wt.begin(), wt.end()),
                    *std::max_element(wt.begin(), wt.end()));
      const double rcm = median(rc), wcm = median(wc);
      std::printf("%-11s %9.1f | %-26s %8.0f %8.2f %8.0f | %-26s %8.0f %8.2f %8.0f\n", f.name, mb, rs, mb / rm,
                  faces / rm / 1e6, mb / rcm, ws, mb / wm, faces / wm / 1e6, mb / wcm);
      std::fflush(stdout);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", f.name, e.what());
      status = 1;
    }
  }
  if (own_dir) fs::remove_all(dir);
  return status;
}
