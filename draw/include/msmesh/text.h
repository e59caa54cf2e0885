// Text in figures: a built-in 5×7 bitmap font (no font files, the same pixels everywhere).
#pragma once
#include <Eigen/Core>
#include <string>

#include "msmesh/image.h"

namespace msmesh {

/// Height in pixels of a line of text drawn at `scale` (8·scale: 7 rows and a descender row).
int text_height(int scale = 1);
/// Width in pixels of `text` drawn at `scale` (6·scale per character, minus the last gap).
int text_width(const std::string& text, int scale = 1);
/// Draws `text` (printable ASCII; UTF-8 "°" and "×" too; anything else shows as "?") with a
/// built-in 5×7 bitmap font, each font pixel a scale×scale block, top-left corner at (x, y).
void draw_text(Image& image, int x, int y, const std::string& text, const Eigen::Vector3d& color, int scale = 1);

}  // namespace msmesh
