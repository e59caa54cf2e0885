// Internal: range checks for the options structs of the core that have no parameter table
// (multicut, noise, repair, feature lines), through check_parameter (parameters.h) so that
// every validate() says the same: "<where>: <name> = <value> is out of range; valid: <range>".
#pragma once
#include <cmath>
#include <limits>
#include <string>

#include "msmesh/parameters.h"

namespace msmesh::detail {

/// Throws InvalidInput unless `value` is finite and in `range` ({min, max, min_open, max_open}).
inline void check_range(const std::string& where, const std::string& name, double value, const ParameterRange& range) {
  check_parameter(where, name, value, range);
}

/// value finite and > 0.
inline void check_positive(const std::string& where, const std::string& name, double value) {
  check_range(where, name, value, {0, std::numeric_limits<double>::infinity(), true, false});
}

/// value finite and >= 0.
inline void check_non_negative(const std::string& where, const std::string& name, double value) {
  check_range(where, name, value, {0, std::numeric_limits<double>::infinity(), false, false});
}

}  // namespace msmesh::detail
