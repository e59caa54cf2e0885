// msmesh: command-line front end. Every subcommand lives in its own cmd_*.cpp.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "command.h"
#include "msmesh/atomic_file.h"
#include "msmesh/errors.h"
#include "msmesh/threads.h"
#include "number_option.h"
#include "runtime_settings.h"
#include "usage_error.h"

namespace {

// Two settings that are only read when the process starts, so msmesh restarts itself once
// with them when the user has not chosen otherwise (docs/performance.md has the figures):
//  - OpenMP waits: a thread that finds no work at a barrier spins, then sleeps. libgomp's
//    default spin (300,000 pauses, milliseconds) holds a core that another process's thread
//    needs (a 1 s job took 10 s under a parallel build), and sleeping at once
//    (OMP_WAIT_POLICY=passive) costs a wake-up at each of the ~1,500 loops of a small
//    denoise (the Cone 0.40 s instead of 0.35 s on an idle machine). So: a short spin
//    (GOMP_SPINCOUNT=kIdleSpinCount) when, at the start, no other task is running on the
//    cores the threads would take, and passive otherwise ("Issue 20, twelfth round").
//  - GLIBC_TUNABLES: freed memory kept for reuse rather than handed back to the system after
//    every iteration (top_pad, trim_threshold, mmap_threshold at its 32 MB maximum): on a
//    virtual machine every fresh page costs a fault and its zeroing. Not transparent huge
//    pages (hugetlb=1, used until 2026-12-03): a madvised huge page needs a free 2 MB block,
//    which the host has often taken back (or the kernel compacts memory for it first), so the
//    first touch cost 3 s per GB instead of 0.4 s with 4 KB pages; the 1.3M-face denoise
//    spent 3.4 s in the kernel instead of 0.65 s (docs/performance.md, "Issue 20, sixth round").
using msmesh::cli::kIdleSpinCount;
using msmesh::cli::kMallocTunables;

/// The threads the parallel loops will use: OMP_NUM_THREADS's first value when set, else every
/// online core (what libgomp takes).
long planned_threads(long cores) {
  const char* env = std::getenv("OMP_NUM_THREADS");
  if (env) {
    char* end = nullptr;
    const long n = std::strtol(env, &end, 10);
    if (end != env && n > 0) return n;
  }
  return cores;
}

/// Whether the cores the threads would take are idle now: /proc/loadavg's count of running
/// tasks (this process among them) against the online cores. False when it cannot tell.
bool cores_idle_for_threads() {
  const long cores = sysconf(_SC_NPROCESSORS_ONLN);
  FILE* f = std::fopen("/proc/loadavg", "r");
  if (!f || cores < 1) {
    if (f) std::fclose(f);
    return false;
  }
  long running = 0;  // the fourth field, "running/total" (the three load averages skipped)
  const int got = std::fscanf(f, "%*f %*f %*f %ld/", &running);
  std::fclose(f);
  if (got != 1) return false;
  return (running - 1) + std::min(planned_threads(cores), cores) <= cores;
}

void restart_with_runtime_settings(char** argv) {
  if (std::getenv("MSMESH_NO_RESTART") != nullptr) return;
  bool changed = false;
  if (std::getenv("OMP_WAIT_POLICY") == nullptr && std::getenv("GOMP_SPINCOUNT") == nullptr)
    changed |= (cores_idle_for_threads() ? setenv("GOMP_SPINCOUNT", kIdleSpinCount, 1)
                                         : setenv("OMP_WAIT_POLICY", "passive", 1)) == 0;
  if (std::getenv("GLIBC_TUNABLES") == nullptr) changed |= setenv("GLIBC_TUNABLES", kMallocTunables, 1) == 0;
  if (!changed) return;
  setenv("MSMESH_NO_RESTART", "1", 1);
  execv("/proc/self/exe", argv);  // returns only on failure: then carry on as we are
}

/// Edit distance between two names (insertions, deletions, substitutions, transpositions).
std::size_t distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

/// The candidate closest to `typed`, or "" when none is close (at most a third of its length).
std::string closest(const std::string& typed, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = typed.size() / 3 + 1;
  for (const std::string& c : candidates) {
    const std::size_t dist = distance(typed, c);
    if (dist < best_d || (dist == best_d && best.empty() && dist <= 2)) {
      best = c;
      best_d = dist;
    }
  }
  return best;
}

/// "did you mean ...?" for the first unknown subcommand or option on the command line.
std::string suggestion(CLI::App& app, int argc, char** argv) {
  CLI::App* sub = nullptr;
  std::vector<std::string> names;
  std::vector<CLI::App*> subs = app.get_subcommands([](CLI::App*) { return true; });
  for (const CLI::App* s : subs) names.push_back(s->get_name());
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (!sub) {
      if (arg == "--threads") {
        ++i;
        continue;
      }
      if (!arg.empty() && arg[0] == '-') continue;
      for (CLI::App* s : subs)
        if (s->get_name() == arg) sub = s;
      if (sub) continue;
      const std::string c = closest(arg, names);
      return c.empty() ? "" : "unknown subcommand '" + arg + "'; did you mean '" + c + "'?";
    }
    if (arg.rfind("--", 0) != 0 || arg == "--") continue;
    const std::string name = arg.substr(0, arg.find('='));
    if (sub->get_option_no_throw(name) || app.get_option_no_throw(name)) continue;
    std::vector<std::string> options;
    for (const CLI::Option* o : sub->get_options())
      for (const std::string& l : o->get_lnames()) options.push_back("--" + l);
    const std::string c = closest(name, options);
    if (!c.empty()) return "unknown option '" + name + "'; did you mean '" + c + "'?";
  }
  return "";
}

/// Every error is reported as "msmesh: error: ..."; usage errors exit with 2, others with 1.
int report_error(const std::string& message, int status) {
  msmesh::cli::finish_progress_line();
  std::cerr << "msmesh: error: " << message << "\n";
  return status;
}

/// A closed standard stream (`>&-`) gets /dev/null opened read-only in its place: the next file
/// opened cannot take its number (so a summary cannot land in an output file) and writes to it
/// still fail (EBADF), which finish_standard_output() reports.
void reserve_standard_streams() {
  for (int fd = 0; fd <= 2; ++fd)
    if (::fcntl(fd, F_GETFD) < 0 && errno == EBADF) {
      const int got = ::open("/dev/null", O_RDONLY);
      if (got >= 0 && got != fd) ::close(got);  // cannot happen: open takes the lowest free number
    }
}

/// Flushes standard output and says whether everything printed reached it (a full disk, a
/// closed descriptor); "" or the reason.
std::string finish_standard_output() {
  std::cout.flush();
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int err = errno;
  if (flushed && std::cout.good() && !std::ferror(stdout)) return "";
  if (!flushed && err != 0) return std::strerror(err);
  return ::write(STDOUT_FILENO, "", 0) < 0 ? std::strerror(errno) : "write error";
}

/// The input file of the subcommand that ran (its positional "input", "result" or "mesh"),
/// or "" when it has none.
std::string input_of(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands())
    for (const char* name : {"input", "result", "mesh"}) {
      const CLI::Option* o = sub->get_option_no_throw(name);
      if (o && o->count() == 1 && !o->results().empty()) return o->results().front();
    }
  return "";
}

/// An error of the work names the input file: "in.obj: v-step conjugate gradient did not
/// converge". File errors (IoError) already start with the file they are about, which may be
/// another one (--truth), so they are left as they are.
std::string naming_input(CLI::App& app, const msmesh::Error& e) {
  const std::string message = e.what(), input = input_of(app);
  if (input.empty() || dynamic_cast<const msmesh::IoError*>(&e) || message.rfind(input + ":", 0) == 0) return message;
  return input + ": " + message;
}

constexpr int kUsageStatus = 2;    // a wrong subcommand, option, value or combination
constexpr int kFailureStatus = 1;  // the work failed: unreadable input, solver failure, ...

/// Parses the command line and runs the subcommand; the exit status.
int run(int argc, char** argv) {
  CLI::App app{
      "msmesh: feature-preserving mesh processing with a Mumford-Shah model on face normals\n"
      "(denoising, inpainting, segmentation; Liu et al. 2022, NMSTV)."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "msmesh 0.1.0");
  // --threads before or after the subcommand (fallthrough passes it up to here); applied as
  // soon as it is parsed, so before any subcommand runs.
  app.fallthrough();
  msmesh::cli::add_number_option(
      &app, "--threads", msmesh::cli::cli_number("command line", "threads", msmesh::ParameterType::Integer, {1, 4096}),
      [](double n) { msmesh::set_threads(static_cast<int>(n)); },
      "Threads for the parallel work (default: every core, or OMP_NUM_THREADS); results are the same for any number",
      "");
  auto& registry = msmesh::cli::command_registry();
  std::sort(registry.begin(), registry.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
  for (const auto& spec : registry) spec.setup(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);  // --help, --version
    std::string message = e.what();
    const std::string hint = suggestion(app, argc, argv);
    if (!hint.empty()) message += " (" + hint + ")";
    return report_error(message + "\nRun 'msmesh --help' or 'msmesh SUBCOMMAND --help' for the options.", kUsageStatus);
  } catch (const msmesh::cli::UsageError& e) {
    return report_error(e.what(), kUsageStatus);
  } catch (const msmesh::Error& e) {
    return report_error(naming_input(app, e), kFailureStatus);
  } catch (const std::bad_alloc&) {
    return report_error("out of memory", kFailureStatus);
  } catch (const std::exception& e) {
    return report_error(e.what(), kFailureStatus);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  reserve_standard_streams();
  restart_with_runtime_settings(argv);
  msmesh::install_output_signal_handlers();  // temporary files removed on SIGINT/SIGTERM/...; SIGXFSZ an error
  int status = run(argc, argv);
  const std::string stdout_error = finish_standard_output();
  if (!stdout_error.empty() && status == 0)
    status = report_error("cannot write to standard output: " + stdout_error, kFailureStatus);
  return status;
}
