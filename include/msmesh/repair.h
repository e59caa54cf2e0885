// Mesh repair: fixes what can be fixed in messy scans and CAD exports (duplicate vertices,
// degenerate and duplicate faces, inconsistent orientation, non-manifold vertices and edges,
// unreferenced vertices) and reports what it did. See docs/robustness.md.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "msmesh/mesh.h"
#include "msmesh/parameters.h"

namespace msmesh {

struct RepairOptions {
  /// Merge vertices closer than weld_tolerance × (mean edge length): faces are redirected to
  /// the first (lowest-index) vertex of each cluster. 0 merges exact duplicates only; the
  /// duplicates stay in the vertex array, unreferenced, unless remove_unreferenced. ≥ 0.
  bool merge_duplicate_vertices = true;
  double weld_tolerance = 0.0;
  /// Remove faces that repeat a vertex (also after merging) or whose area is at most
  /// zero_area_tolerance × (mean edge length)². ≥ 0.
  bool remove_degenerate_faces = true;
  double zero_area_tolerance = 1e-12;
  /// Remove faces with the same three vertices as an earlier face (in any order/orientation).
  bool remove_duplicate_faces = true;
  /// Orient the faces of each connected component consistently (breadth-first over manifold
  /// edges from the component's first face); open components then keep the orientation of the
  /// majority of their faces, closed ones are turned to face outwards (positive volume).
  bool orient = true;
  /// Give each fan of faces around a non-manifold vertex (including the ends of non-manifold
  /// edges) its own copy of the vertex; copies are appended after the existing vertices.
  bool split_non_manifold = false;
  /// Remove vertices no face refers to. This renumbers vertices (the only option that does).
  bool remove_unreferenced = false;

  /// Throws InvalidInput naming the parameter and its valid range.
  void validate() const;
};

/// weld (weld_tolerance) and zero-area-tolerance: names and ranges ([0, 1]) shared by
/// validate(), `msmesh repair --weld` and Python (parameters.h).
const ParameterTable<RepairOptions>& repair_parameters();

/// What repair_mesh() did; every count is 0 when there was nothing to do.
struct RepairReport {
  Eigen::Index vertices_before = 0, faces_before = 0;
  Eigen::Index vertices_after = 0, faces_after = 0;
  Eigen::Index merged_vertices = 0;           ///< vertices redirected to an equal/close earlier one
  Eigen::Index degenerate_faces_removed = 0;  ///< faces repeating a vertex
  Eigen::Index zero_area_faces_removed = 0;   ///< faces of (near) zero area
  Eigen::Index duplicate_faces_removed = 0;
  Eigen::Index flipped_faces = 0;              ///< faces reversed by orientation
  Eigen::Index components = 0;                 ///< connected components of faces after repair
  Eigen::Index non_orientable_components = 0;  ///< components that cannot be oriented (Moebius-like)
  Eigen::Index split_vertices = 0;             ///< vertex copies added by split_non_manifold
  Eigen::Index unreferenced_vertices_removed = 0;
  Eigen::Index unreferenced_vertices = 0;  ///< vertices no face refers to, after repair
  Eigen::Index non_manifold_edges = 0;     ///< after repair
  Eigen::Index non_manifold_vertices = 0;  ///< after repair
  /// #V_before: new index of each input vertex (-1 if removed). Identity unless
  /// remove_unreferenced.
  Eigen::VectorXi vertex_map;
  /// #F_after: input face each output face comes from (face order is kept).
  Eigen::VectorXi face_origin;
  /// What happened to the attributes (carry_attributes, mesh_attributes.h), e.g. per-vertex
  /// texture coordinates that became per-corner when merged vertices had different ones.
  std::vector<std::string> attribute_notes;

  /// True when the mesh was changed.
  bool changed() const;
  /// One line per action taken, e.g. "removed 3 duplicate faces"; empty when nothing was done.
  std::vector<std::string> actions() const;
};

/// Repairs `mesh` in place: V, F and every attribute (mesh.h) are kept consistent: per-vertex
/// ones follow their vertices, per-face ones their faces (texture coordinates their corners,
/// also on flipped faces). Vertex order is kept (new vertices from splitting are appended) unless
/// remove_unreferenced; face order is kept apart from removed faces. Throws InvalidInput for
/// non-finite coordinates or out-of-range indices (which cannot be repaired meaningfully).
RepairReport repair_mesh(Mesh& mesh, const RepairOptions& options = {});

}  // namespace msmesh
