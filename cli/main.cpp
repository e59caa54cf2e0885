// msmesh: command-line front end. Every subcommand lives in its own cmd_*.cpp.
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>

#include "command.h"
#include "msmesh/errors.h"
#include "msmesh/threads.h"

namespace {

// Two settings that are only read when the process starts, so msmesh restarts itself once
// with them when the user has not chosen otherwise (docs/performance.md has the figures):
//  - OMP_WAIT_POLICY=passive: OpenMP threads waiting at a barrier spin by default; on a busy
//    machine a spinning thread holds a core the working thread needs (a 1 s job took 10 s).
//  - GLIBC_TUNABLES: large arrays on transparent huge pages (hugetlb=1), and freed memory kept
//    for reuse rather than handed back to the system after every iteration (top_pad,
//    trim_threshold, mmap_threshold at its 32 MB maximum). On this kind of virtual machine a
//    page fault costs microseconds: setting up the operators of a million-face mesh took 2-3
//    times longer with 4 KB pages, and the whole 1M-face denoise 12.6 s instead of 10.1 s.
constexpr const char* kMallocTunables =
    "glibc.malloc.hugetlb=1:glibc.malloc.mmap_threshold=33554432:glibc.malloc.top_pad=67108864:"
    "glibc.malloc.trim_threshold=1073741824";

void restart_with_runtime_settings(char** argv) {
  if (std::getenv("MSMESH_NO_RESTART") != nullptr) return;
  bool changed = false;
  if (std::getenv("OMP_WAIT_POLICY") == nullptr && std::getenv("GOMP_SPINCOUNT") == nullptr)
    changed |= setenv("OMP_WAIT_POLICY", "passive", 1) == 0;
  if (std::getenv("GLIBC_TUNABLES") == nullptr)
    changed |= setenv("GLIBC_TUNABLES", kMallocTunables, 1) == 0;
  if (!changed) return;
  setenv("MSMESH_NO_RESTART", "1", 1);
  execv("/proc/self/exe", argv);  // returns only on failure: then carry on as we are
}

}  // namespace

int main(int argc, char** argv) {
  restart_with_runtime_settings(argv);
  CLI::App app{
      "msmesh: feature-preserving mesh processing with a Mumford-Shah model on face normals\n"
      "(denoising, inpainting, segmentation; Liu et al. 2022, NMSTV)."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "msmesh 0.1.0");
  // --threads before or after the subcommand (fallthrough passes it up to here); applied as
  // soon as it is parsed, so before any subcommand runs.
  app.fallthrough();
  app.add_option_function<int>(
         "--threads", [](const int& n) { msmesh::set_threads(n); },
         "Threads for the parallel work (default: every core, or OMP_NUM_THREADS); results are the same for any number")
      ->check(CLI::Range(1, 4096))
      ->type_name("N");
  auto& registry = msmesh::cli::command_registry();
  std::sort(registry.begin(), registry.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
  for (const auto& spec : registry) spec.setup(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    msmesh::cli::finish_progress_line();
    return app.exit(e);
  } catch (const msmesh::Error& e) {
    msmesh::cli::finish_progress_line();
    std::cerr << "msmesh: error: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    msmesh::cli::finish_progress_line();
    std::cerr << "msmesh: error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    msmesh::cli::finish_progress_line();
    std::cerr << "msmesh: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
