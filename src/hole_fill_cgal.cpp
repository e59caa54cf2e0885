// The only translation unit of inpainting that sees CGAL: hole filling on a Surface_mesh and
// closest-face queries, behind the plain-Eigen declarations of hole_fill.h.
#ifndef CGAL_EIGEN3_ENABLED
#define CGAL_EIGEN3_ENABLED  // fair() needs its default Eigen sparse solver; Eigen is a dependency anyway
#endif
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <exception>
#include <iterator>
#include <string>
#include <vector>

#include "hole_fill.h"
#include "msmesh/errors.h"

namespace msmesh::detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using VertexIndex = SurfaceMesh::Vertex_index;
using FaceIndex = SurfaceMesh::Face_index;
using HalfedgeIndex = SurfaceMesh::Halfedge_index;
namespace PMP = CGAL::Polygon_mesh_processing;

// The border halfedge of the hole `loop` (loop[0] → loop[1]) when walking CGAL's border from
// it visits exactly the loop's vertices in order; otherwise a null halfedge and a reason.
HalfedgeIndex find_border(const SurfaceMesh& mesh, const std::vector<int>& loop, std::string& why) {
  const auto n = static_cast<int>(loop.size());
  const auto nv = static_cast<int>(mesh.number_of_vertices());
  for (int k = 0; k < n; ++k)
    if (loop[k] < 0 || loop[k] >= nv) {
      why = "hole vertex index " + std::to_string(loop[k]) + " is out of range";
      return {};
    }
  const HalfedgeIndex h = mesh.halfedge(VertexIndex(loop[0]), VertexIndex(loop[1 % n]));
  if (h == SurfaceMesh::null_halfedge() || !mesh.is_border(h)) {
    why = "the hole's edge " + std::to_string(loop[0]) + "-" + std::to_string(loop[1 % n]) +
          " is not a border edge of the half-edge mesh (non-manifold neighbourhood)";
    return {};
  }
  HalfedgeIndex g = h;
  for (int k = 0; k < n; ++k) {
    if (static_cast<int>(mesh.source(g)) != loop[k] || !mesh.is_border(g)) {
      why = "the half-edge mesh sees a different border around vertex " + std::to_string(loop[k]) +
            " (non-manifold neighbourhood)";
      return {};
    }
    g = mesh.next(g);
  }
  if (g != h) {
    why = "the half-edge border of this hole is longer than its loop (non-manifold neighbourhood)";
    return {};
  }
  // Start from the border halfedge CGAL itself meets first (lowest index), as a loop over
  // halfedges(mesh) does: the triangulation's tie-breaking depends on the starting halfedge,
  // and this makes the result the one CGAL's own hole-filling example gives.
  HalfedgeIndex best = h;
  for (int k = 0; k < n; ++k, g = mesh.next(g))
    if (g < best) best = g;
  return best;
}

}  // namespace

CgalFillResult fill_holes_cgal(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                               const std::vector<std::vector<int>>& loops, double density, bool fair) {
  const Eigen::Index nv = V.rows(), nf = F.rows();
  SurfaceMesh mesh;
  mesh.reserve(static_cast<SurfaceMesh::size_type>(nv), static_cast<SurfaceMesh::size_type>(3 * nf / 2 + 16),
               static_cast<SurfaceMesh::size_type>(nf));
  // Vertex i of the Surface_mesh is row i of V (unreferenced rows included), so new vertices get
  // indices from #V on, which are also their rows in the output.
  for (Eigen::Index i = 0; i < nv; ++i) mesh.add_vertex(Point(V(i, 0), V(i, 1), V(i, 2)));
  for (Eigen::Index f = 0; f < nf; ++f)
    // A face that would make the half-edge structure non-manifold is refused (null face);
    // it stays in the output, and a hole next to it is reported by find_border().
    mesh.add_face(VertexIndex(F(f, 0)), VertexIndex(F(f, 1)), VertexIndex(F(f, 2)));

  CgalFillResult res;
  res.holes.resize(loops.size());
  std::vector<std::array<int, 3>> new_faces;
  std::vector<int> new_face_hole;
  for (size_t i = 0; i < loops.size(); ++i) {
    CgalHoleOutcome& out = res.holes[i];
    if (loops[i].size() < 3) {
      out.error = "a hole needs at least 3 boundary vertices";
      continue;
    }
    const HalfedgeIndex h = find_border(mesh, loops[i], out.error);
    if (h == SurfaceMesh::null_halfedge()) continue;
    // Nothing is ever removed from the Surface_mesh, so new elements get consecutive indices.
    const auto faces_before = static_cast<int>(mesh.number_of_faces() + mesh.number_of_removed_faces());
    const auto vertices_before = static_cast<int>(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
    // Keep a copy to restore when CGAL throws halfway (its guarantee covers failures it reports).
    SurfaceMesh backup = mesh;
    try {
      std::vector<FaceIndex> patch_faces;
      std::vector<VertexIndex> patch_vertices;
      if (fair) {
        const auto r = PMP::triangulate_refine_and_fair_hole(mesh, h, std::back_inserter(patch_faces),
                                                             std::back_inserter(patch_vertices),
                                                             CGAL::parameters::density_control_factor(density));
        out.faired = std::get<0>(r);
      } else {
        PMP::triangulate_and_refine_hole(mesh, h, std::back_inserter(patch_faces), std::back_inserter(patch_vertices),
                                         CGAL::parameters::density_control_factor(density));
      }
    } catch (const std::exception& e) {
      mesh = std::move(backup);
      out.error = std::string("CGAL hole filling failed: ") + e.what();
      out.faired = false;
      continue;
    }
    const auto faces_after = static_cast<int>(mesh.number_of_faces() + mesh.number_of_removed_faces());
    const auto vertices_after = static_cast<int>(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
    if (faces_after == faces_before || mesh.number_of_removed_faces() > 0) {
      if (mesh.number_of_removed_faces() > 0) mesh = std::move(backup);
      out.error = "CGAL found no triangulation of this hole";
      out.faired = false;
      continue;
    }
    out.filled = true;
    out.first_face = static_cast<int>(nf + new_faces.size());
    out.face_count = faces_after - faces_before;
    out.first_vertex = vertices_before;
    out.vertex_count = vertices_after - vertices_before;
    for (int f = faces_before; f < faces_after; ++f) {
      std::array<int, 3> tri{};
      int k = 0;
      for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(FaceIndex(f)), mesh))
        if (k < 3) tri[k++] = static_cast<int>(v);
      new_faces.push_back(tri);
    }
  }

  const auto total_vertices = static_cast<Eigen::Index>(mesh.number_of_vertices());
  res.V.resize(total_vertices, 3);
  res.V.topRows(nv) = V;  // the input rows, bit for bit
  for (Eigen::Index i = nv; i < total_vertices; ++i) {
    const Point& p = mesh.point(VertexIndex(static_cast<SurfaceMesh::size_type>(i)));
    res.V.row(i) << p.x(), p.y(), p.z();
  }
  res.F.resize(nf + static_cast<Eigen::Index>(new_faces.size()), 3);
  res.F.topRows(nf) = F;
  for (size_t k = 0; k < new_faces.size(); ++k)
    res.F.row(nf + static_cast<Eigen::Index>(k)) << new_faces[k][0], new_faces[k][1], new_faces[k][2];
  return res;
}

Eigen::VectorXi closest_faces(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& P) {
  using Triangle = Kernel::Triangle_3;
  using Iterator = std::vector<Triangle>::const_iterator;
  using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
  if (F.rows() == 0) throw InvalidInput("closest faces: the mesh has no faces");
  std::vector<Triangle> tris;
  std::vector<int> ids;
  for (int pass = 0; pass < 2 && tris.empty(); ++pass)
    for (Eigen::Index f = 0; f < F.rows(); ++f) {
      const Point a(V(F(f, 0), 0), V(F(f, 0), 1), V(F(f, 0), 2));
      const Point b(V(F(f, 1), 0), V(F(f, 1), 1), V(F(f, 1), 2));
      const Point c(V(F(f, 2), 0), V(F(f, 2), 1), V(F(f, 2), 2));
      const Triangle t(a, b, c);
      if (pass == 0 && t.is_degenerate()) continue;
      tris.push_back(t);
      ids.push_back(static_cast<int>(f));
    }
  // Every face degenerate: no face is closer than another; answer the first face.
  Eigen::VectorXi out = Eigen::VectorXi::Zero(P.rows());
  bool all_degenerate = true;
  for (const Triangle& t : tris)
    if (!t.is_degenerate()) all_degenerate = false;
  if (all_degenerate) return out;
  Tree tree(tris.cbegin(), tris.cend());
  tree.accelerate_distance_queries();
  for (Eigen::Index i = 0; i < P.rows(); ++i) {
    const auto hit = tree.closest_point_and_primitive(Point(P(i, 0), P(i, 1), P(i, 2)));
    out(i) = ids[static_cast<size_t>(hit.second - tris.cbegin())];
  }
  return out;
}

}  // namespace msmesh::detail
