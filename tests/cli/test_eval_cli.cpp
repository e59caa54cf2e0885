// `msmesh eval`: the error figures of a result against a ground truth, as text and JSON.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <random>
#include <string>
#include <utility>

#include "cli_helpers.h"
#include "msmesh/io.h"

using namespace msmesh;
namespace fs = std::filesystem;

namespace {

fs::path temp_folder() {
  std::random_device rd;
  fs::path p =
      fs::temp_directory_path() / ("msmesh_test_eval_" + std::to_string(::getpid()) + "_" + std::to_string(rd()));
  fs::create_directories(p);
  return p;
}

}  // namespace

TEST(EvalCli, FacesTheTruthFoldsAreReportedApart) {
  const fs::path dir = temp_folder();
  const std::string result = (dir / "result.obj").string(), truth = (dir / "truth.obj").string();
  const Mesh flat = test::grid(4);
  Mesh folded = flat;
  std::swap(folded.F(5, 1), folded.F(5, 2));  // the truth turns one face over
  write_mesh(result, flat);
  write_mesh(truth, folded);

  const test::CliRun j = test::run_cli("eval '" + result + "' --truth '" + truth + "' --json");
  EXPECT_EQ(j.status, 0) << j.out;
  for (const char* part :
       {"\"flipped\":1", "\"truth_folded\":1", "\"flipped_outside_folds\":0", "\"msae_outside_folds_e3\":0"})
    EXPECT_NE(j.out.find(part), std::string::npos) << part << " not in " << j.out;

  const test::CliRun t = test::run_cli("eval '" + result + "' --truth '" + truth + "'");
  EXPECT_EQ(t.status, 0) << t.out;
  EXPECT_NE(t.out.find("the truth folds 1 faces against their neighbours; without them: MSAE 0 x 1e-3, flipped 0"),
            std::string::npos)
      << t.out;

  // Against itself nothing is folded and the line is left out.
  const test::CliRun same = test::run_cli("eval '" + result + "' --truth '" + result + "'");
  EXPECT_EQ(same.status, 0) << same.out;
  EXPECT_EQ(same.out.find("folds"), std::string::npos) << same.out;
  fs::remove_all(dir);
}
