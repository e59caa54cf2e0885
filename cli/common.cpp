#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "command.h"
#include "msmesh/errors.h"

namespace msmesh::cli {

std::vector<CommandSpec>& command_registry() {
  static std::vector<CommandSpec> registry;
  return registry;
}

namespace {
bool g_line_open = false;
}

ProgressCallback make_progress_bar(bool quiet) {
  if (quiet || !isatty(STDERR_FILENO)) return {};
  return [](const ProgressEvent& ev) {
    const int width = 30;
    const double frac = ev.max_iterations > 0 ? std::min(1.0, double(ev.iteration) / ev.max_iterations) : 0.0;
    const int filled = static_cast<int>(std::round(frac * width));
    std::string bar(filled, '#');
    bar.resize(width, '-');
    std::fprintf(stderr, "\r%-18s [%s] %3d/%-3d", ev.stage.c_str(), bar.c_str(), ev.iteration, ev.max_iterations);
    if (std::isfinite(ev.residual)) std::fprintf(stderr, "  residual %.3e", ev.residual);
    std::fprintf(stderr, "\x1b[K");
    std::fflush(stderr);
    g_line_open = true;
    return true;
  };
}

void finish_progress_line() {
  if (g_line_open) {
    std::fprintf(stderr, "\r\x1b[K");
    std::fflush(stderr);
    g_line_open = false;
  }
}

std::string fmt(double x, int precision) {
  std::ostringstream os;
  os.precision(precision);
  os << x;
  return os.str();
}

}  // namespace msmesh::cli
