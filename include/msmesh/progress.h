// Progress reporting: the library calls a user-supplied function instead of printing.
#pragma once
#include <functional>
#include <string>

namespace msmesh {

/// One progress event.
///  - stage: short name of the running stage ("normal filtering", "vertex update", ...).
///  - iteration, max_iterations: position within the stage (max 0 when unknown).
///  - residual: the stage's current convergence figure (NaN when none).
struct ProgressEvent {
  std::string stage;
  int iteration = 0;
  int max_iterations = 0;
  double residual = 0.0;
};

/// Called after every iteration of a long stage. Return false to cancel: the algorithm then
/// throws msmesh::Cancelled and leaves its inputs unchanged.
using ProgressCallback = std::function<bool(const ProgressEvent&)>;

}  // namespace msmesh
