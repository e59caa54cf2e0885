// Writing polylines (library msmesh_io), e.g. feature lines: OBJ or ascii PLY by extension,
// written atomically (msmesh/atomic_file.h).
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

namespace msmesh {

/// Writes polylines: OBJ (`v` and `l` records) or ascii PLY (vertices and `edge` elements),
/// by extension. Each polyline is a list of row indices into P (#P by 3).
void write_polylines(const std::string& path, const Eigen::MatrixXd& P, const std::vector<std::vector<int>>& lines);

}  // namespace msmesh
