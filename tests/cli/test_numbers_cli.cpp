// Numbers accepted that should not be (issue 16, class 6): every numeric option of every
// subcommand goes through one strict parser (parse_parameter): empty text, NaN, infinities,
// out-of-range values and fractions for integers are usage errors (exit 2) that name the
// option as typed, before any file is written; the library's options structs check the same
// ranges (tables), and MSMESH_MEMORY_LIMIT must be a size.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "cli_helpers.h"
#include "msmesh/errors.h"
#include "msmesh/holes.h"
#include "msmesh/inpaint.h"
#include "msmesh/io.h"
#include "msmesh/memory.h"
#include "msmesh/multicut.h"
#include "msmesh/noise.h"
#include "msmesh/render.h"
#include "msmesh/repair.h"

using namespace msmesh;
namespace fs = std::filesystem;

namespace {

struct NumbersCli : ::testing::Test {
  fs::path dir;
  std::string in;
  void SetUp() override {
    dir = test::temp_folder("numbers");
    in = (dir / "in.obj").string();
    write_mesh(in, test::grid(4, 0.1));
  }
  void TearDown() override { fs::remove_all(dir); }

  /// `msmesh ARGS` must exit 2, name `option`, and leave the folder as it was.
  void expect_usage_error(const std::string& args, const std::string& option) {
    SCOPED_TRACE(args);
    const auto before = std::distance(fs::directory_iterator(dir), fs::directory_iterator());
    const test::CliRun r = test::run_cli(args);
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(r.out.find(option), std::string::npos) << r.out;
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), before) << "a file was written";
  }
  std::string out(const std::string& name) const { return (dir / name).string(); }
};

TEST_F(NumbersCli, EmptyValuesAreRefusedNotReadAsZero) {
  expect_usage_error("noise " + in + " -o " + out("n.obj") + " --sigma ''", "--sigma");
  expect_usage_error("noise " + in + " -o " + out("n.obj") + " --seed ''", "--seed");
  expect_usage_error("repair " + in + " -o " + out("r.obj") + " --weld ''", "--weld");
  expect_usage_error("shape cube -o " + out("c.obj") + " --resolution ''", "--resolution");
  expect_usage_error("denoise " + in + " -o " + out("d.obj") + " --threads ''", "--threads");
}

TEST_F(NumbersCli, NanAndInfinitiesAreRefused) {
  for (const char* v : {"nan", "inf", "-inf", "1e400"}) {
    expect_usage_error("noise " + in + " -o " + out("n.obj") + " --sigma=" + v, "--sigma");
    expect_usage_error("render " + in + " -o " + out("r.png") + " --line-width=" + v, "--line-width");
    expect_usage_error("render " + in + " -o " + out("r.png") + " --feature-edges=" + v, "--feature-edges");
    expect_usage_error("segment " + in + " -o " + out("s.ply") + " --min-area=" + v, "--min-area");
  }
}

TEST_F(NumbersCli, NegativeValuesDoNotWrap) {
  expect_usage_error("noise " + in + " -o " + out("n.obj") + " --seed -1", "--seed");
  expect_usage_error("holes " + in + " -o " + out("h.obj") + " --seed -1", "--seed");
  expect_usage_error("features " + in + " -o " + out("f.obj") + " --min-edges -1", "--min-edges");
  expect_usage_error("render " + in + " -o " + out("r.png") + " --line-width -1", "--line-width");
  expect_usage_error("render " + in + " -o " + out("r.png") + " --feature-edges -30", "--feature-edges");
  expect_usage_error("holes " + in + " -o " + out("h.obj") + " --count -3", "--count");
  expect_usage_error("inpaint " + in + " -o " + out("i.obj") + " --holes -1", "--holes");
}

TEST_F(NumbersCli, IntegerOptionsRefuseFractions) {
  expect_usage_error("noise " + in + " -o " + out("n.obj") + " --seed 2.5", "--seed");
  expect_usage_error("features " + in + " -o " + out("f.obj") + " --min-edges 2.5", "--min-edges");
  expect_usage_error("render " + in + " -o " + out("r.png") + " --supersample 2.5", "--supersample");
  expect_usage_error("shape cube -o " + out("c.obj") + " --resolution 2.5", "--resolution");
  expect_usage_error("inpaint " + in + " -o " + out("i.obj") + " --holes 1.5", "--holes");
  expect_usage_error("render " + in + " -o " + out("r.png") + " --size 800.5x600", "--size");
}

TEST_F(NumbersCli, BooleanValuesAreStrict) {
  const std::string holed = out("holed.obj");
  write_mesh(holed, test::grid_with_hole());
  for (const char* v : {"nan", "-1", "2", "maybe"})
    expect_usage_error("inpaint " + holed + " -o " + out("f.obj") + " --project-each-iteration=" + v,
                       "--project-each-iteration");
  EXPECT_EQ(test::run_cli("inpaint " + holed + " -o " + out("f.obj") + " --project-each-iteration=off -q").status, 0);
  EXPECT_EQ(test::run_cli("inpaint " + holed + " -o " + out("g.obj") + " --project-each-iteration -q").status, 0);
}

TEST_F(NumbersCli, ShapeResolutionZeroGivesAShortRange) {
  const test::CliRun r = test::run_cli("shape cube -o " + out("c.obj") + " --resolution 0");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("--resolution = 0 is out of range; valid: a whole number in [1, 1000]"), std::string::npos)
      << r.out;
  EXPECT_LT(r.out.size(), 200u) << r.out;
}

TEST_F(NumbersCli, InpaintDensityHasAnUpperBoundAndAMemoryCheck) {
  expect_usage_error("inpaint " + in + " -o " + out("i.obj") + " --density 1000", "--density");
  // A density in range whose fill needs more than the memory limit fails before any work.
  const std::string holed = out("holed.obj");
  write_mesh(holed, test::grid_with_hole());
  const test::CliRun r = test::run_command("MSMESH_MEMORY_LIMIT=1K " + std::string(MSMESH_CLI_PATH) + " inpaint " +
                                           holed + " -o " + out("f.obj") + " --density 20");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("needs about"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out("f.obj")));
}

TEST_F(NumbersCli, ValidValuesStillWork) {
  EXPECT_EQ(test::run_cli("noise " + in + " -o " + out("n.obj") + " --sigma 0.1 --seed 3 -q").status, 0);
  EXPECT_EQ(test::run_cli("noise " + in + " -o " + out("m.obj") + " --sigma=1e-1 --impulsive 0.5 -q").status, 0);
  EXPECT_EQ(test::run_cli("shape cube -o " + out("c.obj") + " -r 2 -q").status, 0);
  EXPECT_EQ(test::run_cli("render " + in + " -o " + out("r.png") + " --size 64x48 --line-width 0 -q").status, 0);
}

TEST_F(NumbersCli, NoiseCorrelationIsCheckedAndNamed) {
  expect_usage_error("noise " + in + " -o " + out("n.obj") + " --correlation -1", "--correlation");
  expect_usage_error("noise " + in + " -o " + out("n.obj") + " --correlation 1001", "--correlation");
  expect_usage_error("noise " + in + " -o " + out("n.obj") + " --correlation 1.5", "--correlation");
  // Correlated impulsive noise is an impossible combination: refused before anything is written.
  const test::CliRun bad = test::run_cli("noise " + in + " -o " + out("n.obj") + " --correlation 2 --impulsive 0.1");
  EXPECT_NE(bad.status, 0) << bad.out;
  EXPECT_NE(bad.out.find("correlation"), std::string::npos) << bad.out;
  EXPECT_NE(bad.out.find("impulsive"), std::string::npos) << bad.out;
  EXPECT_FALSE(fs::exists(out("n.obj")));
  const test::CliRun ok = test::run_cli("noise " + in + " -o " + out("c.obj") + " --sigma 0.2 --correlation 3");
  EXPECT_EQ(ok.status, 0) << ok.out;
  EXPECT_NE(ok.out.find("correlated over 3 passes"), std::string::npos) << ok.out;
}

TEST(NumbersLibrary, OptionStructsCheckTheirTables) {
  NoiseOptions n;
  n.sigma = 1e308;
  EXPECT_THROW(n.validate(), InvalidInput);
  n.sigma = 0.1;
  n.seed = (std::uint64_t{1} << 60);
  EXPECT_THROW(n.validate(), InvalidInput);
  RepairOptions r;
  r.weld_tolerance = std::nan("");
  EXPECT_THROW(r.validate(), InvalidInput);
  RenderOptions ro;
  ro.line_width = -1;
  try {
    ro.validate();
    ADD_FAILURE() << "line_width -1 accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("render: line-width = -1 is out of range; valid: in (0, 20]"),
              std::string::npos)
        << e.what();
  }
  MulticutOptions m;
  m.max_local_rounds = -1;
  EXPECT_THROW(m.validate(), InvalidInput);
}

TEST(NumbersLibrary, NoiseNeverReturnsNonFiniteCoordinates) {
  Mesh m = test::grid(3);
  m.V *= 1e300;
  NoiseOptions o;
  o.sigma = 1e5;
  EXPECT_THROW(add_noise(m.V, m.F, o), InvalidInput);
}

TEST(NumbersLibrary, MemoryLimitThatIsNotASizeIsAnError) {
  for (const char* v : {"abc", "", "0", "-5", "12Q", "1e999", "5MX"}) {
    SCOPED_TRACE(v);
    ::setenv("MSMESH_MEMORY_LIMIT", v, 1);
    EXPECT_THROW(available_memory_bytes(), InvalidInput);
  }
  ::setenv("MSMESH_MEMORY_LIMIT", "2M", 1);
  EXPECT_EQ(available_memory_bytes() <= 2u * 1024 * 1024, true);
  ::unsetenv("MSMESH_MEMORY_LIMIT");
}

TEST(NumbersLibrary, InpaintMemoryEstimateGrowsWithDensitySquared) {
  const Mesh m = test::grid_with_hole();
  const std::vector<Hole> holes = find_holes(m.V, m.F);
  InpaintOptions o;
  o.density = 2;
  const double a = inpaint_memory_estimate(holes, o);
  o.density = 20;
  const double b = inpaint_memory_estimate(holes, o);
  EXPECT_GT(a, 0);
  EXPECT_GT(b, 50 * a);
}

}  // namespace
