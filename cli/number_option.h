// Numeric options outside the denoise/inpaint/segment tables (noise --sigma, holes --count,
// render --line-width, shape --resolution, ...): every one is parsed by the same strict parser
// as the table options (msmesh::parse_parameter: the whole text one finite number, in range,
// whole for integers), while the command line is parsed, so that a bad value is a usage error
// (exit 2) naming the option as typed, before any file is read or written.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <utility>

#include "msmesh/errors.h"
#include "msmesh/parameters.h"
#include "usage_error.h"

namespace msmesh::cli {

/// Adds `flags` ("--sigma", "-r,--resolution"): its text goes through parse_parameter(info)
/// and the number to `set`. `info.name` is the long name without "--". The help gets the
/// valid range, the unit and `default_text` (when not empty).
inline CLI::Option* add_number_option(CLI::App* c, const std::string& flags, const ParameterInfo& info,
                                      std::function<void(double)> set, const std::string& help,
                                      const std::string& default_text) {
  const std::string as_typed = "--" + info.name;
  auto parse = [info, as_typed, set = std::move(set)](const std::string& text) {
    try {
      set(parse_parameter(info, text, as_typed));
    } catch (const InvalidInput& e) {
      throw UsageError(e.what());
    }
  };
  std::string h = help + " (" + info.describe_range() + (info.unit.empty() ? "" : " " + info.unit) + ")";
  if (!default_text.empty()) h += " [default: " + default_text + "]";
  return c->add_option_function<std::string>(flags, parse, h)
      ->type_name(info.type == ParameterType::Integer ? "INT" : "NUM");
}

/// The same for a plain variable (double, int, long long, std::uint64_t): the default shown is
/// its value now.
template <class T>
CLI::Option* add_number_option(CLI::App* c, const std::string& flags, T& target, const ParameterInfo& info,
                               const std::string& help) {
  return add_number_option(
      c, flags, info, [&target](double x) { target = static_cast<T>(x); }, help,
      info.format(static_cast<double>(target)));
}

/// The same for an entry of a library options table (noise_parameters(), repair_parameters(),
/// render_parameters()), setting its field of `options`.
template <class Options>
CLI::Option* add_number_option(CLI::App* c, const std::string& flags, const Parameter<Options>& p, Options& options,
                               const std::string& help) {
  return add_number_option(
      c, flags, p.info, [&p, &options](double x) { p.set(options, x); }, help, p.info.format(p.get(options)));
}

/// A ParameterInfo for a CLI-only number: a real or whole number in `range`.
inline ParameterInfo cli_number(const std::string& command, const std::string& name, ParameterType type,
                                ParameterRange range, const std::string& unit = "") {
  ParameterInfo i;
  i.name = name;
  i.group = command;
  i.type = type;
  i.range = range;
  i.unit = unit;
  return i;
}

}  // namespace msmesh::cli
