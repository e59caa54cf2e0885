// Colour bars: the legend of a figure coloured by a colour map, with tick labels.
#pragma once
#include <Eigen/Core>
#include <string>

#include "msmesh/color_map.h"
#include "msmesh/image.h"

namespace msmesh {

/// A horizontal colour bar with tick labels, for a figure's legend.
struct ColorBar {
  ColorMap map;                 ///< colours of [0,1]
  double min = 0, max = 1;      ///< the values at the two ends (labels)
  int ticks = 3;                ///< labelled ticks, evenly spaced, ends included (≥ 2)
  std::string title;            ///< drawn left of the bar, e.g. "angle error (deg)"
  bool max_is_clamped = false;  ///< label the top end ">=max" (larger values share its colour)
};

/// The formatted tick label of a value: at most 3 significant digits, no exponent for
/// values in [1e-3, 1e5) ("0", "0.25", "12.5", "1500").
std::string format_tick(double value);

/// Draws `bar` into the rectangle (x, y, w, h) of `image`: the title on the left, then the
/// gradient with a dark frame and ticks, labels under it. Text at `scale`. Needs h ≥
/// 2·text_height(scale) + 6·scale to fit; less is clipped.
void draw_color_bar(Image& image, int x, int y, int w, int h, const ColorBar& bar, int scale = 1);

}  // namespace msmesh
