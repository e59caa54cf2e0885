// write_polylines: OBJ (v and l records) or ascii PLY (vertices and edge elements).
#include "msmesh/write_polylines.h"

#include <Eigen/Core>
#include <cmath>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "msmesh/atomic_file.h"
#include "msmesh/errors.h"
#include "msmesh/mesh_format.h"
#include "write_common.h"

namespace msmesh {

using io_detail::OutBuffer;

void write_polylines(const std::string& path, const Eigen::MatrixXd& P, const std::vector<std::vector<int>>& lines) {
  const std::string format = mesh_format_from_path(path);
  if (format != "obj" && format != "ply")
    throw IoError(path + ": polylines can be written to .obj or .ply only, not ." + format);
  if (P.rows() > 0 && P.cols() != 3)
    throw InvalidInput(path + ": polyline points must be #P by 3, got " + std::to_string(P.rows()) + " by " +
                       std::to_string(P.cols()));
  for (Eigen::Index i = 0; i < P.rows(); ++i)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(P(i, c)))
        throw InvalidInput(path + ": polyline point " + std::to_string(i) + " has a non-finite coordinate");
  std::size_t num_edges = 0;
  for (std::size_t l = 0; l < lines.size(); ++l) {
    for (int v : lines[l])
      if (v < 0 || v >= P.rows())
        throw InvalidInput(path + ": polyline " + std::to_string(l) + " refers to point " + std::to_string(v) +
                           ", out of range [0, " + std::to_string(P.rows()) + ")");
    if (lines[l].size() >= 2) num_edges += lines[l].size() - 1;
  }
  write_file_atomically(path, [&](std::ostream& out) {
    OutBuffer o(out);
    if (format == "obj") {
      o.text("# written by msmesh\n");
      for (Eigen::Index i = 0; i < P.rows(); ++i)
        o.text("v ").real(P(i, 0)).ch(' ').real(P(i, 1)).ch(' ').real(P(i, 2)).ch('\n');
      for (const auto& line : lines) {
        if (line.empty()) continue;
        o.ch('l');
        for (int v : line) o.ch(' ').integer(v + 1LL);
        o.ch('\n');
      }
    } else {
      o.text("ply\nformat ascii 1.0\ncomment polylines written by msmesh\nelement vertex ").integer(P.rows());
      o.text("\nproperty double x\nproperty double y\nproperty double z\nelement edge ")
          .integer(static_cast<long long>(num_edges))
          .text("\nproperty int vertex1\nproperty int vertex2\nend_header\n");
      for (Eigen::Index i = 0; i < P.rows(); ++i) o.real(P(i, 0)).ch(' ').real(P(i, 1)).ch(' ').real(P(i, 2)).ch('\n');
      for (const auto& line : lines)
        for (std::size_t k = 1; k < line.size(); ++k) o.integer(line[k - 1]).ch(' ').integer(line[k]).ch('\n');
    }
    o.finish();
  });
}

}  // namespace msmesh
