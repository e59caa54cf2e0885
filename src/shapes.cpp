// Procedural test shapes (shapes.h).
//
// Watertightness is built in rather than repaired: every curve shared by two patches (a cube
// edge, a crease of the CAD part, a cylinder rim) is sampled once and both patches use those
// vertices. Faces are listed counter-clockwise seen from outside.
//
// The CAD-like part is in fandisk.cpp; it and the pyramid are meshed patch by patch
// (patch_mesher.h).
#include "msmesh/shapes.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <unordered_map>
#include <utility>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/topology.h"
#include "patch_mesher.h"
#include "shape_builder.h"

namespace msmesh {

using namespace detail;

namespace {

/// Keeps the faces of F (#F by 3) with keep[f] and the vertices they use, re-indexed in
/// their original order.
Mesh submesh(const Mesh& m, const std::vector<bool>& keep) {
  std::vector<int> new_index(static_cast<size_t>(m.V.rows()), -1);
  Eigen::Index nf = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    if (keep[f]) {
      ++nf;
      for (int k = 0; k < 3; ++k) new_index[m.F(f, k)] = 0;
    }
  int nv = 0;
  for (int& i : new_index)
    if (i == 0) i = nv++;
  Mesh out;
  out.V.resize(nv, 3);
  for (Eigen::Index v = 0; v < m.V.rows(); ++v)
    if (new_index[v] >= 0) out.V.row(new_index[v]) = m.V.row(v);
  out.F.resize(nf, 3);
  Eigen::Index g = 0;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    if (keep[f]) {
      for (int k = 0; k < 3; ++k) out.F(g, k) = new_index[m.F(f, k)];
      ++g;
    }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Disk caps of the cylinder: concentric rings whose vertex counts grow linearly with the
// radius, so that triangles stay near-equilateral from the centre to the rim.

/// Triangulates the annulus between two closed rings (vertex ids with their polar angles,
/// increasing, each ring starting near angle 0). `up`: counter-clockwise seen from +z.
void zip_rings(MeshBuilder& b, const std::vector<int>& inner, double inner_offset, const std::vector<int>& outer,
               double outer_offset, bool up) {
  const int ni = static_cast<int>(inner.size()), no = static_cast<int>(outer.size());
  auto emit = [&](int a, int c, int d) { up ? b.add_triangle(a, c, d) : b.add_triangle(a, d, c); };
  int i = 0, o = 0;
  while (i < ni || o < no) {
    const double next_inner = inner_offset + 2 * kPi * (i + 1) / ni;
    const double next_outer = outer_offset + 2 * kPi * (o + 1) / no;
    if (o < no && (i == ni || next_outer <= next_inner)) {
      emit(inner[i % ni], outer[o % no], outer[(o + 1) % no]);
      ++o;
    } else {
      emit(inner[i % ni], outer[o % no], inner[(i + 1) % ni]);
      ++i;
    }
  }
}

/// Adds a flat disk of radius 1 at height z whose rim is `rim` (vertex i at angle 2πi/#rim).
void add_disk_cap(MeshBuilder& b, const std::vector<int>& rim, double z, bool up) {
  const int n = static_cast<int>(rim.size());
  // Radial spacing 1/m matches the rim spacing 2π/n.
  const int m = std::max(1, static_cast<int>(std::lround(n / (2 * kPi))));
  std::vector<int> outer = rim;
  double outer_offset = 0;
  for (int k = m - 1; k >= 1; --k) {
    const int count = std::max(3, static_cast<int>(std::lround(double(n) * k / m)));
    // Alternate rings are turned by half a step so that vertices of neighbouring rings interleave.
    const double offset = ((m - k) % 2) ? kPi / count : 0.0;
    const double r = double(k) / m;
    std::vector<int> ring(static_cast<size_t>(count));
    for (int i = 0; i < count; ++i) {
      const double a = offset + 2 * kPi * i / count;
      ring[i] = b.add_vertex(Vec3(r * std::cos(a), r * std::sin(a), z));
    }
    zip_rings(b, ring, offset, outer, outer_offset, up);
    outer = std::move(ring);
    outer_offset = offset;
  }
  const int centre = b.add_vertex(Vec3(0, 0, z));
  const int no = static_cast<int>(outer.size());
  for (int i = 0; i < no; ++i) {
    if (up)
      b.add_triangle(centre, outer[i], outer[(i + 1) % no]);
    else
      b.add_triangle(centre, outer[(i + 1) % no], outer[i]);
  }
}

// ---------------------------------------------------------------------------------------------
// Holes of make_cube_with_holes.

/// Hole centres: an edge midpoint, a face centre, then the remaining edge midpoints, face
/// centres and corners of [-1,1]^3, each the farthest from those already chosen.
std::vector<Vec3> hole_centres(int count) {
  std::vector<Vec3> sites;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x != 0 || y != 0 || z != 0) sites.emplace_back(x, y, z);
  std::vector<Vec3> chosen{Vec3(1, 0, 1), Vec3(-1, 0, 0)};
  chosen.resize(std::min<size_t>(chosen.size(), static_cast<size_t>(count)));
  while (static_cast<int>(chosen.size()) < count) {
    double best = -1;
    Vec3 pick = Vec3::Zero();
    for (const Vec3& s : sites) {
      double d = std::numeric_limits<double>::infinity();
      for (const Vec3& c : chosen) d = std::min(d, (s - c).norm());
      if (d > best + 1e-12) {
        best = d;
        pick = s;
      }
    }
    chosen.push_back(pick);
  }
  return chosen;
}

constexpr int kMaxHoles = 26;
constexpr double kHoleRadius = 0.3;  // faces whose barycentre is this close to a centre go

}  // namespace

// =============================================================================================

Mesh make_cube(int n) {
  require(n >= 1, int_message("make_cube", "n", ">= 1", n));
  MeshBuilder b;
  // Lattice points (i, j, k) ∈ {0..n}^3 on the surface; each exists once, so the 12 edges
  // and 8 corners are shared by the faces meeting there.
  std::unordered_map<long long, int> index;
  auto vertex = [&](const std::array<int, 3>& ijk) {
    const long long key = (static_cast<long long>(ijk[0]) * (n + 1) + ijk[1]) * (n + 1) + ijk[2];
    const auto [it, inserted] = index.try_emplace(key, static_cast<int>(b.V.size()));
    if (inserted) b.add_vertex(Vec3(-1 + 2.0 * ijk[0] / n, -1 + 2.0 * ijk[1] / n, -1 + 2.0 * ijk[2] / n));
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      // Tangent axes with e_u × e_v = outward normal ±e_axis.
      int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if (side == 0) std::swap(u, v);
      auto at = [&](int i, int j) {
        std::array<int, 3> ijk;
        ijk[axis] = side * n;
        ijk[u] = i;
        ijk[v] = j;
        return vertex(ijk);
      };
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) b.add_quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
    }
  }
  return b.to_mesh();
}

Mesh make_cylinder(int segments, int rings, bool caps) {
  require(segments >= 3, int_message("make_cylinder", "segments", ">= 3", segments));
  require(rings >= 1, int_message("make_cylinder", "rings", ">= 1", rings));
  MeshBuilder b;
  for (int j = 0; j <= rings; ++j)
    for (int i = 0; i < segments; ++i) {
      const double a = 2 * kPi * i / segments;
      b.add_vertex(Vec3(std::cos(a), std::sin(a), -1 + 2.0 * j / rings));
    }
  auto side = [&](int i, int j) { return j * segments + i % segments; };
  for (int j = 0; j < rings; ++j)
    for (int i = 0; i < segments; ++i) b.add_quad(side(i, j), side(i + 1, j), side(i + 1, j + 1), side(i, j + 1));
  if (caps) {
    std::vector<int> bottom(static_cast<size_t>(segments)), top(static_cast<size_t>(segments));
    for (int i = 0; i < segments; ++i) {
      bottom[i] = side(i, 0);
      top[i] = side(i, rings);
    }
    add_disk_cap(b, bottom, -1.0, false);
    add_disk_cap(b, top, 1.0, true);
  }
  return b.to_mesh();
}

Mesh make_sphere(int subdivisions) {
  require(subdivisions >= 0 && subdivisions <= 10,
          int_message("make_sphere", "subdivisions", "in [0, 10]", subdivisions));
  const double t = (1 + std::sqrt(5.0)) / 2;
  MeshBuilder b;
  const double ico[12][3] = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                             {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (const auto& p : ico) b.add_vertex(Vec3(p[0], p[1], p[2]).normalized());
  const int faces[20][3] = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                            {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                            {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (const auto& f : faces) b.add_triangle(f[0], f[1], f[2]);
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int i, int j) {
      const auto key = std::minmax(i, j);
      const auto [it, inserted] = midpoint.try_emplace(key, static_cast<int>(b.V.size()));
      if (inserted) b.add_vertex((b.V[i] + b.V[j]).normalized());
      return it->second;
    };
    std::vector<Eigen::Vector3i> coarse;
    coarse.swap(b.F);
    for (const Eigen::Vector3i& f : coarse) {
      const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
      b.add_triangle(f[0], ab, ca);
      b.add_triangle(f[1], bc, ab);
      b.add_triangle(f[2], ca, bc);
      b.add_triangle(ab, bc, ca);
    }
  }
  return b.to_mesh();
}

Mesh make_torus(int major_segments, int minor_segments) {
  require(major_segments >= 3, int_message("make_torus", "major_segments", ">= 3", major_segments));
  require(minor_segments >= 3, int_message("make_torus", "minor_segments", ">= 3", minor_segments));
  constexpr double R = 1.0, r = 0.4;
  MeshBuilder b;
  for (int j = 0; j < minor_segments; ++j)
    for (int i = 0; i < major_segments; ++i) {
      const double u = 2 * kPi * i / major_segments, v = 2 * kPi * j / minor_segments;
      b.add_vertex(Vec3((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)));
    }
  // ∂/∂u × ∂/∂v points outwards, so (u, v) quads are counter-clockwise seen from outside.
  auto at = [&](int i, int j) { return (j % minor_segments) * major_segments + i % major_segments; };
  for (int j = 0; j < minor_segments; ++j)
    for (int i = 0; i < major_segments; ++i) b.add_quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  return b.to_mesh();
}

Mesh make_pyramid(int n, std::uint64_t seed) {
  require(n >= 1, int_message("make_pyramid", "n", ">= 1", n));
  // Target edge length grows linearly from 0.4 h at x = -1 to h at x = 1.
  const double h = 2.0 / n;
  PatchMesher mesher([h](const Vec3& p) { return h * (0.4 + 0.3 * (std::clamp(p.x(), -1.0, 1.0) + 1)); },
                     InteriorSampling::PoissonDisk, seed, 0.3);
  std::array<int, 4> base;
  const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int i = 0; i < 4; ++i) base[i] = mesher.add_corner(Vec3(corner[i][0], corner[i][1], -0.6));
  const int apex = mesher.add_corner(Vec3(0, 0, 0.6));
  auto segment = [&](int a, int b) {
    const Vec3 pa = mesher.position(a), pb = mesher.position(b);
    return mesher.add_curve(a, b, [=](double t) -> Vec3 { return pa + t * (pb - pa); });
  };
  std::array<std::vector<int>, 4> base_edge, lateral;
  for (int i = 0; i < 4; ++i) base_edge[i] = segment(base[i], base[(i + 1) % 4]);
  for (int i = 0; i < 4; ++i) lateral[i] = segment(base[i], apex);
  std::vector<int> bottom;
  for (int i = 3; i >= 0; --i) append_curve(bottom, base_edge[i], true);
  mesher.add_planar_patch(bottom);
  for (int i = 0; i < 4; ++i) {
    std::vector<int> loop;
    append_curve(loop, base_edge[i]);
    append_curve(loop, lateral[(i + 1) % 4]);
    append_curve(loop, lateral[i], true);
    mesher.add_planar_patch(loop);
  }
  return mesher.to_mesh();
}

Mesh make_cube_with_holes(int n, int holes) {
  require(n >= 4, int_message("make_cube_with_holes", "n", ">= 4", n));
  require(holes >= 0 && holes <= kMaxHoles, int_message("make_cube_with_holes", "holes", "in [0, 26]", holes));
  const Mesh cube = make_cube(n);
  const std::vector<Vec3> centres = hole_centres(holes);
  const Eigen::MatrixXd B = face_barycenters(cube.V, cube.F);
  std::vector<bool> keep(static_cast<size_t>(cube.F.rows()), true);
  for (Eigen::Index f = 0; f < B.rows(); ++f)
    for (const Vec3& c : centres)
      if ((B.row(f).transpose() - c).norm() < kHoleRadius) keep[f] = false;

  // Clean up until every hole is bounded by one simple loop: keep the largest connected piece
  // (no islands inside a hole) and clear the fan of any vertex where two holes or two parts of
  // one hole touch (more than two boundary edges).
  for (bool changed = true; changed;) {
    changed = false;
    Eigen::MatrixXi F(std::count(keep.begin(), keep.end(), true), 3);
    std::vector<Eigen::Index> original;
    for (Eigen::Index f = 0; f < cube.F.rows(); ++f)
      if (keep[f]) {
        F.row(static_cast<Eigen::Index>(original.size())) = cube.F.row(f);
        original.push_back(f);
      }
    const Topology topo = build_topology(F, cube.V.rows());
    int components = 0;
    const Eigen::VectorXi label = face_components(topo, &components);
    if (components > 1) {
      std::vector<int> size(static_cast<size_t>(components), 0);
      for (Eigen::Index f = 0; f < label.size(); ++f) ++size[label(f)];
      const int largest = static_cast<int>(std::max_element(size.begin(), size.end()) - size.begin());
      for (Eigen::Index f = 0; f < label.size(); ++f)
        if (label(f) != largest) keep[original[f]] = false;
      changed = true;
      continue;
    }
    std::vector<int> boundary_edges(static_cast<size_t>(cube.V.rows()), 0);
    for (Eigen::Index e = 0; e < topo.num_edges(); ++e)
      if (topo.edge_face_count(e) == 1) {
        ++boundary_edges[topo.edges(e, 0)];
        ++boundary_edges[topo.edges(e, 1)];
      }
    for (Eigen::Index f = 0; f < F.rows(); ++f)
      for (int k = 0; k < 3; ++k)
        if (boundary_edges[F(f, k)] > 2) {
          keep[original[f]] = false;
          changed = true;
        }
  }
  Mesh out = submesh(cube, keep);
  // Only at n = 4 do neighbouring holes (1 apart) come close enough to merge.
  const TopologySummary s = summarize_topology(out.F, build_topology(out.F, out.V.rows()));
  if (static_cast<int>(s.boundary_loops.size()) != holes) {
    std::ostringstream os;
    os << "make_cube_with_holes: " << holes << " holes merge into " << s.boundary_loops.size() << " at n = " << n
       << "; use a larger n";
    throw InvalidInput(os.str());
  }
  return out;
}

std::vector<std::string> shape_names() {
  return {"cube", "cylinder", "sphere", "torus", "fandisk", "pyramid", "holes"};
}

namespace {
[[noreturn]] void unknown_shape(const std::string& name) {
  std::string list;
  for (const std::string& s : shape_names()) list += (list.empty() ? "" : ", ") + s;
  throw InvalidInput("unknown shape '" + name + "'; valid names: " + list);
}
}  // namespace

Mesh make_shape(const std::string& name, int resolution) {
  require(resolution >= 1, int_message("make_shape", "resolution", ">= 1", resolution));
  const int r = resolution;
  if (name == "cube") return make_cube(r);
  // Edges of about 2/r, as on the cube: π r around, r along the height 2.
  if (name == "cylinder") return make_cylinder(std::max(3, static_cast<int>(std::lround(kPi * r))), r);
  // About as many faces as the cube: 20·4^s ≈ 12 r².
  if (name == "sphere")
    return make_sphere(std::clamp(static_cast<int>(std::lround(std::log(0.6 * r * r) / std::log(4.0))), 0, 10));
  // Tube steps of 360°/3r (15° at r = 8) keep the torus one smooth patch; 5:3 keeps its
  // outer quads from stretching.
  if (name == "torus") return make_torus(5 * r, 3 * r);
  if (name == "fandisk") return make_fandisk_like(r);
  if (name == "pyramid") return make_pyramid(r, 1);
  if (name == "holes") return make_cube_with_holes(std::max(4, r), 2);
  unknown_shape(name);
}

int shape_patch_count(const std::string& name) {
  if (name == "cube" || name == "holes") return 6;
  if (name == "cylinder") return 3;
  if (name == "sphere" || name == "torus") return 1;
  if (name == "pyramid") return 5;
  if (name == "fandisk") return fandisk_like_patch_count();
  unknown_shape(name);
}

}  // namespace msmesh
