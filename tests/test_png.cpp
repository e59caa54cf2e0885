// PNG encoding (png.h): structure, checksums, and the pixels decoded by an independent decoder
// (Python's zlib).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/image.h"
#include "msmesh/png.h"
#include "test_helpers.h"

using namespace msmesh;
namespace fs = std::filesystem;

TEST(Png, StructureAndChecksums) {
  Image im(7, 3, Eigen::Vector3d(0.2, 0.4, 0.6));
  const std::vector<std::uint8_t> png = encode_png(im);
  ASSERT_GT(png.size(), 8u + 25u + 12u + 12u);
  EXPECT_EQ(std::vector<std::uint8_t>(png.begin(), png.begin() + 8),
            (std::vector<std::uint8_t>{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'}));
  EXPECT_EQ(std::string(png.begin() + 12, png.begin() + 16), "IHDR");
  auto u32 = [&](size_t i) { return (png[i] << 24) | (png[i + 1] << 16) | (png[i + 2] << 8) | png[i + 3]; };
  EXPECT_EQ(u32(16), 7u);
  EXPECT_EQ(u32(20), 3u);
  EXPECT_EQ(png[24], 8);  // bit depth
  EXPECT_EQ(png[25], 2);  // RGB
  EXPECT_EQ(std::string(png.end() - 8, png.end() - 4), "IEND");
  EXPECT_THROW(encode_png(Image()), InvalidInput);
}

TEST(Png, DecodesToTheSamePixelsWithAnIndependentDecoder) {
  if (std::system("python3 -c 'import zlib' >/dev/null 2>&1") != 0) GTEST_SKIP() << "python3 not available";
  // A picture with flat areas, gradients and noise: every filter type and match length.
  Image im(97, 61);
  std::mt19937 rng(5);
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      Eigen::Vector3d c(x / 96.0, y / 60.0, 0.5);
      if (x > 60) c = Eigen::Vector3d::Constant((rng() % 256) / 255.0);
      if (y < 10) c = Eigen::Vector3d(0.9, 0.9, 0.9);
      im.set(x, y, c);
    }
  const fs::path dir = test::temp_folder("render_png");
  const std::vector<std::uint8_t> png = encode_png(im);
  {
    std::ofstream out(dir / "a.png", std::ios::binary);
    out.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
  }
  const std::string script = R"PY(
import struct, sys, zlib
d = open(sys.argv[1], 'rb').read()
i, idat = 8, b''
while i < len(d):
    n, = struct.unpack('>I', d[i:i+4]); t = d[i+4:i+8]; body = d[i+8:i+8+n]
    assert zlib.crc32(t + body) == struct.unpack('>I', d[i+8+n:i+12+n])[0], 'bad CRC'
    if t == b'IHDR': w, h = struct.unpack('>II', body[:8])
    if t == b'IDAT': idat += body
    i += 12 + n
raw = zlib.decompress(idat); s = 3 * w; out = bytearray(); prev = bytearray(s)
for y in range(h):
    f = raw[y*(s+1)]; line = bytearray(raw[y*(s+1)+1:(y+1)*(s+1)])
    for x in range(s):
        a = line[x-3] if x >= 3 else 0; b = prev[x]; c = prev[x-3] if x >= 3 else 0
        if f == 1: line[x] = (line[x] + a) & 255
        elif f == 2: line[x] = (line[x] + b) & 255
        elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c; pa, pb, pc = abs(p-a), abs(p-b), abs(p-c)
            line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    out += line; prev = line
open(sys.argv[2], 'wb').write(out)
)PY";
  { std::ofstream(dir / "decode.py") << script; }
  const test::CliRun r = test::run_command("python3 '" + (dir / "decode.py").string() + "' '" +
                                           (dir / "a.png").string() + "' '" + (dir / "a.rgb").string() + "'");
  ASSERT_EQ(r.status, 0) << r.out;
  const std::string rgb = test::read_bytes(dir / "a.rgb");
  ASSERT_EQ(rgb.size(), im.rgb.size());
  EXPECT_TRUE(std::equal(rgb.begin(), rgb.end(), im.rgb.begin(),
                         [](char a, std::uint8_t b) { return static_cast<std::uint8_t>(a) == b; }));
  fs::remove_all(dir);
}
