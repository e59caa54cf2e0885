// Hole finding: the boundary loops of a mesh, with the rule that tells the outer boundary of an
// open surface (a scan's rim) from its holes. inpaint() fills what find_holes() returns.
#pragma once
#include <Eigen/Core>
#include <vector>

namespace msmesh {

/// One boundary loop of a mesh.
struct Hole {
  /// The boundary vertices in order, walking each boundary edge opposite to the direction in
  /// which its face walks it (so the hole lies to the left seen from outside). For a boundary
  /// that touches itself the walk visits the touching vertices more than once.
  std::vector<int> loop;
  int edges = 0;        ///< number of boundary edges
  double diameter = 0;  ///< largest distance between two loop vertices, in mean edge lengths
  double length = 0;    ///< sum of the boundary edge lengths, in mean edge lengths
  /// Area the loop spans, in squared mean edge lengths: the norm of its vector area
  /// ½ Σ p_k × p_{k+1} (exact for a planar loop, the projected area of a bent one).
  double spanned_area = 0;
  int component = 0;  ///< connected component of faces it borders
  /// The outer boundary of an open surface (see find_holes): never filled unless asked.
  bool outer_boundary = false;
  /// False when the boundary touches itself: some vertex has more than two boundary edges.
  bool simple = true;
  int touching_vertex = -1;  ///< a vertex where a non-simple boundary touches itself
};

/// The boundary loops of (V, F) (#V by 3, #F by 3), in a deterministic order (by smallest
/// vertex index). Edges with exactly one incident face are boundary edges; non-manifold edges
/// (three or more faces) are not.
///
/// Outer-boundary rule: within each connected component of faces, the boundary loop with the
/// largest diameter (ties: more edges) is the component's outer boundary — the rim of an open
/// scan or sheet — when the area it spans is at least a quarter of the component's surface
/// area. A flat sheet's rim spans all of it, a hemispherical scan's rim half; a hole in a
/// closed surface spans a small part of what surrounds it (a cube missing one whole face: 1/5).
std::vector<Hole> find_holes(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

}  // namespace msmesh
