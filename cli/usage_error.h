// Usage errors: a wrong option, value or combination of options. main() reports them like
// every error ("msmesh: error: ...") but exits with status 2 instead of 1 (README, "Exit status").
#pragma once
#include <string>

#include "msmesh/errors.h"

namespace msmesh::cli {

class UsageError : public InvalidInput {
 public:
  explicit UsageError(const std::string& what) : InvalidInput(what) {}
};

}  // namespace msmesh::cli
