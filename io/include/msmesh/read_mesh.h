// Reading meshes (library msmesh_io). The format follows the extension (msmesh/mesh_format.h);
// `.gz` files are inflated first. OBJ, PLY and glTF are read by our own code (glTF through
// tinygltf), OFF and STL by CGAL's readers behind checks of their own; polygons are triangulated
// on read, STL triangle soups are welded into shared vertices. Every failure throws
// msmesh::IoError naming the file. What each format's attributes become: docs/robustness.md
// ("Attributes").
#pragma once
#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

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
  /// No longer set: texture coordinates with seams are kept per corner (Mesh::texcoords,
  /// Mesh::face_texcoords; uv_seams says so). Kept for source compatibility.
  bool uv_dropped = false;
  bool uv_seams = false;  ///< texture coordinates with seams (one vertex, several uv), kept per corner
  /// What the file had that the mesh does not keep, one sentence each (e.g. "OBJ smoothing
  /// groups ('s') are not kept"); empty when nothing was lost.
  std::vector<std::string> dropped;
};

/// As above, and says what it noticed. The Mesh attributes (mesh.h) are filled from:
///  - OBJ: "v x y z r g b" colours, "vt" (per-vertex uv, or per corner when there are seams),
///    "vn" normals (per-vertex when every corner of a vertex names the same one), `mtllib`,
///    `usemtl`, `g` and `o`;
///  - PLY: vertex red/green/blue[/alpha], texture_u/texture_v (or u/v, s/t), nx/ny/nz, every
///    other scalar vertex property (vertex_properties, with its type), face red/green/blue[/alpha];
///    float coordinates set position_type;
///  - OFF: vertex colours; glTF: POSITION, NORMAL, COLOR_0, TEXCOORD_0 of every triangle
///    primitive, the material names, and the whole document (gltf_document).
/// `format` may end in ".gz" (e.g. "ply.gz"): the data is inflated first.
Mesh read_mesh(const std::string& path, ReadNotes& notes);
Mesh read_mesh_from_memory(std::string_view data, const std::string& format, const std::string& name, ReadNotes& notes);

}  // namespace msmesh
