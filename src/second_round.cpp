#include "msmesh/second_round.h"

#include <utility>

namespace msmesh {

DenoiseResult denoise_in_rounds(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ResolvedPreset& first,
                                const DenoiseOptions& options, const AdjustOptions& adjust,
                                const ProgressCallback& progress, SecondRound* second) {
  DenoiseResult r = denoise(V, F, options, progress);
  const double w = first.second_round;  // 0 unless auto asked for one
  if (second) *second = SecondRound{};
  if (!(w > 0)) return r;
  ResolvedPreset again = resolve_preset("auto", r.V, F, first.strength);
  DenoiseOptions o = again.options;
  if (adjust) adjust(o);
  DenoiseResult s = denoise(r.V, F, o, progress);
  // r.V + w (V₂ − r.V): a vertex both rounds leave where it was (unreferenced) stays bit for bit.
  s.V = r.V + w * (s.V - r.V);
  s.seconds_normals += r.seconds_normals;
  s.seconds_vertices += r.seconds_vertices;
  s.despiked_vertices += r.despiked_vertices;
  if (second) {
    second->weight = w;
    second->preset = std::move(again);
  }
  return s;
}

}  // namespace msmesh
