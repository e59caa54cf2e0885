// Reading and writing meshes (library msmesh_io, on top of the core). Formats: OBJ, OFF,
// PLY (ascii and binary), STL (ascii and binary), chosen by the file extension
// (case-insensitive). Readers are CGAL's; polygons are triangulated on read, STL triangle
// soups are welded into shared vertices. Every failure throws msmesh::IoError naming the file.
#pragma once
#include <Eigen/Core>
#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "msmesh/mesh.h"

namespace msmesh {

/// Lower-case format name of a path ("obj", "off", "ply", "stl"); throws IoError for others.
std::string mesh_format_from_path(const std::string& path);

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
  bool had_normals = false;  ///< the file has vertex normals (per-vertex ones fill Mesh::vertex_normals;
                             ///< per-corner ones, e.g. split at creases, are replaced by recomputed ones)
  bool uv_dropped = false;   ///< OBJ texture coordinates with seams (one vertex, several vt): not per-vertex, dropped
};

/// As above, and says what it noticed. OBJ "v x y z r g b" colours, "vt" texture coordinates
/// and "vn" normals (per-vertex when every corner of a vertex names the same one), and PLY
/// texture_u/texture_v (or u/v, s/t) and nx/ny/nz vertex properties fill the Mesh attributes.
Mesh read_mesh(const std::string& path, ReadNotes& notes);
Mesh read_mesh_from_memory(std::string_view data, const std::string& format, const std::string& name,
                           ReadNotes& notes);

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

/// Writes polylines: OBJ (`v` and `l` records) or ascii PLY (vertices and `edge` elements),
/// by extension. Each polyline is a list of row indices into P (#P by 3).
void write_polylines(const std::string& path, const Eigen::MatrixXd& P, const std::vector<std::vector<int>>& lines);

/// Writes `text` to `path` atomically (temporary file, then rename).
void write_text_file(const std::string& path, const std::string& text);

/// Writes `path` atomically: `fill` writes the content to a stream on a new temporary file in
/// the same folder, which is flushed to disk and renamed over `path`. When anything fails
/// (including an exception thrown by `fill`, which is rethrown) the temporary file is removed
/// and `path` is left as it was. Throws IoError naming `path` for file-system failures.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill);

}  // namespace msmesh
