// Colouring a mesh for a figure: faces by angle error, edges by edge field, faces by segment
// label, or the file's own vertex colours, each with its legend (a colour bar) and a one-line
// summary. Shared by `msmesh render`, `msmesh compare` and msmesh.render()/compare().
#pragma once
#include <Eigen/Core>
#include <string>

#include "msmesh/color_bar.h"
#include "msmesh/image.h"
#include "msmesh/render.h"

namespace msmesh {

/// The colours and legend of one rendered mesh.
struct Coloring {
  MeshStyle style;
  bool has_bar = false;
  ColorBar bar;
  std::string summary;  ///< one line for the terminal, e.g. "angle error 0-12.5 deg"
};

/// A round upper end for an error colour scale: the 98th percentile of the values rounded up
/// to 1, 2 or 5 × 10^k (so one wild face does not wash the picture out), at least 1e-3.
double error_scale(const Eigen::VectorXd& values);

/// Faces coloured by angle error (degrees, #F) on [0, max_deg] with heat_color();
/// max_deg ≤ 0: automatic (error_scale of the values). Larger errors share the top colour,
/// and the bar says so (">=max").
Coloring error_coloring(const Eigen::VectorXd& angle_deg, double max_deg);

/// The edge field v (#E, v[e] on Topology::edges.row(e) of F) as lines coloured with
/// field_color() of the normalised field (features dark red); smooth edges are left undrawn.
/// Throws InvalidInput when v does not have one value per edge.
Coloring field_coloring(const Eigen::MatrixXi& F, Eigen::Index num_vertices, const Eigen::VectorXd& v);

/// Faces coloured by label (label_color), with dark lines where the label changes. Throws
/// InvalidInput when labels does not have one value per face.
Coloring label_coloring(const Eigen::MatrixXi& F, Eigen::Index num_vertices, const Eigen::VectorXi& labels);

/// The file's own colours: `vertex_colors` (#V by 3, RGB in [0,1]) interpolated across the
/// faces; no colour bar. Throws InvalidInput for a wrong size or values outside [0,1].
Coloring vertex_coloring(const Eigen::MatrixXd& vertex_colors, Eigen::Index num_vertices);

/// `picture` with a strip below it holding the colour bar of `c` (when it has one).
Image add_color_bar(const Image& picture, const Coloring& c);

}  // namespace msmesh
