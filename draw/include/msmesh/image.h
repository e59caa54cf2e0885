// 8-bit RGB images in memory, and the 2D pieces of a figure made of them: filled rectangles,
// copies and panels laid out side by side. Part of the drawing library (msmesh_draw), which
// the core library does not link.
#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace msmesh {

/// An 8-bit RGB image: rows top to bottom, 3 bytes (R, G, B) per pixel.
struct Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  ///< width·height·3 bytes

  Image() = default;
  /// A width by height image filled with `color` (RGB in [0,1]; default white).
  Image(int width, int height, const Eigen::Vector3d& color = Eigen::Vector3d::Ones());

  /// Colour of pixel (x, y) in [0,1]; (0,0) is the top-left pixel.
  Eigen::Vector3d pixel(int x, int y) const;
  /// Sets pixel (x, y) to `color` (clamped to [0,1]); ignores pixels outside the image.
  void set(int x, int y, const Eigen::Vector3d& color);
  bool operator==(const Image& o) const { return width == o.width && height == o.height && rgb == o.rgb; }
  bool operator!=(const Image& o) const { return !(*this == o); }
};

/// Fills the rectangle [x, x+w) × [y, y+h), clipped to the image.
void fill_rect(Image& image, int x, int y, int w, int h, const Eigen::Vector3d& color);

/// Copies `src` into `dst` with its top-left corner at (x, y), clipped.
void blit(Image& dst, const Image& src, int x, int y);

/// Lays `panels` out left to right, `gap` pixels apart, on `background`, tops aligned.
Image hstack(const std::vector<Image>& panels, int gap = 0,
             const Eigen::Vector3d& background = Eigen::Vector3d::Ones());
/// Lays `panels` out top to bottom, `gap` pixels apart, left aligned.
Image vstack(const std::vector<Image>& panels, int gap = 0,
             const Eigen::Vector3d& background = Eigen::Vector3d::Ones());

}  // namespace msmesh
