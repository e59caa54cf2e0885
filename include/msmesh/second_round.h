// Preset auto's second round under heavy noise (docs/presets.md, "A second round under heavy
// noise"): auto again on the first round's result, its positions blended into the first round's
// with the weight the first estimate gave (ResolvedPreset::second_round).
#pragma once
#include <Eigen/Core>
#include <functional>

#include "msmesh/denoise.h"
#include "msmesh/presets.h"
#include "msmesh/progress.h"

namespace msmesh {

/// The caller's own settings on top of a resolved preset's options (method, parameter
/// overrides, solver): applied to the second round's options as to the first's.
using AdjustOptions = std::function<void(DenoiseOptions&)>;

/// What the second round ran: its weight (0: none ran) and auto as resolved on the first round's
/// result, at the same strength, with its options adjusted.
struct SecondRound {
  double weight = 0;
  ResolvedPreset preset;
};

/// denoise(V, F, options) and then, when `first.second_round` > 0 (auto under heavy noise),
/// the second round: resolve_preset("auto") on the result at first.strength, `adjust` on its
/// options, denoise() of the result, and the positions (1 − w) V₁ + w V₂, w = first.second_round.
/// The result's filtered normals, edge field and reports are the second round's (the field of
/// the cleaner mesh), its times and despiked vertices the sums of both rounds'. `second`
/// (optional) receives what the second round ran. Throws as denoise().
DenoiseResult denoise_in_rounds(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ResolvedPreset& first,
                                const DenoiseOptions& options, const AdjustOptions& adjust,
                                const ProgressCallback& progress = {}, SecondRound* second = nullptr);

}  // namespace msmesh
