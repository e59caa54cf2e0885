// Pixels of images (image.h), shared by the tests of the drawing library.
#pragma once
#include <array>
#include <cstddef>

#include "msmesh/image.h"

namespace msmesh::test {

/// The (R, G, B) bytes of pixel (x, y).
inline std::array<int, 3> px(const Image& im, int x, int y) {
  const size_t i = (static_cast<size_t>(y) * im.width + x) * 3;
  return {im.rgb[i], im.rgb[i + 1], im.rgb[i + 2]};
}

}  // namespace msmesh::test
