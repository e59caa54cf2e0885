// write_mesh: the checks before writing and the writer of the path's format (write_obj.cpp,
// write_off.cpp, write_ply.cpp, write_stl.cpp), through write_file_atomically.
#include "msmesh/write_mesh.h"

#include <Eigen/Core>
#include <cmath>
#include <ostream>
#include <string>

#include "msmesh/atomic_file.h"
#include "msmesh/errors.h"
#include "msmesh/mesh_format.h"
#include "write_common.h"

namespace msmesh {
namespace io_detail {

void check_for_writing(const std::string& path, const Mesh& mesh) {
  const Eigen::MatrixXd& V = mesh.V;
  const Eigen::MatrixXi& F = mesh.F;
  auto fail = [&path](const std::string& what) { throw InvalidInput(path + ": cannot write mesh: " + what); };
  if (V.cols() != 3)
    fail("vertex array must be #V by 3, got " + std::to_string(V.rows()) + " by " + std::to_string(V.cols()));
  if (F.rows() > 0 && F.cols() != 3)
    fail("face array must be #F by 3, got " + std::to_string(F.rows()) + " by " + std::to_string(F.cols()));
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(V(i, c))) fail("vertex " + std::to_string(i) + " has a non-finite coordinate");
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (F(f, k) < 0 || F(f, k) >= V.rows())
        fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(F(f, k)) + ", out of range [0, " +
             std::to_string(V.rows()) + ")");
  if (mesh.vertex_colors.size() > 0 && (mesh.vertex_colors.rows() != V.rows() || mesh.vertex_colors.cols() != 3))
    fail("vertex_colors must be empty or #V by 3");
  if (mesh.uv.size() > 0 && (mesh.uv.rows() != V.rows() || mesh.uv.cols() != 2)) fail("uv must be empty or #V by 2");
  if (mesh.vertex_normals.size() > 0 && (mesh.vertex_normals.rows() != V.rows() || mesh.vertex_normals.cols() != 3))
    fail("vertex_normals must be empty or #V by 3");
}

}  // namespace io_detail

using namespace io_detail;  // the writers' shared pieces (write_common.h)

void write_mesh(const std::string& path, const Mesh& mesh, const WriteOptions& options) {
  const std::string format = mesh_format_from_path(path);
  check_for_writing(path, mesh);
  write_file_atomically(path, [&](std::ostream& out) {
    OutBuffer o(out);
    if (format == "obj")
      write_obj(o, mesh);
    else if (format == "off")
      write_off(o, mesh);
    else if (format == "ply")
      write_ply(o, mesh, options.binary, nullptr);
    else
      write_stl(o, mesh, options.binary, path);
    o.finish();
  });
}

}  // namespace msmesh
