// PNG encoding of images to bytes in memory (a self-contained encoder, no zlib).
#pragma once
#include <cstdint>
#include <vector>

#include "msmesh/image.h"

namespace msmesh {

/// The bytes of a PNG file of `image` (8-bit RGB, no interlace; per-row adaptive filters,
/// deflate with fixed Huffman codes and LZ77 matching: a self-contained encoder, no zlib).
/// Deterministic. Throws InvalidInput for an empty image or one whose rgb has the wrong size.
std::vector<std::uint8_t> encode_png(const Image& image);

}  // namespace msmesh
