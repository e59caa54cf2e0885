// Writing meshes (library msmesh_io). The format follows the extension (msmesh/mesh_format.h);
// every file is written atomically (msmesh/atomic_file.h).
#pragma once
#include <Eigen/Core>
#include <string>

#include "msmesh/mesh.h"

namespace msmesh {

struct WriteOptions {
  bool binary = true;  ///< PLY and STL: binary (true) or ascii; OBJ and OFF are always text
};

/// Writes a mesh; the format follows the extension. Coordinates keep full double precision
/// (shortest round-trip decimal; PLY stores doubles) except in binary STL, which is float32.
/// Vertex colours go to OBJ ("v x y z r g b"), OFF (COFF) and PLY; uv and vertex normals to
/// OBJ (vt, vn) and PLY (texture_u/v, nx/ny/nz). The file is written to a
/// temporary file in the same folder and renamed into place, so it appears completely or not
/// at all. Throws InvalidInput (nothing written) for out-of-range indices or non-finite
/// coordinates, IoError for an unknown extension or a file-system failure.
void write_mesh(const std::string& path, const Mesh& mesh, const WriteOptions& options = {});

/// Writes a PLY (binary unless !binary) with one RGB colour (components in [0,1]) per face.
void write_ply_face_colors(const std::string& path, const Mesh& mesh, const Eigen::MatrixXd& face_colors,
                           bool binary = true);

}  // namespace msmesh
