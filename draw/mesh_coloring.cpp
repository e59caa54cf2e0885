// Figure colourings (mesh_coloring.h).
#include "msmesh/mesh_coloring.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "msmesh/color_map.h"
#include "msmesh/errors.h"
#include "msmesh/segment.h"
#include "msmesh/text.h"
#include "msmesh/topology.h"

namespace msmesh {

double error_scale(const Eigen::VectorXd& values) {
  std::vector<double> x;
  for (Eigen::Index i = 0; i < values.size(); ++i)
    if (std::isfinite(values(i))) x.push_back(values(i));
  if (x.empty()) return 1;
  const size_t k = std::min(x.size() - 1, static_cast<size_t>(std::floor(0.98 * double(x.size()))));
  std::nth_element(x.begin(), x.begin() + static_cast<long>(k), x.end());
  const double p = std::max(x[k], 1e-3);
  const double decade = std::pow(10.0, std::floor(std::log10(p)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= p * (1 - 1e-12)) return m * decade;
  return 10 * decade;
}

Coloring error_coloring(const Eigen::VectorXd& angle_deg, double max_deg) {
  Coloring c;
  const double top = max_deg > 0 ? max_deg : error_scale(angle_deg);
  c.style.face_colors.resize(angle_deg.size(), 3);
  for (Eigen::Index f = 0; f < angle_deg.size(); ++f)
    c.style.face_colors.row(f) = heat_color(angle_deg(f) / top).transpose();
  c.has_bar = true;
  c.bar.map = heat_color;
  c.bar.min = 0;
  c.bar.max = top;
  c.bar.ticks = 5;
  c.bar.title = "angle error (deg)";
  c.bar.max_is_clamped = angle_deg.size() > 0 && angle_deg.maxCoeff() > top;
  c.summary = "angle error, colour scale 0-" + format_tick(top) + " deg (max " +
              format_tick(angle_deg.size() ? angle_deg.maxCoeff() : 0.0) + ")";
  return c;
}

Coloring field_coloring(const Eigen::MatrixXi& F, Eigen::Index num_vertices, const Eigen::VectorXd& v) {
  const Topology topo = build_topology(F, num_vertices);
  if (v.size() != topo.num_edges())
    throw InvalidInput("edge field has " + std::to_string(v.size()) + " values; the mesh has " +
                       std::to_string(topo.num_edges()) + " edges");
  const Eigen::VectorXd vn = normalize_edge_field(v);
  // Smooth edges (normalised v near 1) would be drawn nearly in the face colour: leave them out.
  constexpr double kDrawBelow = 0.9;
  std::vector<Eigen::Index> drawn;
  for (Eigen::Index e = 0; e < vn.size(); ++e)
    if (vn(e) < kDrawBelow) drawn.push_back(e);
  Coloring c;
  c.style.lines.resize(static_cast<Eigen::Index>(drawn.size()), 2);
  c.style.line_colors.resize(static_cast<Eigen::Index>(drawn.size()), 3);
  for (size_t k = 0; k < drawn.size(); ++k) {
    c.style.lines.row(k) = topo.edges.row(drawn[k]);
    c.style.line_colors.row(k) = field_color(vn(drawn[k])).transpose();
  }
  c.has_bar = true;
  c.bar.map = field_color;
  c.bar.min = v.size() ? v.minCoeff() : 0.0;
  c.bar.max = v.size() ? v.maxCoeff() : 1.0;
  c.bar.ticks = 3;
  c.bar.title = "edge field v";
  c.summary = "edge field v in [" + format_tick(c.bar.min) + ", " + format_tick(c.bar.max) + "], " +
              std::to_string(drawn.size()) + " edges drawn (normalised v < 0.9)";
  return c;
}

Coloring label_coloring(const Eigen::MatrixXi& F, Eigen::Index num_vertices, const Eigen::VectorXi& labels) {
  if (labels.size() != F.rows())
    throw InvalidInput("got " + std::to_string(labels.size()) + " labels for " + std::to_string(F.rows()) + " faces");
  const Topology topo = build_topology(F, num_vertices);
  Coloring c;
  c.style.face_colors.resize(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f) c.style.face_colors.row(f) = label_color(labels(f)).transpose();
  std::vector<Eigen::Index> cut;
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e)
    if (topo.edge_face_count(e) >= 2 && labels(topo.edge_faces(e, 0)) != labels(topo.edge_faces(e, 1)))
      cut.push_back(e);
  c.style.lines.resize(static_cast<Eigen::Index>(cut.size()), 2);
  for (size_t k = 0; k < cut.size(); ++k) c.style.lines.row(k) = topo.edges.row(cut[k]);
  c.style.line_colors = Eigen::RowVector3d(0.15, 0.15, 0.15);
  const int count = labels.size() ? labels.maxCoeff() + 1 : 0;
  c.summary = std::to_string(count) + " labels, " + std::to_string(cut.size()) + " boundary edges drawn";
  return c;
}

Image add_color_bar(const Image& picture, const Coloring& c) {
  if (!c.has_bar) return picture;
  const int scale = picture.width >= 700 ? 2 : 1;
  const int pad = 8 * scale, h = 2 * text_height(scale) + 8 * scale;
  Image strip(picture.width, h + 2 * pad);
  const int w = std::min(picture.width - 2 * pad, 560 * scale);
  draw_color_bar(strip, (picture.width - w) / 2, pad, w, h, c.bar, scale);
  return vstack({picture, strip});
}

Coloring vertex_coloring(const Eigen::MatrixXd& vertex_colors, Eigen::Index num_vertices) {
  if (vertex_colors.rows() != num_vertices || vertex_colors.cols() != 3)
    throw InvalidInput("vertex colours are " + std::to_string(vertex_colors.rows()) + "x" +
                       std::to_string(vertex_colors.cols()) + ", expected " + std::to_string(num_vertices) + "x3");
  if (!vertex_colors.allFinite() ||
      (vertex_colors.size() && (vertex_colors.minCoeff() < 0 || vertex_colors.maxCoeff() > 1)))
    throw InvalidInput("vertex colours must be RGB values in [0, 1]");
  Coloring c;
  c.style.vertex_colors = vertex_colors;
  c.summary = "the file's vertex colours";
  return c;
}

}  // namespace msmesh
