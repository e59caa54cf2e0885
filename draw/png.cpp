// PNG encoding (png.h): RFC 2083 / ISO 15948 with zlib RFC 1950 and deflate RFC 1951,
// per-row adaptive filters, LZ77 with hash chains, one deflate block with the fixed Huffman
// codes. No dependency; rendered figures (large flat areas) compress well with it.
#include "msmesh/png.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <string>

#include "msmesh/errors.h"

namespace msmesh {
namespace {

// ---------------------------------------------------------------------------------------
// Checksums
// ---------------------------------------------------------------------------------------

std::uint32_t crc32(const std::uint8_t* data, size_t n, std::uint32_t crc = 0) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  crc = ~crc;
  for (size_t i = 0; i < n; ++i) crc = table[(crc ^ data[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

std::uint32_t adler32(const std::vector<std::uint8_t>& data) {
  std::uint32_t a = 1, b = 0;
  size_t i = 0;
  while (i < data.size()) {
    const size_t end = std::min(data.size(), i + 5552);  // largest run without overflow
    for (; i < end; ++i) {
      a += data[i];
      b += a;
    }
    a %= 65521;
    b %= 65521;
  }
  return (b << 16) | a;
}

// ---------------------------------------------------------------------------------------
// Deflate, fixed Huffman codes (RFC 1951 §3.2.6)
// ---------------------------------------------------------------------------------------

class BitWriter {
 public:
  explicit BitWriter(std::vector<std::uint8_t>& out) : out_(out) {}
  /// Appends the n low bits of `bits`, least significant first (data elements, extra bits).
  void put(std::uint32_t bits, int n) {
    acc_ |= static_cast<std::uint64_t>(bits & ((1u << n) - 1)) << count_;
    count_ += n;
    while (count_ >= 8) {
      out_.push_back(static_cast<std::uint8_t>(acc_ & 0xFF));
      acc_ >>= 8;
      count_ -= 8;
    }
  }
  /// Appends a Huffman code of n bits, most significant bit first.
  void put_code(std::uint32_t code, int n) {
    std::uint32_t r = 0;
    for (int i = 0; i < n; ++i) r |= ((code >> i) & 1u) << (n - 1 - i);
    put(r, n);
  }
  void flush() {
    if (count_ > 0) out_.push_back(static_cast<std::uint8_t>(acc_ & 0xFF));
    acc_ = 0;
    count_ = 0;
  }

 private:
  std::vector<std::uint8_t>& out_;
  std::uint64_t acc_ = 0;
  int count_ = 0;
};

void put_literal_length(BitWriter& w, int symbol) {
  if (symbol < 144)
    w.put_code(0x30 + symbol, 8);
  else if (symbol < 256)
    w.put_code(0x190 + (symbol - 144), 9);
  else if (symbol < 280)
    w.put_code(symbol - 256, 7);
  else
    w.put_code(0xC0 + (symbol - 280), 8);
}

constexpr int kLengthBase[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                 31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr int kLengthExtra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                  2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr int kDistBase[30] = {1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
                               193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
constexpr int kDistExtra[30] = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                                6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

void put_match(BitWriter& w, int length, int distance) {
  int li = 28;
  while (kLengthBase[li] > length) --li;
  put_literal_length(w, 257 + li);
  if (kLengthExtra[li]) w.put(static_cast<std::uint32_t>(length - kLengthBase[li]), kLengthExtra[li]);
  int di = 29;
  while (kDistBase[di] > distance) --di;
  w.put_code(static_cast<std::uint32_t>(di), 5);
  if (kDistExtra[di]) w.put(static_cast<std::uint32_t>(distance - kDistBase[di]), kDistExtra[di]);
}

/// A zlib stream (RFC 1950) of `data`: one final fixed-Huffman deflate block, greedy LZ77
/// matching over a 32 KiB window with hash chains of bounded length.
std::vector<std::uint8_t> zlib_compress(const std::vector<std::uint8_t>& data) {
  std::vector<std::uint8_t> out = {0x78, 0x01};  // deflate, 32 KiB window; (0x7801 % 31 == 0)
  BitWriter w(out);
  w.put(1, 1);  // BFINAL
  w.put(1, 2);  // BTYPE = 01, fixed Huffman codes
  constexpr int kWindow = 32768, kMinMatch = 3, kMaxMatch = 258, kMaxChain = 96;
  constexpr int kHashBits = 15;
  std::vector<int> head(1 << kHashBits, -1), prev(data.size(), -1);
  const size_t n = data.size();
  auto hash = [&](size_t i) {
    const std::uint32_t v = (std::uint32_t(data[i]) << 16) | (std::uint32_t(data[i + 1]) << 8) | data[i + 2];
    return static_cast<int>((v * 2654435761u) >> (32 - kHashBits));
  };
  auto insert = [&](size_t i) {
    if (i + kMinMatch > n) return;
    const int h = hash(i);
    prev[i] = head[h];
    head[h] = static_cast<int>(i);
  };
  size_t i = 0;
  while (i < n) {
    int best_len = 0, best_dist = 0;
    if (i + kMinMatch <= n) {
      const size_t max_len = std::min<size_t>(kMaxMatch, n - i);
      int cand = head[hash(i)];
      for (int chain = 0; cand >= 0 && chain < kMaxChain; ++chain, cand = prev[cand]) {
        const size_t dist = i - static_cast<size_t>(cand);
        if (dist > kWindow) break;
        if (data[cand + best_len] != data[i + best_len]) continue;  // cannot beat the best
        size_t len = 0;
        while (len < max_len && data[cand + len] == data[i + len]) ++len;
        if (static_cast<int>(len) > best_len) {
          best_len = static_cast<int>(len);
          best_dist = static_cast<int>(dist);
          if (len == max_len) break;
        }
      }
    }
    if (best_len >= kMinMatch) {
      put_match(w, best_len, best_dist);
      for (int k = 0; k < best_len; ++k) insert(i + k);
      i += best_len;
    } else {
      put_literal_length(w, data[i]);
      insert(i);
      ++i;
    }
  }
  put_literal_length(w, 256);  // end of block
  w.flush();
  const std::uint32_t a = adler32(data);
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<std::uint8_t>((a >> s) & 0xFF));
  return out;
}

// ---------------------------------------------------------------------------------------
// PNG
// ---------------------------------------------------------------------------------------

int paeth(int a, int b, int c) {
  const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

/// The filtered scanlines (filter-type byte + row), each row filtered with the type whose
/// output has the smallest sum of absolute values (the usual heuristic of libpng).
std::vector<std::uint8_t> filter_rows(const Image& image) {
  const size_t stride = static_cast<size_t>(image.width) * 3;
  std::vector<std::uint8_t> out;
  out.reserve((stride + 1) * image.height);
  std::vector<std::uint8_t> zero(stride, 0), candidate(stride), best(stride);
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* row = image.rgb.data() + y * stride;
    const std::uint8_t* up = y > 0 ? row - stride : zero.data();
    long best_cost = -1;
    int best_type = 0;
    for (int type = 0; type < 5; ++type) {
      long cost = 0;
      for (size_t i = 0; i < stride; ++i) {
        const int a = i >= 3 ? row[i - 3] : 0, b = up[i], c = i >= 3 ? up[i - 3] : 0;
        int pred = 0;
        switch (type) {
          case 1:
            pred = a;
            break;
          case 2:
            pred = b;
            break;
          case 3:
            pred = (a + b) / 2;
            break;
          case 4:
            pred = paeth(a, b, c);
            break;
          default:
            break;
        }
        const std::uint8_t v = static_cast<std::uint8_t>(row[i] - pred);
        candidate[i] = v;
        cost += v < 128 ? v : 256 - v;
      }
      if (best_cost < 0 || cost < best_cost) {
        best_cost = cost;
        best_type = type;
        best.swap(candidate);
      }
    }
    out.push_back(static_cast<std::uint8_t>(best_type));
    out.insert(out.end(), best.begin(), best.end());
  }
  return out;
}

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<std::uint8_t>((v >> s) & 0xFF));
}

void put_chunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& data) {
  put_u32(out, static_cast<std::uint32_t>(data.size()));
  const size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  put_u32(out, crc32(out.data() + start, out.size() - start));
}

}  // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
  if (image.width < 1 || image.height < 1)
    throw InvalidInput("encode_png: the image is empty (" + std::to_string(image.width) + "x" +
                       std::to_string(image.height) + ")");
  if (image.rgb.size() != static_cast<size_t>(image.width) * image.height * 3)
    throw InvalidInput("encode_png: the image has " + std::to_string(image.rgb.size()) + " bytes, expected " +
                       std::to_string(static_cast<size_t>(image.width) * image.height * 3));
  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  std::vector<std::uint8_t> ihdr;
  put_u32(ihdr, static_cast<std::uint32_t>(image.width));
  put_u32(ihdr, static_cast<std::uint32_t>(image.height));
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, adaptive filters, no interlace
  put_chunk(png, "IHDR", ihdr);
  put_chunk(png, "IDAT", zlib_compress(filter_rows(image)));
  put_chunk(png, "IEND", {});
  return png;
}

}  // namespace msmesh
