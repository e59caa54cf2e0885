#include "field_files.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "msmesh/color_map.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"

namespace msmesh::cli {

namespace {
inline std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}
}  // namespace

void write_edge_field(const std::string& path, const Eigen::MatrixXd& V, const Eigen::MatrixXi& edges,
                      const Eigen::VectorXd& v) {
  std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  std::ostringstream os;
  char buf[128];
  if (ext == ".ply") {
    os << "ply\nformat ascii 1.0\ncomment msmesh edge discontinuity field v (0 = feature, 1 = smooth)\n"
       << "element vertex " << V.rows() << "\nproperty double x\nproperty double y\nproperty double z\n"
       << "element edge " << edges.rows() << "\nproperty int vertex1\nproperty int vertex2\nproperty double value\n"
       << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
    for (Eigen::Index i = 0; i < V.rows(); ++i) {
      std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", V(i, 0), V(i, 1), V(i, 2));
      os << buf;
    }
    for (Eigen::Index e = 0; e < edges.rows(); ++e) {
      const Eigen::Vector3d c = field_color(v(e)) * 255.0;
      std::snprintf(buf, sizeof buf, "%d %d %.9g %d %d %d\n", edges(e, 0), edges(e, 1), v(e), int(c(0) + 0.5),
                    int(c(1) + 0.5), int(c(2) + 0.5));
      os << buf;
    }
  } else {
    os << "# msmesh edge field: vertex_i vertex_j v (0 = feature, 1 = smooth), one line per edge\n";
    for (Eigen::Index e = 0; e < edges.rows(); ++e) {
      std::snprintf(buf, sizeof buf, "%d %d %.9g\n", edges(e, 0), edges(e, 1), v(e));
      os << buf;
    }
  }
  write_text_file(path, os.str());
}

Eigen::VectorXd read_edge_field(const std::string& path, const Topology& topo) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot open the edge field file '" + path + "'");
  std::unordered_map<std::uint64_t, Eigen::Index> index;
  index.reserve(static_cast<size_t>(topo.num_edges()) * 2);
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) index[edge_key(topo.edges(e, 0), topo.edges(e, 1))] = e;
  Eigen::VectorXd v = Eigen::VectorXd::Constant(topo.num_edges(), std::numeric_limits<double>::quiet_NaN());
  std::string line;
  long line_no = 0;
  // PLY (as written by --save-field x.ply): skip the header and the vertex lines.
  long skip = 0, edges_left = -1;
  if (in.peek() == 'p') {
    long vertices = 0;
    bool ended = false;
    while (std::getline(in, line)) {
      ++line_no;
      std::istringstream ls(line);
      std::string a, b;
      long n = 0;
      ls >> a;
      if (a == "format" && ls >> b && b != "ascii")
        throw IoError("'" + path + "': only ascii PLY edge fields are read (msmesh denoise --save-field writes them)");
      if (a == "element" && ls >> b >> n) {
        if (b == "vertex")
          vertices = n;
        else if (b == "edge")
          edges_left = n;
      }
      if (a == "end_header") {
        ended = true;
        break;
      }
    }
    if (!ended || edges_left < 0) throw IoError("'" + path + "' is not a PLY file with an edge element");
    skip = vertices;
  }
  Eigen::Index seen = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (skip > 0) {
      --skip;
      continue;
    }
    if (edges_left == 0) break;
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream ls(line);
    long long i = 0, j = 0;
    double value = 0;
    if (!(ls >> i)) continue;  // blank or comment line
    if (!(ls >> j >> value) || !std::isfinite(value))
      throw IoError("'" + path + "' line " + std::to_string(line_no) + ": expected 'i j v' with a finite v");
    if (edges_left > 0) --edges_left;
    const auto it =
        (i < 0 || j < 0 || i > INT32_MAX || j > INT32_MAX) ? index.end() : index.find(edge_key(int(i), int(j)));
    if (it == index.end())
      throw InvalidInput("'" + path + "' line " + std::to_string(line_no) + ": (" + std::to_string(i) + ", " +
                         std::to_string(j) + ") is not an edge of the mesh (was the field written for another mesh?)");
    if (std::isnan(v(it->second))) ++seen;
    v(it->second) = value;
  }
  if (seen != topo.num_edges())
    throw InvalidInput("'" + path + "' gives the field on " + std::to_string(seen) + " of the mesh's " +
                       std::to_string(topo.num_edges()) + " edges (was it written for another mesh?)");
  return v;
}

Eigen::VectorXi read_face_labels(const std::string& path, Eigen::Index faces) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot open the labels file '" + path + "'");
  std::vector<int> labels;
  std::string line;
  long line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream ls(line);
    long long x = 0;
    while (ls >> x) {
      if (x < 0 || x > INT32_MAX)
        throw IoError("'" + path + "' line " + std::to_string(line_no) + ": label " + std::to_string(x) +
                      " is not in [0, 2^31)");
      labels.push_back(static_cast<int>(x));
    }
    if (!ls.eof()) throw IoError("'" + path + "' line " + std::to_string(line_no) + ": not an integer label");
  }
  if (static_cast<Eigen::Index>(labels.size()) != faces)
    throw IoError("'" + path + "' has " + std::to_string(labels.size()) + " labels; the mesh has " +
                  std::to_string(faces) + " faces");
  return Eigen::Map<Eigen::VectorXi>(labels.data(), static_cast<Eigen::Index>(labels.size()));
}

}  // namespace msmesh::cli
