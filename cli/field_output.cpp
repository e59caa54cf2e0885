#include "field_output.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "msmesh/errors.h"
#include "msmesh/io.h"

namespace msmesh::cli {

Eigen::Vector3d field_color(double x) {
  x = std::clamp(x, 0.0, 1.0);
  const Eigen::Vector3d a(0.45, 0.0, 0.05), b(1.0, 0.8, 0.1), c(0.85, 0.85, 0.85);
  return x < 0.5 ? Eigen::Vector3d(a + (b - a) * (x / 0.5)) : Eigen::Vector3d(b + (c - b) * ((x - 0.5) / 0.5));
}

void write_edge_field(const std::string& path, const Eigen::MatrixXd& V, const Topology& topo, const Eigen::VectorXd& v) {
  std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  std::ostringstream os;
  char buf[128];
  if (ext == ".ply") {
    os << "ply\nformat ascii 1.0\ncomment msmesh edge discontinuity field v (0 = feature, 1 = smooth)\n"
       << "element vertex " << V.rows() << "\nproperty double x\nproperty double y\nproperty double z\n"
       << "element edge " << topo.num_edges()
       << "\nproperty int vertex1\nproperty int vertex2\nproperty double value\n"
       << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
    for (Eigen::Index i = 0; i < V.rows(); ++i) {
      std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", V(i, 0), V(i, 1), V(i, 2));
      os << buf;
    }
    for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
      const Eigen::Vector3d c = field_color(v(e)) * 255.0;
      std::snprintf(buf, sizeof buf, "%d %d %.9g %d %d %d\n", topo.edges(e, 0), topo.edges(e, 1), v(e),
                    int(c(0) + 0.5), int(c(1) + 0.5), int(c(2) + 0.5));
      os << buf;
    }
  } else {
    os << "# msmesh edge field: vertex_i vertex_j v (0 = feature, 1 = smooth), one line per edge\n";
    for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
      std::snprintf(buf, sizeof buf, "%d %d %.9g\n", topo.edges(e, 0), topo.edges(e, 1), v(e));
      os << buf;
    }
  }
  write_text_file(path, os.str());
}

}  // namespace msmesh::cli
