// Procedural test shapes, built in code (for tests, benchmarks and the demo).
// All are closed, consistently oriented (outward normals) triangle meshes unless stated.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "msmesh/mesh.h"

namespace msmesh {

/// Axis-aligned cube [-1,1]^3, each face split into n×n quads (2n² triangles per face).
Mesh make_cube(int n);

/// Cylinder of radius 1 and height 2 around z, `segments` around, `rings` along; with caps
/// (triangulated disks meeting the side at sharp 90° creases) unless !caps (then open).
Mesh make_cylinder(int segments, int rings, bool caps = true);

/// Unit sphere: icosahedron subdivided `subdivisions` times (20·4^s faces).
Mesh make_sphere(int subdivisions);

/// Torus with major radius 1, minor radius 0.4, `major_segments` × `minor_segments` quads.
Mesh make_torus(int major_segments, int minor_segments);

/// A "fandisk-like" CAD part with flat, cylindrical and sharp regions; `n` sets the
/// resolution (≈ n² faces per unit area). Its number of smooth patches is
/// fandisk_like_patch_count().
Mesh make_fandisk_like(int n);
int fandisk_like_patch_count();

/// A square pyramid (base and four sides: 5 flat patches) with irregular sampling:
/// vertices of each face jittered in-plane with the given seed.
Mesh make_pyramid(int n, std::uint64_t seed = 1);

/// A cube of resolution n with `holes` disks removed (open boundary loops), some across
/// creases; deterministic.
Mesh make_cube_with_holes(int n, int holes = 2);

/// Names accepted by make_shape, e.g. "cube", "cylinder", "sphere", "torus", "fandisk",
/// "pyramid", "holes".
std::vector<std::string> shape_names();

/// Builds a named shape at a resolution level (≥ 1; larger = finer, about
/// `resolution`² faces per face of a cube). Throws InvalidInput for an unknown name.
Mesh make_shape(const std::string& name, int resolution);

/// Number of smooth patches (segments a perfect segmentation finds) of a named shape.
int shape_patch_count(const std::string& name);

}  // namespace msmesh
