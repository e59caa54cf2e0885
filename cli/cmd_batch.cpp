// msmesh batch: many meshes on a Dask cluster (docs/batch.md). The batch runner is Python
// (python/msmesh/batch.py, on dask.distributed); this subcommand replaces the process with
//   PYTHON -m msmesh.batch ARGS...
// where PYTHON is $MSMESH_PYTHON, else the interpreter the module was built for, and the package
// is the one beside this program (the build tree's <build>/python, or a pip install's
// <site-packages>/msmesh/_bin/msmesh), else the interpreter's own. The tasks run this program
// (MSMESH_CLI), so that a batch gives the outputs of single runs of it.
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "command.h"
#include "msmesh/errors.h"
#include "runtime_settings.h"

#ifndef MSMESH_PYTHON_EXECUTABLE
#define MSMESH_PYTHON_EXECUTABLE "/usr/bin/python3"
#endif

namespace msmesh::cli {
namespace {

namespace fs = std::filesystem;

/// The folder to put on PYTHONPATH for the package beside the program, or "" for none.
std::string package_root(const fs::path& program) {
  std::error_code ec;
  const fs::path dir = program.parent_path();
  if (fs::is_regular_file(dir / "python" / "msmesh" / "batch.py", ec)) return (dir / "python").string();
  if (fs::is_regular_file(dir.parent_path() / "batch.py", ec)) return dir.parent_path().parent_path().string();
  return "";
}

/// Undoes what main.cpp's restart set for the program only (the Python processes and the
/// workers do not need it; every task runs msmesh, which sets it again).
void unset_runtime_settings() {
  if (std::getenv("MSMESH_NO_RESTART") == nullptr) return;
  unsetenv("MSMESH_NO_RESTART");
  const char* wait = std::getenv("OMP_WAIT_POLICY");
  if (wait && std::strcmp(wait, "passive") == 0) unsetenv("OMP_WAIT_POLICY");
  const char* spin = std::getenv("GOMP_SPINCOUNT");
  if (spin && std::strcmp(spin, kIdleSpinCount) == 0) unsetenv("GOMP_SPINCOUNT");
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables && std::strcmp(tunables, kMallocTunables) == 0) unsetenv("GLIBC_TUNABLES");
}

[[noreturn]] void run(const std::vector<std::string>& args) {
  std::error_code ec;
  const fs::path program = fs::canonical("/proc/self/exe", ec);
  const char* chosen = std::getenv("MSMESH_PYTHON");
  const std::string python = chosen && *chosen ? chosen : MSMESH_PYTHON_EXECUTABLE;
  if (!ec) {
    const std::string root = package_root(program);
    if (!root.empty()) {
      const char* old = std::getenv("PYTHONPATH");
      setenv("PYTHONPATH", (old && *old ? root + ":" + old : root).c_str(), 1);
    }
    setenv("MSMESH_CLI", program.c_str(), 0);
  }
  unset_runtime_settings();
  std::vector<std::string> words = {python, "-m", "msmesh.batch"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  execv(python.c_str(), argv.data());
  throw Error("batch: cannot run the Python interpreter " + python + ": " + std::strerror(errno) +
              " (set MSMESH_PYTHON to one with the msmesh module and python3-distributed)");
}

const Registrar kRegistration("batch", 200, [](CLI::App& app) {
  CLI::App* c = app.add_subcommand(
      "batch",
      "Run denoise, inpaint, segment, repair or eval on many meshes (files, folders, globs, CSV manifests) on a "
      "Dask cluster; `msmesh batch --help` shows the options");
  // Every argument after `batch` goes to the Python runner, in order, --help too.
  c->prefix_command();
  c->allow_extras();
  c->fallthrough(false);
  c->set_help_flag();
  c->callback([c]() { run(c->remaining()); });
});

}  // namespace
}  // namespace msmesh::cli
