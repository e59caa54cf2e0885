// Procedural test shapes, built in code (for tests, benchmarks and the demo).
//
// Every shape is a triangle mesh (V #V by 3, F #F by 3) that is closed, manifold, watertight
// (vertices along creases and seams exist once, never duplicated), consistently oriented with
// outward normals (counter-clockwise seen from outside, positive signed volume) and free of
// degenerate faces, unless stated otherwise. Sizes grow with the resolution parameter; all
// functions are deterministic. Invalid parameters throw msmesh::InvalidInput.
//
// "Smooth patches" are the regions separated by sharp creases (dihedral angle between face
// normals above about 20°); a tangent-continuous blend does not separate two regions.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "msmesh/mesh.h"

namespace msmesh {

/// Axis-aligned cube [-1,1]^3, each face split into n×n quads of 2 triangles.
///  - n ≥ 1. Returns 6n²+2 vertices (shared along the 12 edges) and 12n² faces; 6 patches.
Mesh make_cube(int n);

/// Cylinder of radius 1 around z, z ∈ [-1,1]: `segments` ≥ 3 vertices around, `rings` ≥ 1
/// quad rows along (2·segments·rings side faces). With caps, each cap is a flat disk of
/// concentric vertex rings (counts growing with the radius, so triangles stay near-equilateral)
/// that meets the side exactly at its rim vertices, with a 90° crease: 3 patches (2 flat,
/// 1 curved) once 360°/segments < 20°. Without caps it is an open tube with 2 boundary loops.
Mesh make_cylinder(int segments, int rings, bool caps = true);

/// Unit sphere: icosahedron subdivided `subdivisions` ∈ [0, 10] times, vertices projected
/// onto the sphere (20·4^s faces, 10·4^s + 2 vertices). One patch from s = 2 on.
Mesh make_sphere(int subdivisions);

/// Torus around z with major radius 1 and minor radius 0.4: `major_segments` ≥ 3 ×
/// `minor_segments` ≥ 3 quads of 2 triangles. One patch once 360°/minor_segments < 20°.
Mesh make_torus(int major_segments, int minor_segments);

/// A CAD-like part ("fandisk-like"): a profile of lines and one arc extruded along z, with a
/// flat back cap and a slanted flat front cap, centred, 2 long (x) × 0.7 (y) × 0.6–1.4 (z).
/// Its fandisk_like_patch_count() = 9 smooth patches: bottom, right wall, chamfer, a
/// cylindrical roof (radius 1.5) blending tangentially into a flat slope (one patch), a
/// concave step wall, tower top, left wall, back cap and front cap. Crease angles: 30°
/// (roof/chamfer), 45° (chamfer/wall), 90° (walls, back cap), 115° concave (slope/step) and
/// 68°–112° along the slanted front cap.
///  - n ≥ 1: target edge length 1.25/n, i.e. ≈ 1.5 n² faces per unit area (6.7k faces at
///    n = 24). Patches are triangulated (constrained Delaunay on a triangular lattice) so that
///    triangles are near-equilateral; smooth patches keep dihedral angles below 20° for n ≥ 4.
Mesh make_fandisk_like(int n);
/// Number of smooth patches of make_fandisk_like (9).
int fandisk_like_patch_count();

/// A square pyramid (base [-1,1]² at z = -0.6, apex (0,0,0.6); base and four sides: 5 flat
/// patches) with irregular sampling for robustness tests: vertices along the 8 edges are
/// jittered along them, interior vertices are Poisson-disk samples in their face's plane, and
/// the density is graded (target edge 0.8/n at x = -1 up to 2/n at x = 1).
///  - n ≥ 1; the same (n, seed) gives the same mesh on any machine, other seeds differ.
Mesh make_pyramid(int n, std::uint64_t seed = 1);

/// The cube make_cube(n) with `holes` disks removed (faces whose barycentre lies within 0.3 of
/// a centre), each bounded by one simple boundary loop, unreferenced vertices removed.
/// Centres: the midpoint of the edge x = z = 1 (the hole crosses the crease), the centre of
/// face x = -1, then further edge midpoints, face centres and corners, each farthest from
/// those already chosen. Euler characteristic 2 - holes; 6 patches.
///  - n ≥ 4, holes ∈ [0, 26]. At n = 4 more than 4 holes would merge (InvalidInput).
Mesh make_cube_with_holes(int n, int holes = 2);

/// Names accepted by make_shape: "cube", "cylinder", "sphere", "torus", "fandisk",
/// "pyramid", "holes".
std::vector<std::string> shape_names();

/// Builds a named shape at a resolution level r ≥ 1 (larger = finer; edges of about 2/r on
/// shapes 2 across, like make_cube(r)):
///  - cube: make_cube(r); cylinder: make_cylinder(round(π r), r);
///  - sphere: make_sphere(round(log4(0.6 r²))), about 12 r² faces;
///  - torus: make_torus(5r, 3r); fandisk: make_fandisk_like(r); pyramid: make_pyramid(r, 1);
///  - holes: make_cube_with_holes(max(r, 4), 2).
/// From r = 8 on, every shape has exactly shape_patch_count(name) crease-separated patches.
/// Throws InvalidInput for r < 1 or an unknown name (the message lists the valid names).
Mesh make_shape(const std::string& name, int resolution);

/// Number of smooth patches (segments a perfect segmentation finds) of a named shape:
/// cube 6, cylinder 3, sphere 1, torus 1, fandisk fandisk_like_patch_count(), pyramid 5,
/// holes 6. Throws InvalidInput for an unknown name.
int shape_patch_count(const std::string& name);

}  // namespace msmesh
