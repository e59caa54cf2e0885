// The parameter tables: every user-facing numeric parameter of denoising, inpainting and
// segmentation, once, with its name (as typed on the command line and, with '-' -> '_', in
// Python), symbol, unit, valid range, help and the options field it sets.
//
// Everything that shows or checks a parameter is made from these tables: the CLI options and
// their --help (with the real defaults), the validation messages of every validate(), the
// JSON output, the HTML report's parameter table, `msmesh params`, and the Python keywords and
// docstrings. The values of the named parameter sets are in presets.h.
#pragma once
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace msmesh {

struct NormalFilterOptions;
struct VertexUpdateOptions;
struct BilateralOptions;
struct DenoiseOptions;
struct InpaintOptions;
struct SegmentOptions;

enum class ParameterType {
  Real,     ///< any finite number in the range
  Integer,  ///< a whole number in the range
  Boolean,  ///< 0 (false) or 1 (true)
};

/// The valid values of a numeric parameter: an interval, each end open or closed.
struct ParameterRange {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_open = false;  ///< true: min itself is not allowed
  bool max_open = false;  ///< true: max itself is not allowed
  bool contains(double x) const;
  /// "> 0", ">= 1", "in (0, 2]", "in [0, 1)".
  std::string describe() const;
};

/// What a parameter is, independent of where it is stored.
struct ParameterInfo {
  std::string name;    ///< as typed on the command line without "--": "alpha", "normal-iterations"
  std::string symbol;  ///< the paper's symbol ("α"), or empty
  std::string unit;    ///< "mean edge lengths", "degrees", ...; empty when dimensionless
  ParameterType type = ParameterType::Real;
  ParameterRange range;
  std::string help;   ///< one line: what it does
  std::string group;  ///< "normal filtering", "vertex update", "bilateral", "solver", ...

  /// The name as a Python keyword or JSON key: '-' replaced by '_'.
  std::string key() const;
  /// "alpha > 0", "normal-iterations: integer >= 1", "project-each-iteration: 0 or 1".
  std::string describe_range() const;
  /// A value as it is shown in help and reports (shortest exact decimal; booleans on/off).
  std::string format(double value) const;  // booleans: "on" / "off"
};

/// Throws InvalidInput "`as_typed` = value: must be <range>" when `value` is NaN, infinite,
/// outside the range, not whole (Integer) or not 0/1 (Boolean). `as_typed` defaults to the
/// parameter's name; the CLI passes "--name", Python "name=".
void check_parameter(const ParameterInfo& p, double value, const std::string& as_typed = "");

/// The same check and message ("<group>: <name> = <value> is out of range; valid: <range>") for
/// a value of an options struct without a parameter table (multicut, noise, repair, render).
void check_parameter(const std::string& group, const std::string& name, double value, const ParameterRange& range);

/// Parses a value typed by a user: the whole text must be one finite number ("" and "1x"
/// are refused; Boolean also takes true/false/yes/no/on/off). Throws InvalidInput naming
/// `as_typed` and the text; the value is then checked with check_parameter.
double parse_parameter(const ParameterInfo& p, const std::string& text, const std::string& as_typed = "");

/// A parameter bound to the field(s) of an options struct that it sets.
template <class Options>
struct Parameter {
  ParameterInfo info;
  std::function<double(const Options&)> get;
  std::function<void(Options&, double)> set;
};

template <class Options>
using ParameterTable = std::vector<Parameter<Options>>;

/// A parameter bound to one field (double, bool or an integer type) of Options.
template <class Options, class T>
Parameter<Options> bind_parameter(ParameterInfo info, T Options::*m) {
  return {std::move(info), [m](const Options& o) { return static_cast<double>(o.*m); },
          [m](Options& o, double x) {
            if constexpr (std::is_same_v<T, bool>)
              o.*m = x != 0;
            else
              o.*m = static_cast<T>(x);
          }};
}

/// The largest whole number a double holds exactly (2^53): the top of integer ranges (seeds)
/// that a parsed value must not round or wrap beyond.
constexpr double kLargestExactInteger = 9007199254740992.0;

/// The entry named `name` (CLI or Python spelling), or nullptr.
template <class Options>
const Parameter<Options>* find_parameter(const ParameterTable<Options>& table, const std::string& name) {
  for (const auto& p : table)
    if (p.info.name == name || p.info.key() == name) return &p;
  return nullptr;
}

/// Checks every parameter of `options` (check_parameter); used by the validate() functions.
template <class Options>
void check_parameters(const ParameterTable<Options>& table, const Options& options) {
  for (const auto& p : table) check_parameter(p.info, p.get(options));
}

/// The tables. Denoise's is the normal filter's, the vertex update's and the bilateral
/// baseline's together (`vertex-iterations` sets both vertex updates) plus the solver
/// tolerance; segment's holds the normal filter's and the segmentation's own.
const ParameterTable<NormalFilterOptions>& normal_filter_parameters();
const ParameterTable<VertexUpdateOptions>& vertex_update_parameters();
const ParameterTable<BilateralOptions>& bilateral_parameters();
const ParameterTable<DenoiseOptions>& denoise_parameters();
const ParameterTable<InpaintOptions>& inpaint_parameters();
const ParameterTable<SegmentOptions>& segment_parameters();

}  // namespace msmesh
