// Reading and writing meshes (library msmesh_io, on top of the core): everything the io
// library offers, one header per concept. Formats: OBJ, OFF, PLY (ascii and binary), STL
// (ascii and binary), chosen by the file extension (case-insensitive). Readers are CGAL's;
// polygons are triangulated on read, STL triangle soups are welded into shared vertices. Every
// failure throws msmesh::IoError naming the file.
#pragma once
#include "msmesh/atomic_file.h"      // write_file_atomically, write_text_file
#include "msmesh/mesh_format.h"      // mesh_format_from_path
#include "msmesh/read_mesh.h"        // read_mesh, read_mesh_from_memory, ReadNotes
#include "msmesh/write_mesh.h"       // write_mesh, WriteOptions, write_ply_face_colors
#include "msmesh/write_polylines.h"  // write_polylines
