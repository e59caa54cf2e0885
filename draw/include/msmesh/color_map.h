// Colour maps for figures (x in [0,1], values outside are clamped; RGB in [0,1]).
#pragma once
#include <Eigen/Core>
#include <functional>

namespace msmesh {

using ColorMap = std::function<Eigen::Vector3d(double)>;

/// Sequential map for errors (ColorBrewer YlOrRd, designed for perception and colour-blind
/// safe): light yellow (0, shaded faces still read as a shape) to dark red (1).
Eigen::Vector3d heat_color(double x);

/// Edge field map (x in [0,1]): dark red (0, features) through yellow to light grey (1, smooth).
Eigen::Vector3d field_color(double x);

/// Distinct colours for labels ≥ 0: hues stepped by the golden ratio (the same colours as the
/// faces of `msmesh segment`'s .ply output).
Eigen::Vector3d label_color(int label);

}  // namespace msmesh
