// Writing meshes (library msmesh_io). The format follows the extension (msmesh/mesh_format.h);
// `.gz` files are compressed with gzip; every file is written atomically (msmesh/atomic_file.h).
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "msmesh/mesh.h"

namespace msmesh {

struct WriteOptions {
  bool binary = true;  ///< PLY and STL: binary (true) or ascii; OBJ, OFF and .gltf are text, .glb binary
};

/// Writes a mesh; the format follows the extension (`m.ply.gz`: PLY, gzip-compressed).
/// Coordinates keep full double precision (shortest round-trip decimal; PLY stores doubles)
/// unless mesh.position_type is Float32 (the file they came from stored floats: they are
/// written as floats again), and in binary STL and glTF, which are float32. Each format gets
/// the attributes it can hold (docs/robustness.md, "Attributes"):
///  - OBJ: vertex colours ("v x y z r g b"), uv and per-corner texture coordinates (vt), normals
///    (vn), `mtllib` (the path rewritten relative to the output's folder; the .mtl file itself
///    is referenced, not copied), `usemtl`, `g` and `o`;
///  - PLY: vertex colours and alpha, uv, normals, extra vertex properties (with their types),
///    face colours (and alpha), per-corner texture coordinates (face `texcoord` lists);
///  - OFF: vertex colours (COFF); STL: geometry only;
///  - glTF/GLB: normals, colours (COLOR_0), uv (TEXCOORD_0; vertices are split where texture
///    coordinates have seams), and the source document's scene and materials (Mesh::gltf_document).
/// What the format cannot hold is left out: unsupported_attributes() names it. The file is
/// written to a temporary file in the same folder and renamed into place, so it appears
/// completely or not at all. Throws InvalidInput (nothing written) for out-of-range indices,
/// non-finite coordinates or attributes of the wrong shape, IoError for an unknown extension or
/// a file-system failure.
void write_mesh(const std::string& path, const Mesh& mesh, const WriteOptions& options = {});

/// What writing `mesh` to `path` (its format from the extension) leaves out, one sentence per
/// attribute, e.g. "STL has no vertex colours"; empty when the format keeps every attribute
/// the mesh has. The commands print these as notes.
std::vector<std::string> unsupported_attributes(const Mesh& mesh, const std::string& path);

/// Writes a PLY (binary unless !binary) with one RGB or RGBA colour (components in [0,1]) per face.
void write_ply_face_colors(const std::string& path, const Mesh& mesh, const Eigen::MatrixXd& face_colors,
                           bool binary = true);

}  // namespace msmesh
