// The parameter tables (msmesh/parameters.h): ranges, checks, parsing, and that every entry
// reads and writes the field it names.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

#include "msmesh/errors.h"
#include "msmesh/inpaint.h"
#include "msmesh/parameters.h"
#include "msmesh/presets.h"
#include "msmesh/segment.h"

using namespace msmesh;

namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

/// A value inside the entry's range other than `current`.
double another_valid_value(const ParameterInfo& i, double current) {
  if (i.type == ParameterType::Boolean) return current != 0 ? 0 : 1;
  const double lo = std::isfinite(i.range.min) ? i.range.min : -1e6;
  const double hi = std::isfinite(i.range.max) ? i.range.max : lo + 1e6;
  for (double t : {0.25, 0.5, 0.75}) {
    double x = lo + t * (hi - lo);
    if (i.type == ParameterType::Integer) x = std::round(x);
    if (i.range.contains(x) && x != current) return x;
  }
  return current;
}

/// Every entry: names unique, its value valid at the defaults, and set() changes what get()
/// reads and nothing else in the table (except entries that share a field on purpose).
template <class Options>
void check_table(const ParameterTable<Options>& table, const std::string& what) {
  std::set<std::string> names;
  const Options defaults;
  for (const Parameter<Options>& p : table) {
    SCOPED_TRACE(what + " " + p.info.name);
    EXPECT_TRUE(names.insert(p.info.name).second) << "duplicate";
    EXPECT_FALSE(p.info.help.empty());
    EXPECT_FALSE(p.info.group.empty());
    EXPECT_EQ(p.info.key().find('-'), std::string::npos);
    EXPECT_NO_THROW(check_parameter(p.info, p.get(defaults)));
    Options o;
    const double x = another_valid_value(p.info, p.get(o));
    ASSERT_NE(x, p.get(o));
    p.set(o, x);
    EXPECT_EQ(p.get(o), x);
    for (const Parameter<Options>& q : table)
      if (&q != &p) EXPECT_EQ(q.get(o), q.get(defaults)) << "set " << p.info.name << " changed " << q.info.name;
  }
}

}  // namespace

TEST(Parameters, EveryTableEntrySetsItsOwnField) {
  check_table(normal_filter_parameters(), "normal filter");
  check_table(vertex_update_parameters(), "vertex update");
  check_table(bilateral_parameters(), "bilateral");
  check_table(denoise_parameters(), "denoise");
  check_table(inpaint_parameters(), "inpaint");
  check_table(segment_parameters(), "segment");
}

TEST(Parameters, SharedEntriesSetBothFields) {
  DenoiseOptions o;
  find_parameter(denoise_parameters(), "vertex-iterations")->set(o, 7);
  EXPECT_EQ(o.vertices.max_iterations, 7);
  EXPECT_EQ(o.bilateral.vertex_iterations, 7);
  find_parameter(denoise_parameters(), "solver_tolerance")->set(o, 1e-5);  // Python spelling finds it too
  EXPECT_EQ(o.normals.solver_tolerance, 1e-5);
  EXPECT_EQ(o.vertices.solver_tolerance, 1e-5);
  EXPECT_EQ(find_parameter(denoise_parameters(), "no-such-thing"), nullptr);
}

TEST(Parameters, RangesAreDescribedAndChecked) {
  const ParameterInfo& alpha = find_parameter(normal_filter_parameters(), "alpha")->info;
  EXPECT_EQ(alpha.describe_range(), "> 0");
  EXPECT_EQ(alpha.symbol, "α");
  const ParameterInfo& nu = find_parameter(normal_filter_parameters(), "nu")->info;
  EXPECT_TRUE(nu.range.contains(1.618));
  EXPECT_FALSE(nu.range.contains(1.62));
  EXPECT_FALSE(nu.range.contains(0));
  const ParameterInfo& its = find_parameter(normal_filter_parameters(), "normal-iterations")->info;
  EXPECT_EQ(its.describe_range(), "a whole number in [1, 100000]");

  EXPECT_NO_THROW(check_parameter(alpha, 3));
  for (double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    EXPECT_THROW(check_parameter(alpha, bad), InvalidInput) << bad;
  EXPECT_THROW(check_parameter(its, 2.5), InvalidInput);
  const std::string m = message_of([&] { check_parameter(alpha, -2, "--alpha"); });
  EXPECT_NE(m.find("normal filtering: --alpha = -2 is out of range; valid: > 0"), std::string::npos) << m;
}

TEST(Parameters, ParsingTakesOnlyWholeNumbers) {
  const ParameterInfo& alpha = find_parameter(normal_filter_parameters(), "alpha")->info;
  EXPECT_EQ(parse_parameter(alpha, "2.5"), 2.5);
  EXPECT_EQ(parse_parameter(alpha, "1e-3"), 1e-3);
  for (const char* bad : {"", " ", "2.5x", "x", "1,5", "--3", "0x10"})
    EXPECT_THROW(parse_parameter(alpha, bad, "--alpha"), InvalidInput) << "'" << bad << "'";
  EXPECT_NE(message_of([&] { parse_parameter(alpha, "", "--alpha"); }).find("--alpha = '' is not a number"),
            std::string::npos);
  const ParameterInfo& project = find_parameter(normal_filter_parameters(), "project-each-iteration")->info;
  EXPECT_EQ(parse_parameter(project, "true"), 1);
  EXPECT_EQ(parse_parameter(project, "OFF"), 0);
  EXPECT_THROW(parse_parameter(project, "2"), InvalidInput);
}

TEST(Parameters, ValidateUsesTheTablesNames) {
  NormalFilterOptions n;
  n.max_iterations = 0;
  EXPECT_NE(message_of([&] { n.validate(); }).find("normal-iterations = 0"), std::string::npos);
  SegmentOptions s;
  s.clamp_probability = 0.7;
  EXPECT_NE(message_of([&] { s.validate(); }).find("segmentation: clamp = 0.7"), std::string::npos);
  InpaintOptions i;
  i.rounds = 0;
  EXPECT_NE(message_of([&] { i.validate(); }).find("inpainting: rounds = 0"), std::string::npos);
  i = InpaintOptions{};
  i.normals.gamma = -1;  // the lifted normal filter entries are checked too
  EXPECT_NE(message_of([&] { i.validate(); }).find("gamma = -1"), std::string::npos);
}

TEST(Parameters, ValuesAreFormattedExactlyAndShortly) {
  const ParameterInfo& alpha = find_parameter(normal_filter_parameters(), "alpha")->info;
  EXPECT_EQ(alpha.format(2.5), "2.5");
  EXPECT_EQ(alpha.format(100000), "100000");
  EXPECT_EQ(alpha.format(1e-8), "1e-08");
  EXPECT_EQ(alpha.format(0.1), "0.1");
  const ParameterInfo& project = find_parameter(normal_filter_parameters(), "project-each-iteration")->info;
  EXPECT_EQ(project.format(1), "on");
}

TEST(Parameters, CheckWithoutATableEntryNamesParameterValueAndRange) {
  // check_parameter(group, name, value, range): for values that have no table entry (feature
  // lines' threshold), with the tables' message.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(message_of([] {
              check_parameter("stage", "alpha", -1, {0, kInf, true, false});
            }),
            "stage: alpha = -1 is out of range; valid: > 0");
  EXPECT_EQ(message_of([] {
              check_parameter("stage", "sigma", -2, {0, kInf});
            }),
            "stage: sigma = -2 is out of range; valid: >= 0");
  EXPECT_EQ(message_of([] {
              check_parameter("stage", "k", 0, {1, 100});
            }),
            "stage: k = 0 is out of range; valid: in [1, 100]");
  EXPECT_EQ(message_of([] {
              check_parameter("stage", "t", 1, {0, 1, false, true});
            }),
            "stage: t = 1 is out of range; valid: in [0, 1)");
  EXPECT_EQ(message_of([] {
              check_parameter("stage", "t", 0, {0, 1, true, false});
            }),
            "stage: t = 0 is out of range; valid: in (0, 1]");
  EXPECT_NE(message_of([] { check_parameter("stage", "t", std::nan(""), {0, 1}); }), "");
  EXPECT_NE(message_of([] { check_parameter("stage", "t", kInf, {0, kInf}); }), "");
  EXPECT_EQ(message_of([] { check_parameter("stage", "t", 1, {0, 1}); }), "");
  EXPECT_EQ(message_of([] { check_parameter("stage", "t", 1e-300, {0, kInf, true, false}); }), "");
}
