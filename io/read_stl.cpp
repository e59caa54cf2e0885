// STL reader: binary files by our own loop (read_stl_binary.h), ascii ones by CGAL's read_STL
// behind guards. Both weld the triangle soup into shared vertices the same way: a vertex is
// numbered on its first appearance, equal coordinates (compared as numbers, so -0 = 0) are one
// vertex. CGAL does it through std::map<Point, int>, which NaN breaks (non-finite coordinates
// are refused first), at about 10 MB/s; the binary reader uses hash tables instead. CGAL
// parses a binary file whose header starts with "solid" as ascii first, and retries a failed
// ascii parse as binary, which "succeeds" on files shorter than 84 bytes.
#include <CGAL/IO/STL.h>

#include <algorithm>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "msmesh/errors.h"
#include "read_common.h"
#include "read_stl_binary.h"

namespace msmesh::io_detail {

void read_stl(const std::string& path, std::string_view data, Soup& soup) {
  // A byte-order mark before "solid" (ascii files only: a binary header may start with anything).
  const bool binary_size = data.size() >= 84 && [&] {
    std::uint32_t n;
    std::memcpy(&n, data.data() + 80, 4);
    return data.size() == 84 + 50 * static_cast<std::uint64_t>(n);
  }();
  if (!binary_size && without_utf8_bom(data).substr(0, 5) == "solid") data = without_utf8_bom(data);
  std::size_t first = 0;
  while (first < data.size() && std::isspace(static_cast<unsigned char>(data[first]))) ++first;
  const bool says_solid = data.substr(first, 5) == "solid";
  bool binary = false;
  std::uint32_t triangles = 0;
  if (data.size() >= 84) {
    std::memcpy(&triangles, data.data() + 80, 4);  // little-endian on the hosts we build for
    binary = data.size() == 84 + 50 * static_cast<std::uint64_t>(triangles);
  }
  if (!binary && !says_solid) {
    if (data.size() < 84)
      throw IoError(path + ": not an STL file: no 'solid' keyword and too short (" + std::to_string(data.size()) +
                    " bytes) for a binary STL");
    throw IoError(path + ": truncated or corrupt binary STL: the header declares " + std::to_string(triangles) +
                  " triangles (" + std::to_string(84 + 50 * static_cast<std::uint64_t>(triangles)) +
                  " bytes), the file has " + std::to_string(data.size()) + " bytes");
  }
  if (binary) {
    // (Many exporters start binary headers with "solid": the size decides, as above.)
    read_binary_stl(path, data, triangles, soup);
    return;
  }
  if (!binary && data.find("endsolid") == std::string_view::npos)
    throw IoError(path + ": truncated ascii STL (no 'endsolid')");
  MemoryStream in(data);
  bool ok = CGAL::IO::read_STL(in, soup.points, soup.polygons, CGAL::parameters::verbose(false));
  if (ok && !binary) {
    // When its ascii parse fails CGAL retries as binary, which "succeeds" on files shorter
    // than a binary header; the facet count tells.
    std::size_t facets = 0;
    for (std::size_t at = data.find("endfacet"); at != std::string_view::npos; at = data.find("endfacet", at + 8))
      ++facets;
    ok = facets == soup.polygons.size();
  }
  if (!ok) throw IoError(path + ": malformed or truncated ascii STL (CGAL's reader failed)");
}

}  // namespace msmesh::io_detail
