// Typed exceptions of msmesh. The library never prints: every failure is one of these,
// with a message that names the file, element and value concerned.
#pragma once
#include <stdexcept>
#include <string>

namespace msmesh {

/// Base class of every error msmesh throws.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

/// The input mesh or a parameter is not acceptable (NaN, index out of range, bad value).
class InvalidInput : public Error {
 public:
  explicit InvalidInput(const std::string& what) : Error(what) {}
};

/// A linear solver or factorisation failed (not positive definite, numerical issue).
class SolverError : public Error {
 public:
  explicit SolverError(const std::string& what) : Error(what) {}
};

/// Reading or writing a file failed (missing, unknown format, malformed, truncated).
class IoError : public Error {
 public:
  explicit IoError(const std::string& what) : Error(what) {}
};

/// The progress callback asked to stop.
class Cancelled : public Error {
 public:
  explicit Cancelled(const std::string& what) : Error(what) {}
};

}  // namespace msmesh
