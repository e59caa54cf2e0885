// msmesh: command-line front end. Every subcommand lives in its own cmd_*.cpp.
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>

#include "command.h"
#include "msmesh/errors.h"

namespace {

// OpenMP threads that wait at a barrier spin by default. On a busy machine (another build,
// another msmesh) a spinning thread holds a core the working thread needs, and a 1 s job can
// take 10 s (docs/performance.md). libgomp reads OMP_WAIT_POLICY once, when it is loaded, so
// when the user has not chosen a policy msmesh restarts itself once with "passive" set.
void prefer_passive_openmp_waits(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") != nullptr || std::getenv("GOMP_SPINCOUNT") != nullptr) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
  execv("/proc/self/exe", argv);  // returns only on failure: then carry on as we are
}

}  // namespace

int main(int argc, char** argv) {
  prefer_passive_openmp_waits(argv);
  CLI::App app{
      "msmesh: feature-preserving mesh processing with a Mumford-Shah model on face normals\n"
      "(denoising, inpainting, segmentation; Liu et al. 2022, NMSTV)."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "msmesh 0.1.0");
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
