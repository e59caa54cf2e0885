// `msmesh eval`: the error figures of a result against a ground truth, as text and JSON.
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "cli_helpers.h"
#include "msmesh/io.h"

using namespace msmesh;

TEST(EvalCli, FacesTheTruthFoldsAreReportedApart) {
  const test::TempDir dir;
  const std::string result = dir.file("result.obj"), truth = dir.file("truth.obj");
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
}
