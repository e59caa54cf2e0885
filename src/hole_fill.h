// Internal: CGAL's hole filling and closest-face queries behind plain Eigen data. Everything
// that includes CGAL's headers for inpainting lives in hole_fill_cgal.cpp only.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

namespace msmesh::detail {

/// What happened to one hole handed to fill_holes_cgal().
struct CgalHoleOutcome {
  bool filled = false;  ///< a patch was added (false: the mesh is unchanged for this hole)
  bool faired = false;  ///< the fairing solve succeeded (a filled but unfaired patch is kept)
  int first_face = 0;   ///< new faces of this hole: rows [first_face, first_face + face_count) of F
  int face_count = 0;
  int first_vertex = 0;  ///< new vertices of this hole: rows [first_vertex, first_vertex + vertex_count) of V
  int vertex_count = 0;
  std::string error;  ///< why the hole was not filled (empty when filled)
};

struct CgalFillResult {
  Eigen::MatrixXd V;                   ///< #V' by 3: the input rows first (copied bit for bit), then new vertices
  Eigen::MatrixXi F;                   ///< #F' by 3: the input rows first, in order, then the new faces
  std::vector<CgalHoleOutcome> holes;  ///< one per requested loop, in order
};

/// Fills each hole with CGAL::Polygon_mesh_processing::triangulate_refine_and_fair_hole (Liepa
/// 2003: minimal-area triangulation, refinement to the surrounding density, C¹ fairing) on a
/// CGAL::Surface_mesh built from (V, F). Each loop lists the hole's boundary vertices in the
/// direction opposite to the one in which the surrounding faces walk those edges (the
/// direction of CGAL's border halfedges). A loop whose border halfedges are not found in the
/// Surface_mesh (non-manifold neighbourhood, faces CGAL refused) is reported and left open.
/// `density` is CGAL's density_control_factor (√2 by default; larger gives denser patches);
/// `fair` = false stops after triangulation and refinement (no fairing).
CgalFillResult fill_holes_cgal(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                               const std::vector<std::vector<int>>& loops, double density = 1.4142135623730951,
                               bool fair = true);

/// For each row of P (#P by 3), the index of the face of (V, F) closest to it (AABB tree).
/// Zero-area faces are ignored unless every face has zero area. #F must be > 0.
Eigen::VectorXi closest_faces(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& P);

}  // namespace msmesh::detail
