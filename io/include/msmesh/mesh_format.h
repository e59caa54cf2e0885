// The mesh formats msmesh reads and writes (library msmesh_io): OBJ, OFF, PLY (ascii and
// binary), STL (ascii and binary), glTF 2.0 (.gltf, .glb), chosen by the file extension
// (case-insensitive); each also gzip-compressed (`.obj.gz`, `.ply.gz`, ...).
#pragma once
#include <string>

namespace msmesh {

/// Lower-case format name of a path ("obj", "off", "ply", "stl", "gltf", "glb"; for "m.ply.gz"
/// the format under the .gz, "ply"); throws IoError for others.
std::string mesh_format_from_path(const std::string& path);

/// True when the path ends in ".gz" (case-insensitive): the file is gzip-compressed.
bool is_gzip_path(const std::string& path);

}  // namespace msmesh
