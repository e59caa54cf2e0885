// Subcommand registry: every cli/cmd_*.cpp registers itself with a static Registrar, so
// adding a subcommand never touches main.cpp.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "msmesh/progress.h"

namespace msmesh::cli {

struct CommandSpec {
  std::string name;
  int order;                             ///< position in --help
  std::function<void(CLI::App&)> setup;  ///< adds the subcommand and its callback
};

std::vector<CommandSpec>& command_registry();

struct Registrar {
  Registrar(std::string name, int order, std::function<void(CLI::App&)> setup) {
    command_registry().push_back({std::move(name), order, std::move(setup)});
  }
};

/// A progress callback that draws a bar on stderr when it is a terminal, and does nothing
/// otherwise (or when quiet).
ProgressCallback make_progress_bar(bool quiet);
/// Ends the current progress line, if one was drawn.
void finish_progress_line();

/// -q,--quiet, the same on every subcommand: no progress bar and no summary. Errors, notes of
/// what was dropped or repaired in the data, and output asked for with --json still appear.
inline CLI::Option* add_quiet_flag(CLI::App* c, bool& quiet) {
  return c->add_flag(
      "-q,--quiet", quiet,
      "No progress bar and no summary (errors, notes of dropped or repaired data and --json still print)");
}

/// Formats a double compactly for summaries.
std::string fmt(double x, int precision = 4);

}  // namespace msmesh::cli
