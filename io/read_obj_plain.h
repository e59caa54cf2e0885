// Internal: the OBJ files most exporters (and msmesh itself) write, read on every core.
#pragma once
#include <string_view>

#include "read_common.h"

namespace msmesh::io_detail {

/// Reads an OBJ file made only of vertex records "v x y z", triangles "f i j k" with positive
/// plain indices (no '/'), comments and blank lines straight into soup.mesh (soup.direct), in
/// parallel chunks of whole lines, with the same number parser as read_obj's line-by-line
/// reading, so that the mesh is the one that reading gives, bit for bit. Returns false, `soup`
/// unchanged, at anything else — another record, a vertex with more values (colours), a polygon,
/// a corner with '/', a word that is not a plain number, a non-finite coordinate, coordinates
/// spanning more than validate_mesh allows, an index out of range, a triangle repeating a
/// vertex, no vertices or no faces: then read_obj reads the file, with its notes and messages.
/// `data` without a byte-order mark.
bool read_plain_obj(std::string_view data, Soup& soup);

}  // namespace msmesh::io_detail
