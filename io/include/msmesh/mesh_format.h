// The mesh formats msmesh reads and writes (library msmesh_io): OBJ, OFF, PLY (ascii and
// binary), STL (ascii and binary), chosen by the file extension (case-insensitive).
#pragma once
#include <string>

namespace msmesh {

/// Lower-case format name of a path ("obj", "off", "ply", "stl"); throws IoError for others.
std::string mesh_format_from_path(const std::string& path);

}  // namespace msmesh
