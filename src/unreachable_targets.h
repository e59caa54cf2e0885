// Internal: targets a first vertex update could not reach (denoise.cpp; docs/presets.md,
// "Unreachable targets").
#pragma once
#include <Eigen/Core>
#include <vector>

namespace msmesh::detail {

/// What unreachable_targets found.
struct UnreachableTargets {
  std::vector<char> marked;  ///< #F: 1 where the face ended too far from its target
  Eigen::Index faces = 0;    ///< faces marked
};

/// Marks the faces whose normal in positions X (#V by 3) lies more than `angle_deg` from their
/// target N (#F by 3 unit rows). A face whose neighbours hold it on one side of a crease while its
/// target is the other side's (a sliver beside a crease that Algorithm 1 gave the wrong plateau)
/// cannot follow its target: the update leaves it far from it. angle_deg ≤ 0 marks none, and a
/// face the update collapsed (no normal to judge by) is not marked. Independent of the thread
/// count; invariant to scale, position and rotation (of X and N together).
UnreachableTargets unreachable_targets(const Eigen::MatrixXd& X, const Eigen::MatrixXi& F, const Eigen::MatrixXd& N,
                                       double angle_deg);

/// Sets the targets of the marked faces to zero: the vertex update's P-step then leaves such a
/// face as it stands, so at its fixed point the face has no normal term of its own and follows
/// its neighbours (vertex_update.cpp, p_step; a flipped one is no longer turned back by it).
void drop_targets(const std::vector<char>& marked, Eigen::MatrixXd& N);

}  // namespace msmesh::detail
