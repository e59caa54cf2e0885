// Internal: numbers in messages and reports (4 significant digits), for inpainting and the
// hole puncher.
#pragma once
#include <sstream>
#include <string>

namespace msmesh::detail {

/// x with 4 significant digits, as an ostream prints it ("0.1", "12.35", "1e+06").
inline std::string num(double x) {
  std::ostringstream os;
  os.precision(4);
  os << x;
  return os.str();
}

}  // namespace msmesh::detail
