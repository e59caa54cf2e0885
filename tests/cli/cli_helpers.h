// Helpers of the command-line tests (msmesh_cli_tests), which run the built msmesh program.
#pragma once
#include <string>

#include "test_helpers.h"

namespace msmesh::test {

/// Runs `msmesh ARGS` (the built program) and captures its output.
inline CliRun run_cli(const std::string& args) { return run_command(std::string(MSMESH_CLI_PATH) + " " + args); }

}  // namespace msmesh::test
