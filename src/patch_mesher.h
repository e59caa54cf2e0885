// Internal: meshing a surface patch by patch (the CAD-like part, the pyramid).
//
// Each patch is developed into the plane, filled with interior points (a triangular lattice,
// or Poisson-disk samples for irregular meshes), triangulated by a constrained Delaunay
// triangulation whose constraints are the patch boundary, and mapped back onto the surface.
// Curves shared by two patches are sampled once, so the result is watertight.
#pragma once
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "msmesh/mesh.h"
#include "random.h"
#include "shape_builder.h"

namespace msmesh::detail {

/// Target edge length at a point of the surface.
using SizeField = std::function<double(const Vec3&)>;
/// A curve t ∈ [0,1] ↦ R³.
using Curve = std::function<Vec3(double)>;
/// Isometric development of a patch into the plane, and its inverse.
using Develop = std::function<Vec2(const Vec3&)>;
using Embed = std::function<Vec3(const Vec2&)>;

enum class InteriorSampling {
  Lattice,      ///< equilateral triangular lattice (regular meshes; constant size field)
  PoissonDisk,  ///< randomised maximal Poisson-disk samples (irregular meshes; any size field)
};

/// Builds a mesh patch by patch. Corners and curves are created first; each patch is then
/// bounded by a loop of curve vertices, so patches sharing a curve share its vertices.
class PatchMesher {
 public:
  /// size: target edge length; sampling: how patch interiors are filled; seed: random
  /// numbers (Poisson-disk sampling and curve jitter); curve_jitter in [0, 0.4]: curve
  /// samples move by up to this fraction of the gap to their neighbour.
  PatchMesher(SizeField size, InteriorSampling sampling, std::uint64_t seed = 0, double curve_jitter = 0)
      : size_(std::move(size)), sampling_(sampling), rng_(seed), curve_jitter_(curve_jitter) {}

  int add_corner(const Vec3& p) { return mesh_.add_vertex(p); }
  const Vec3& position(int v) const { return mesh_.V[v]; }

  /// Samples `curve` (curve(0) at corner a, curve(1) at corner b) with edges of about the
  /// target size. Returns the vertex ids along it, a first and b last.
  std::vector<int> add_curve(int a, int b, const Curve& curve);

  /// Triangulates the patch bounded by `loop` (vertex ids, counter-clockwise seen from
  /// outside), developed into the plane by to_plane and mapped back by to_surface.
  void add_patch(const std::vector<int>& loop, const Develop& to_plane, const Embed& to_surface);

  /// A planar patch bounded by `loop` (counter-clockwise seen from outside).
  void add_planar_patch(const std::vector<int>& loop);

  Mesh to_mesh() const { return mesh_.to_mesh(); }

 private:
  /// Points strictly inside the polygon q (#q by 2, either orientation), away from its edges.
  std::vector<Vec2> interior_points(const std::vector<Vec2>& q, const Embed& to_surface);

  MeshBuilder mesh_;
  SizeField size_;
  InteriorSampling sampling_;
  Random<SplitMix64> rng_;
  double curve_jitter_;
};

/// Appends a curve's vertex ids to a patch loop, without its last one (the next curve's first).
inline void append_curve(std::vector<int>& loop, const std::vector<int>& curve, bool reversed = false) {
  if (reversed)
    loop.insert(loop.end(), curve.rbegin(), curve.rend() - 1);
  else
    loop.insert(loop.end(), curve.begin(), curve.end() - 1);
}

}  // namespace msmesh::detail
