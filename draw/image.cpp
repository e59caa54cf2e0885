// Images (image.h): pixels, rectangles, copies and panel layout.
#include "msmesh/image.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "msmesh/errors.h"

namespace msmesh {

namespace {
inline std::uint8_t to_byte(double c) {
  if (!(c > 0)) return 0;  // also NaN
  if (c >= 1) return 255;
  return static_cast<std::uint8_t>(std::lround(c * 255.0));
}
}  // namespace

Image::Image(int w, int h, const Eigen::Vector3d& color) : width(w), height(h) {
  if (w < 0 || h < 0) throw InvalidInput("image size " + std::to_string(w) + "x" + std::to_string(h) + " is negative");
  rgb.resize(static_cast<size_t>(w) * h * 3);
  const std::uint8_t r = to_byte(color(0)), g = to_byte(color(1)), b = to_byte(color(2));
  for (size_t i = 0; i < rgb.size(); i += 3) {
    rgb[i] = r;
    rgb[i + 1] = g;
    rgb[i + 2] = b;
  }
}

Eigen::Vector3d Image::pixel(int x, int y) const {
  if (x < 0 || y < 0 || x >= width || y >= height)
    throw InvalidInput("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                       std::to_string(width) + "x" + std::to_string(height) + " image");
  const size_t i = (static_cast<size_t>(y) * width + x) * 3;
  return Eigen::Vector3d(rgb[i], rgb[i + 1], rgb[i + 2]) / 255.0;
}

void Image::set(int x, int y, const Eigen::Vector3d& color) {
  if (x < 0 || y < 0 || x >= width || y >= height) return;
  const size_t i = (static_cast<size_t>(y) * width + x) * 3;
  rgb[i] = to_byte(color(0));
  rgb[i + 1] = to_byte(color(1));
  rgb[i + 2] = to_byte(color(2));
}

void fill_rect(Image& image, int x, int y, int w, int h, const Eigen::Vector3d& color) {
  const int xa = std::max(0, x), xb = std::min(image.width, x + std::max(0, w));
  const int ya = std::max(0, y), yb = std::min(image.height, y + std::max(0, h));
  for (int j = ya; j < yb; ++j)
    for (int i = xa; i < xb; ++i) image.set(i, j, color);
}

void blit(Image& dst, const Image& src, int x, int y) {
  for (int j = std::max(0, -y); j < src.height && y + j < dst.height; ++j)
    for (int i = std::max(0, -x); i < src.width && x + i < dst.width; ++i) {
      const size_t s = (static_cast<size_t>(j) * src.width + i) * 3;
      const size_t d = (static_cast<size_t>(y + j) * dst.width + (x + i)) * 3;
      std::copy(src.rgb.begin() + s, src.rgb.begin() + s + 3, dst.rgb.begin() + d);
    }
}

namespace {
/// Panels one after the other, left to right (`horizontal` false: top to bottom), `gap` apart,
/// aligned at the top (left).
Image stack(const std::vector<Image>& panels, int gap, const Eigen::Vector3d& background, bool horizontal) {
  int along = 0, across = 0;
  for (size_t i = 0; i < panels.size(); ++i) {
    along += (horizontal ? panels[i].width : panels[i].height) + (i ? gap : 0);
    across = std::max(across, horizontal ? panels[i].height : panels[i].width);
  }
  Image out(horizontal ? along : across, horizontal ? across : along, background);
  int at = 0;
  for (const Image& p : panels) {
    blit(out, p, horizontal ? at : 0, horizontal ? 0 : at);
    at += (horizontal ? p.width : p.height) + gap;
  }
  return out;
}
}  // namespace

Image hstack(const std::vector<Image>& panels, int gap, const Eigen::Vector3d& background) {
  return stack(panels, gap, background, true);
}

Image vstack(const std::vector<Image>& panels, int gap, const Eigen::Vector3d& background) {
  return stack(panels, gap, background, false);
}

}  // namespace msmesh
