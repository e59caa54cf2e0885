// Internal: the ascii OFF files most exporters write, read on every core.
#pragma once
#include <string_view>

#include "read_common.h"

namespace msmesh::io_detail {

/// Reads the body of an ascii "OFF" file (no colours, normals or homogeneous coordinates) whose
/// records are only `x y z` lines and `3 i j k` triangles, one per line, with blank lines but no
/// comments, `vertices` and `faces` of them and nothing after, straight into soup.mesh
/// (soup.direct), in parallel chunks of whole lines. The numbers are read as CGAL's reader
/// reads them (`istream >> double`, correctly rounded like fast_float for these plain
/// decimal words), so the mesh is the one the general reader gives, bit for bit. Returns false,
/// `soup` unchanged, for anything else (then read_off reads the file with CGAL, with its
/// checks and messages). `body`: the file after the header's three counts.
bool read_plain_off(std::string_view body, long long vertices, long long faces, Soup& soup);

}  // namespace msmesh::io_detail
