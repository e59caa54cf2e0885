// Figure helpers shared by `msmesh render` and `msmesh compare`: PNG files, picture sizes, and
// colouring a mesh by angle error, edge field or segment label (with the colour bar).
#pragma once
#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <string>
#include <utility>

#include "msmesh/color_bar.h"
#include "msmesh/color_map.h"
#include "msmesh/image.h"
#include "msmesh/render.h"

namespace msmesh::cli {

/// Writes `image` as a PNG file (atomically). Throws IoError naming the file.
void write_png(const std::string& path, const Image& image);

/// Parses "WxH" (e.g. "800x600") into width and height, each strictly a whole number in the
/// range of RenderOptions (render_parameters()); throws InvalidInput otherwise.
std::pair<int, int> parse_size(const std::string& text);

/// The options render and compare share, each checked while the command line is parsed (a
/// usage error naming the option, exit 2): --size WxH, --feature-edges DEG in [0, 180),
/// --error-max DEG in [0, 180], --supersample in [1, 4].
CLI::Option* add_size_option(CLI::App* c, std::string& size, const std::string& help);
CLI::Option* add_feature_edges_option(CLI::App* c, double& degrees, const std::string& help);
CLI::Option* add_error_max_option(CLI::App* c, double& degrees, const std::string& help);
CLI::Option* add_supersample_option(CLI::App* c, int& supersample);

/// The colours and legend of one rendered mesh.
struct Coloring {
  MeshStyle style;
  bool has_bar = false;
  ColorBar bar;
  std::string summary;  ///< one line for the terminal, e.g. "angle error 0-12.5 deg"
};

/// Faces coloured by angle error (degrees, #F) on [0, max_deg] with heat_color();
/// max_deg ≤ 0: automatic (error_scale of the values).
Coloring error_coloring(const Eigen::VectorXd& angle_deg, double max_deg);
/// A round upper end for an error colour scale: the 98th percentile of the values rounded up
/// to 1, 2 or 5 × 10^k (so one wild face does not wash the picture out), at least 1e-3.
double error_scale(const Eigen::VectorXd& values);
/// The edge field v (#E, v[e] on Topology::edges.row(e) of F) as lines coloured with field_color() of
/// the normalised field (features dark red); smooth edges are left undrawn.
Coloring field_coloring(const Eigen::MatrixXi& F, Eigen::Index num_vertices, const Eigen::VectorXd& v);
/// Faces coloured by label (label_color), with dark lines where the label changes.
Coloring label_coloring(const Eigen::MatrixXi& F, Eigen::Index num_vertices, const Eigen::VectorXi& labels);

/// `picture` with a strip below it holding the colour bar of `c` (when it has one).
Image add_color_bar(const Image& picture, const Coloring& c);

}  // namespace msmesh::cli
