// Reading and writing meshes (library msmesh_io, on top of the core): everything the io
// library offers, one header per concept. Formats: OBJ, OFF, PLY (ascii and binary), STL
// (ascii and binary), glTF 2.0 (.gltf, .glb), each optionally gzip-compressed (.obj.gz, ...),
// chosen by the file extension (case-insensitive), with the attributes of msmesh/mesh.h;
// polygons are triangulated on read, STL triangle soups are welded into shared vertices. Every
// failure throws msmesh::IoError naming the file.
#pragma once
#include "msmesh/atomic_file.h"      // write_file_atomically, write_text_file
#include "msmesh/mesh_format.h"      // mesh_format_from_path, is_gzip_path
#include "msmesh/read_mesh.h"        // read_mesh, read_mesh_from_memory, ReadNotes
#include "msmesh/write_mesh.h"       // write_mesh, WriteOptions, unsupported_attributes, write_ply_face_colors
#include "msmesh/write_polylines.h"  // write_polylines
