// The command line made from the parameter tables: --help shows the values the code uses,
// `msmesh params` prints them, and typed values are checked with the option's name.
#include <gtest/gtest.h>

#include "cli_helpers.h"
#include "msmesh/inpaint.h"
#include "msmesh/parameters.h"
#include "msmesh/presets.h"
#include "msmesh/segment.h"

using namespace msmesh;

namespace {

/// The help line of option --name in `text` (CLI11 puts a long help on the option's line).
std::string help_line(const std::string& text, const std::string& name) {
  const std::string key = "  --" + name + " ";
  const std::size_t at = text.find(key);
  if (at == std::string::npos) return "";
  return text.substr(at, text.find('\n', at) - at);
}

template <class Options>
void expect_help_shows(const std::string& help, const ParameterTable<Options>& table,
                       const std::vector<std::pair<std::string, Options>>& defaults, const std::string& what) {
  for (const Parameter<Options>& p : table) {
    SCOPED_TRACE(what + " --" + p.info.name);
    const std::string line = help_line(help, p.info.name);
    ASSERT_FALSE(line.empty()) << "--" << p.info.name << " missing from the help";
    bool same = true;
    for (const auto& d : defaults) same = same && p.get(d.second) == p.get(defaults[0].second);
    for (const auto& [label, o] : defaults) {
      const std::string shown = (same || label.empty() ? "" : label + " ") + p.info.format(p.get(o));
      EXPECT_NE(line.find(shown), std::string::npos) << "expected '" << shown << "' in: " << line;
      if (same) break;
    }
    if (p.info.type != ParameterType::Boolean) EXPECT_NE(line.find(p.info.describe_range()), std::string::npos) << line;
  }
}

}  // namespace

TEST(ParamsCli, HelpShowsTheDefaultsTheCodeUses) {
  const auto denoise = test::run_cli("denoise --help");
  ASSERT_EQ(denoise.status, 0) << denoise.out;
  std::vector<std::pair<std::string, DenoiseOptions>> presets;
  for (const std::string& name : preset_names()) presets.emplace_back(name, preset_options(name));
  expect_help_shows(denoise.out, denoise_parameters(), presets, "denoise");
  EXPECT_NE(denoise.out.find("--preset TEXT:{auto,cad,smooth,paper}=auto"), std::string::npos) << denoise.out;

  const auto inpaint = test::run_cli("inpaint --help");
  ASSERT_EQ(inpaint.status, 0) << inpaint.out;
  expect_help_shows(inpaint.out, inpaint_parameters(), {{"", InpaintOptions{}}}, "inpaint");

  const auto segment = test::run_cli("segment --help");
  ASSERT_EQ(segment.status, 0) << segment.out;
  std::vector<std::pair<std::string, SegmentOptions>> seg;
  for (const std::string& name : preset_names()) {
    seg.emplace_back(name, SegmentOptions{});
    seg.back().second.normals = preset_options(name).normals;
  }
  expect_help_shows(segment.out, segment_parameters(), seg, "segment");
}

TEST(ParamsCli, ParamsPrintsAPresetAndAutoForAMesh) {
  const auto smooth = test::run_cli("params --preset smooth --json");
  ASSERT_EQ(smooth.status, 0) << smooth.out;
  EXPECT_NE(smooth.out.find("\"preset\":\"smooth\""), std::string::npos) << smooth.out;
  EXPECT_NE(smooth.out.find("\"rho\":0.9"), std::string::npos) << smooth.out;
  EXPECT_NE(smooth.out.find("\"normal_iterations\":30"), std::string::npos) << smooth.out;

  const auto table = test::run_cli("params --preset cad");
  ASSERT_EQ(table.status, 0) << table.out;
  EXPECT_NE(table.out.find("--alpha"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("2.5"), std::string::npos) << table.out;

  const test::TempDir tmp;  // removed with its content at the end
  const std::filesystem::path& dir = tmp.path();
  const std::string mesh = (dir / "part.obj").string();
  ASSERT_EQ(test::run_cli("shape fandisk --resolution 8 -q -o " + mesh).status, 0);
  const auto automatic = test::run_cli("params " + mesh);
  ASSERT_EQ(automatic.status, 0) << automatic.out;
  EXPECT_NE(automatic.out.find("preset cad, chosen automatically (noise sigma"), std::string::npos) << automatic.out;
  EXPECT_NE(automatic.out.find("crease fraction"), std::string::npos) << automatic.out;

  const auto no_mesh = test::run_cli("params");
  EXPECT_EQ(no_mesh.status, 2) << no_mesh.out;
  EXPECT_NE(no_mesh.out.find("msmesh: error: params: --preset auto is chosen from a mesh"), std::string::npos)
      << no_mesh.out;
  EXPECT_EQ(test::run_cli("params --command inpaint --preset cad").status, 2);
  EXPECT_EQ(test::run_cli("params --command segment --preset auto").status, 2);
  EXPECT_EQ(test::run_cli("params --command inpaint -q").status, 0);
}

TEST(ParamsCli, UsageErrorsExitTwoAndNameTheClosestOption) {
  const test::TempDir tmp;  // removed with its content at the end
  const std::filesystem::path& dir = tmp.path();
  const std::string in = (dir / "m.obj").string(), out = (dir / "o.obj").string();
  ASSERT_EQ(test::run_cli("shape cube --resolution 2 -q -o " + in).status, 0);
  struct Case {
    std::string args, expected;
  };
  const Case cases[] = {
      {"denoize " + in + " -o " + out, "did you mean 'denoise'?"},
      {"denoise " + in + " -o " + out + " --alhpa 3", "did you mean '--alpha'?"},
      {"inpaint " + in + " -o " + out + " --no-featurs", "did you mean '--no-features'?"},
      {"denoise " + in + " -o " + out + " --alpha ''", "--alpha = '' is not a number"},
      {"denoise " + in + " -o " + out + " --alpha 2x", "--alpha = '2x' is not a number"},
      {"denoise " + in + " -o " + out + " --normal-iterations 2.5", "--normal-iterations = 2.5 is out of range"},
      {"denoise " + in + " -o " + out + " --crease", "--crease"},
      {"inpaint " + in + " -o " + out + " --features --no-features", "contradict"},
      {"denoise " + in + " -o " + out + " --method bilateral --save-field " + (dir / "v.txt").string(),
       "--save-field needs --method nmstv or mstv"},
      {"", "A subcommand is required"},
  };
  for (const Case& c : cases) {
    const auto run = test::run_cli(c.args);
    EXPECT_EQ(run.status, 2) << c.args << ": " << run.out;
    EXPECT_NE(run.out.find("msmesh: error: "), std::string::npos) << c.args << ": " << run.out;
    EXPECT_NE(run.out.find(c.expected), std::string::npos) << c.args << ": " << run.out;
    EXPECT_FALSE(std::filesystem::exists(out)) << c.args;
  }
  // A failure of the work (here an unreadable input) exits 1.
  const auto missing = test::run_cli("denoise " + (dir / "none.obj").string() + " -o " + out);
  EXPECT_EQ(missing.status, 1) << missing.out;
  EXPECT_NE(missing.out.find("msmesh: error: "), std::string::npos) << missing.out;
}

TEST(ParamsCli, QuietMeansTheSameOnEverySubcommand) {
  const test::TempDir tmp;  // removed with its content at the end
  const std::filesystem::path& dir = tmp.path();
  const std::string clean = (dir / "c.obj").string(), noisy = (dir / "n.obj").string();
  for (const std::string& args :
       {"shape fandisk --resolution 4 -q -o " + clean, "noise " + clean + " -o " + noisy + " --sigma 0.2 -q",
        "info " + noisy + " -q", "eval " + noisy + " --truth " + clean + " -q",
        "denoise " + noisy + " -o " + (dir / "d.obj").string() + " -q",
        "holes " + clean + " -o " + (dir / "h.obj").string() + " --count 1 -q",
        "repair " + noisy + " -o " + (dir / "r.obj").string() + " -q", std::string("params --preset cad -q")}) {
    const auto run = test::run_cli(args);
    EXPECT_EQ(run.status, 0) << args << ": " << run.out;
    EXPECT_EQ(run.out, "") << args;
  }
}

TEST(ParamsCli, DenoiseSaysWhatItEstimatedAndTakesAStrength) {
  const test::TempDir tmp;  // removed with its content at the end
  const std::filesystem::path& dir = tmp.path();
  const std::string mesh = (dir / "part.obj").string(), out = (dir / "out.obj").string();
  ASSERT_EQ(test::run_cli("shape fandisk -o " + mesh + " --resolution 8 -q").status, 0);
  const auto noisy = test::run_cli("noise " + mesh + " -o " + mesh + ".noisy.obj --sigma 0.3 --seed 2 -q");
  ASSERT_EQ(noisy.status, 0) << noisy.out;
  const auto run = test::run_cli("denoise " + mesh + ".noisy.obj -o " + out + " --json");
  ASSERT_EQ(run.status, 0) << run.out;
  for (const char* key : {"\"noise_sigma\":", "\"noise_sigma_rms\":", "\"noise_sigma_noise\":", "\"noise_detail\":",
                          "\"noise_level_used\":", "\"noise_detail_as_noise\":", "\"noise_detail_ease\":",
                          "\"strength\":1", "\"prefilter\":"})
    EXPECT_NE(run.out.find(key), std::string::npos) << key << "\n" << run.out;
  const auto text = test::run_cli("denoise " + mesh + ".noisy.obj -o " + out + " --strength 2");
  ASSERT_EQ(text.status, 0) << text.out;
  EXPECT_NE(text.out.find("strength 2.00"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("noise sigma"), std::string::npos) << text.out;
  // Out of range, and with the bilateral baseline: usage errors, nothing written.
  const std::string other = (dir / "other.obj").string();
  EXPECT_EQ(test::run_cli("denoise " + mesh + " -o " + other + " --strength 0").status, 2);
  EXPECT_EQ(test::run_cli("denoise " + mesh + " -o " + other + " --strength 11").status, 2);
  EXPECT_EQ(test::run_cli("denoise " + mesh + " -o " + other + " --strength 2 --method bilateral").status, 2);
  EXPECT_FALSE(std::filesystem::exists(other));
  const auto paper = test::run_cli("params --preset paper --json");
  ASSERT_EQ(paper.status, 0) << paper.out;
  EXPECT_NE(paper.out.find("\"project_each_iteration\":true"), std::string::npos) << paper.out;
  EXPECT_NE(paper.out.find("\"penalty\":1"), std::string::npos) << paper.out;
}
