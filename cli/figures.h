// Figure helpers shared by `msmesh render` and `msmesh compare`: PNG files, picture sizes and
// the options both take (the colourings themselves: msmesh/mesh_coloring.h).
#pragma once
#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <string>
#include <utility>

#include "msmesh/image.h"
#include "msmesh/mesh_coloring.h"
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

}  // namespace msmesh::cli
