// Internal: the range checks of the options' validate() functions, with one message format:
//   "<where>: <name> = <value> is out of range; valid: <range>[ <note>]"
// e.g. "normal filtering: alpha = -1 is out of range; valid: > 0".
#pragma once
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "msmesh/errors.h"

namespace msmesh::detail {

/// Which ends of the interval from lo to hi are valid values.
enum class Ends { Closed, Open, OpenClosed, ClosedOpen };

/// Throws InvalidInput with the message above; `range` as it should read, e.g. "(0, 1.618...)".
[[noreturn]] inline void fail_range(const std::string& where, const std::string& name, double value,
                                    const std::string& range) {
  std::ostringstream os;
  os << where << ": " << name << " = " << value << " is out of range; valid: " << range;
  throw InvalidInput(os.str());
}

/// Unless `value` is finite and lies between lo and hi (ends as given), throws InvalidInput
/// naming the range, written "[lo, hi]", "(lo, hi)", ...; with hi = +inf, "> lo" or ">= lo".
/// `note` follows the range in the message, e.g. "(0: no limit)".
inline void check_range(const std::string& where, const std::string& name, double value, double lo, double hi,
                        Ends ends, const std::string& note = "") {
  const bool lo_open = ends == Ends::Open || ends == Ends::OpenClosed;
  const bool hi_open = ends == Ends::Open || ends == Ends::ClosedOpen;
  const bool ok = std::isfinite(value) && (lo_open ? value > lo : value >= lo) && (hi_open ? value < hi : value <= hi);
  if (ok) return;
  std::ostringstream range;
  if (std::isinf(hi))
    range << (lo_open ? "> " : ">= ") << lo;
  else
    range << (lo_open ? "(" : "[") << lo << ", " << hi << (hi_open ? ")" : "]");
  if (!note.empty()) range << " " << note;
  fail_range(where, name, value, range.str());
}

/// value finite and > 0.
inline void check_positive(const std::string& where, const std::string& name, double value) {
  check_range(where, name, value, 0, std::numeric_limits<double>::infinity(), Ends::Open);
}

/// value finite and >= 0.
inline void check_non_negative(const std::string& where, const std::string& name, double value,
                               const std::string& note = "") {
  check_range(where, name, value, 0, std::numeric_limits<double>::infinity(), Ends::ClosedOpen, note);
}

}  // namespace msmesh::detail
