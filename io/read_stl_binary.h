// Internal: binary STL files read straight into the mesh, the points welded on every core.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>

namespace msmesh::io_detail {

struct Soup;  // read_common.h

/// A binary STL of `triangles` triangles (the size already checked, little-endian floats), read
/// straight into the mesh (soup.mesh, soup.direct), the points welded as CGAL's
/// parse_binary_STL welds them: numbered on first appearance, equal when their coordinates
/// compare equal (-0 = +0, the first appearance's bits kept). Triangles repeating a vertex after
/// welding are left out and counted, as soup_to_mesh does. A non-finite coordinate is refused
/// (CGAL merges through std::map<Point, int>, which NaN breaks), naming the first triangle that
/// has one.
///
/// From kStlRangeTriangles triangles per thread up, the file is cut into ranges of whole
/// triangles, one per thread, each welded on its own; then the ranges are joined in order, a
/// range's points looked up among those of the ranges before it: the same numbers as one
/// welder over the whole file (test ReadBinaryStl.WeldsAsAnIndependentWelderAtEveryThreadCount).
void read_binary_stl(const std::string& path, std::string_view data, std::uint32_t triangles, Soup& soup);

/// Fewest triangles a thread welds on its own (below that, one welder; a range's own table and
/// the join cost more than they save).
inline constexpr std::uint32_t kStlRangeTriangles = 32768;

}  // namespace msmesh::io_detail
