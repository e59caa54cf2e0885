// Reading meshes (library msmesh_io). The format follows the extension (msmesh/mesh_format.h).
// Readers are CGAL's, behind checks of their own; polygons are triangulated on read, STL
// triangle soups are welded into shared vertices. Every failure throws msmesh::IoError naming
// the file.
#pragma once
#include <Eigen/Core>
#include <string>
#include <string_view>

#include "msmesh/mesh.h"

namespace msmesh {

/// Reads a mesh. Throws IoError when the file is missing, of unknown format, truncated or
/// malformed, has no vertices or no faces, non-finite coordinates or out-of-range indices.
/// Polygons are fan-triangulated; triangles that repeat a vertex (also after STL welding)
/// are dropped (`dropped_degenerate` counts them, when given). PLY and OFF vertex colours
/// (uchar RGB) fill Mesh::vertex_colors.
Mesh read_mesh(const std::string& path, Eigen::Index* dropped_degenerate = nullptr);

/// Reads a mesh from the bytes of a file already in memory, exactly as read_mesh reads a file
/// of format `format` ("obj", "off", "ply" or "stl", as from mesh_format_from_path); `name`
/// stands for the file in error messages. Same results and errors as read_mesh.
Mesh read_mesh_from_memory(std::string_view data, const std::string& format, const std::string& name,
                           Eigen::Index* dropped_degenerate = nullptr);

/// What read_mesh noticed besides the mesh itself.
struct ReadNotes {
  Eigen::Index dropped_degenerate = 0;  ///< triangles repeating a vertex, dropped
  bool had_normals = false;             ///< the file has vertex normals (per-vertex ones fill Mesh::vertex_normals;
                                        ///< per-corner ones, e.g. split at creases, are replaced by recomputed ones)
  bool uv_dropped = false;  ///< OBJ texture coordinates with seams (one vertex, several vt): not per-vertex, dropped
};

/// As above, and says what it noticed. OBJ "v x y z r g b" colours, "vt" texture coordinates
/// and "vn" normals (per-vertex when every corner of a vertex names the same one), and PLY
/// texture_u/texture_v (or u/v, s/t) and nx/ny/nz vertex properties fill the Mesh attributes.
Mesh read_mesh(const std::string& path, ReadNotes& notes);
Mesh read_mesh_from_memory(std::string_view data, const std::string& format, const std::string& name, ReadNotes& notes);

}  // namespace msmesh
