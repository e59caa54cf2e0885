// 2D drawing of render.h: rectangles, a 5×7 bitmap font, colour bars, panel layout.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "msmesh/errors.h"
#include "msmesh/render.h"

namespace msmesh {

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

// ---------------------------------------------------------------------------------------
// Font: the classic 5×7 LCD font, one byte per column, bit 0 = top row (rows 0–7; row 7 is
// only used by descenders). Printable ASCII 32–126, then "°" and "×".
// ---------------------------------------------------------------------------------------

namespace {

constexpr unsigned char kFont[][5] = {
    {0x00, 0x00, 0x00, 0x00, 0x00},  // ' '
    {0x00, 0x00, 0x5F, 0x00, 0x00},  // !
    {0x00, 0x07, 0x00, 0x07, 0x00},  // "
    {0x14, 0x7F, 0x14, 0x7F, 0x14},  // #
    {0x24, 0x2A, 0x7F, 0x2A, 0x12},  // $
    {0x23, 0x13, 0x08, 0x64, 0x62},  // %
    {0x36, 0x49, 0x55, 0x22, 0x50},  // &
    {0x00, 0x05, 0x03, 0x00, 0x00},  // '
    {0x00, 0x1C, 0x22, 0x41, 0x00},  // (
    {0x00, 0x41, 0x22, 0x1C, 0x00},  // )
    {0x14, 0x08, 0x3E, 0x08, 0x14},  // *
    {0x08, 0x08, 0x3E, 0x08, 0x08},  // +
    {0x00, 0x50, 0x30, 0x00, 0x00},  // ,
    {0x08, 0x08, 0x08, 0x08, 0x08},  // -
    {0x00, 0x60, 0x60, 0x00, 0x00},  // .
    {0x20, 0x10, 0x08, 0x04, 0x02},  // /
    {0x3E, 0x51, 0x49, 0x45, 0x3E},  // 0
    {0x00, 0x42, 0x7F, 0x40, 0x00},  // 1
    {0x42, 0x61, 0x51, 0x49, 0x46},  // 2
    {0x21, 0x41, 0x45, 0x4B, 0x31},  // 3
    {0x18, 0x14, 0x12, 0x7F, 0x10},  // 4
    {0x27, 0x45, 0x45, 0x45, 0x39},  // 5
    {0x3C, 0x4A, 0x49, 0x49, 0x30},  // 6
    {0x01, 0x71, 0x09, 0x05, 0x03},  // 7
    {0x36, 0x49, 0x49, 0x49, 0x36},  // 8
    {0x06, 0x49, 0x49, 0x29, 0x1E},  // 9
    {0x00, 0x36, 0x36, 0x00, 0x00},  // :
    {0x00, 0x56, 0x36, 0x00, 0x00},  // ;
    {0x08, 0x14, 0x22, 0x41, 0x00},  // <
    {0x14, 0x14, 0x14, 0x14, 0x14},  // =
    {0x00, 0x41, 0x22, 0x14, 0x08},  // >
    {0x02, 0x01, 0x51, 0x09, 0x06},  // ?
    {0x32, 0x49, 0x79, 0x41, 0x3E},  // @
    {0x7E, 0x11, 0x11, 0x11, 0x7E},  // A
    {0x7F, 0x49, 0x49, 0x49, 0x36},  // B
    {0x3E, 0x41, 0x41, 0x41, 0x22},  // C
    {0x7F, 0x41, 0x41, 0x22, 0x1C},  // D
    {0x7F, 0x49, 0x49, 0x49, 0x41},  // E
    {0x7F, 0x09, 0x09, 0x09, 0x01},  // F
    {0x3E, 0x41, 0x49, 0x49, 0x7A},  // G
    {0x7F, 0x08, 0x08, 0x08, 0x7F},  // H
    {0x00, 0x41, 0x7F, 0x41, 0x00},  // I
    {0x20, 0x40, 0x41, 0x3F, 0x01},  // J
    {0x7F, 0x08, 0x14, 0x22, 0x41},  // K
    {0x7F, 0x40, 0x40, 0x40, 0x40},  // L
    {0x7F, 0x02, 0x0C, 0x02, 0x7F},  // M
    {0x7F, 0x04, 0x08, 0x10, 0x7F},  // N
    {0x3E, 0x41, 0x41, 0x41, 0x3E},  // O
    {0x7F, 0x09, 0x09, 0x09, 0x06},  // P
    {0x3E, 0x41, 0x51, 0x21, 0x5E},  // Q
    {0x7F, 0x09, 0x19, 0x29, 0x46},  // R
    {0x46, 0x49, 0x49, 0x49, 0x31},  // S
    {0x01, 0x01, 0x7F, 0x01, 0x01},  // T
    {0x3F, 0x40, 0x40, 0x40, 0x3F},  // U
    {0x1F, 0x20, 0x40, 0x20, 0x1F},  // V
    {0x3F, 0x40, 0x38, 0x40, 0x3F},  // W
    {0x63, 0x14, 0x08, 0x14, 0x63},  // X
    {0x07, 0x08, 0x70, 0x08, 0x07},  // Y
    {0x61, 0x51, 0x49, 0x45, 0x43},  // Z
    {0x00, 0x7F, 0x41, 0x41, 0x00},  // [
    {0x02, 0x04, 0x08, 0x10, 0x20},  // backslash
    {0x00, 0x41, 0x41, 0x7F, 0x00},  // ]
    {0x04, 0x02, 0x01, 0x02, 0x04},  // ^
    {0x40, 0x40, 0x40, 0x40, 0x40},  // _
    {0x00, 0x01, 0x02, 0x04, 0x00},  // `
    {0x20, 0x54, 0x54, 0x54, 0x78},  // a
    {0x7F, 0x48, 0x44, 0x44, 0x38},  // b
    {0x38, 0x44, 0x44, 0x44, 0x20},  // c
    {0x38, 0x44, 0x44, 0x48, 0x7F},  // d
    {0x38, 0x54, 0x54, 0x54, 0x18},  // e
    {0x08, 0x7E, 0x09, 0x01, 0x02},  // f
    {0x18, 0xA4, 0xA4, 0xA4, 0x7C},  // g
    {0x7F, 0x08, 0x04, 0x04, 0x78},  // h
    {0x00, 0x44, 0x7D, 0x40, 0x00},  // i
    {0x40, 0x80, 0x84, 0x7D, 0x00},  // j
    {0x7F, 0x10, 0x28, 0x44, 0x00},  // k
    {0x00, 0x41, 0x7F, 0x40, 0x00},  // l
    {0x7C, 0x04, 0x78, 0x04, 0x78},  // m
    {0x7C, 0x08, 0x04, 0x04, 0x78},  // n
    {0x38, 0x44, 0x44, 0x44, 0x38},  // o
    {0xFC, 0x24, 0x24, 0x24, 0x18},  // p
    {0x18, 0x24, 0x24, 0x24, 0xFC},  // q
    {0x7C, 0x08, 0x04, 0x04, 0x08},  // r
    {0x48, 0x54, 0x54, 0x54, 0x24},  // s
    {0x04, 0x3F, 0x44, 0x40, 0x20},  // t
    {0x3C, 0x40, 0x40, 0x20, 0x7C},  // u
    {0x1C, 0x20, 0x40, 0x20, 0x1C},  // v
    {0x3C, 0x40, 0x30, 0x40, 0x3C},  // w
    {0x44, 0x28, 0x10, 0x28, 0x44},  // x
    {0x1C, 0xA0, 0xA0, 0xA0, 0x7C},  // y
    {0x44, 0x64, 0x54, 0x4C, 0x44},  // z
    {0x00, 0x08, 0x36, 0x41, 0x00},  // {
    {0x00, 0x00, 0x7F, 0x00, 0x00},  // |
    {0x00, 0x41, 0x36, 0x08, 0x00},  // }
    {0x08, 0x04, 0x08, 0x10, 0x08},  // ~
    {0x00, 0x06, 0x09, 0x09, 0x06},  // ° (index 95)
    {0x22, 0x14, 0x08, 0x14, 0x22},  // × (index 96)
};
constexpr int kUnknown = '?' - 32;

/// Glyph indices of a UTF-8 string (one per character shown).
std::vector<int> glyphs(const std::string& text) {
  std::vector<int> g;
  for (size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 32 && c <= 126) {
      g.push_back(c - 32);
    } else if (c == 0xC2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) == 0xB0) {
      g.push_back(95);
      ++i;
    } else if (c == 0xC3 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) == 0x97) {
      g.push_back(96);
      ++i;
    } else if (c >= 0x80) {
      // Skip the continuation bytes of an unsupported UTF-8 sequence: one "?" per character.
      while (i + 1 < text.size() && (static_cast<unsigned char>(text[i + 1]) & 0xC0) == 0x80) ++i;
      g.push_back(kUnknown);
    } else {
      g.push_back(kUnknown);  // control characters
    }
  }
  return g;
}

}  // namespace

int text_height(int scale) { return 8 * std::max(1, scale); }

int text_width(const std::string& text, int scale) {
  const int n = static_cast<int>(glyphs(text).size());
  return n == 0 ? 0 : (6 * n - 1) * std::max(1, scale);
}

void draw_text(Image& image, int x, int y, const std::string& text, const Eigen::Vector3d& color, int scale) {
  scale = std::max(1, scale);
  int pen = x;
  for (int g : glyphs(text)) {
    for (int col = 0; col < 5; ++col)
      for (int row = 0; row < 8; ++row)
        if (kFont[g][col] & (1u << row)) fill_rect(image, pen + col * scale, y + row * scale, scale, scale, color);
    pen += 6 * scale;
  }
}

// ---------------------------------------------------------------------------------------
// Colour bar and layout
// ---------------------------------------------------------------------------------------

std::string format_tick(double value) {
  if (!std::isfinite(value)) return value > 0 ? "inf" : (value < 0 ? "-inf" : "nan");
  if (value == 0) return "0";
  char buf[32];
  const double a = std::abs(value);
  if (a >= 1e-3 && a < 1e5) {
    // 3 significant digits, fixed notation, trailing zeros dropped.
    const int digits = std::max(0, 2 - static_cast<int>(std::floor(std::log10(a))));
    std::snprintf(buf, sizeof buf, "%.*f", digits, value);
    std::string s = buf;
    if (s.find('.') != std::string::npos) {
      while (!s.empty() && s.back() == '0') s.pop_back();
      if (!s.empty() && s.back() == '.') s.pop_back();
    }
    return s == "-0" ? "0" : s;
  }
  std::snprintf(buf, sizeof buf, "%.2g", value);
  return buf;
}

void draw_color_bar(Image& image, int x, int y, int w, int h, const ColorBar& bar, int scale) {
  if (!bar.map) throw InvalidInput("draw_color_bar: the colour bar has no colour map");
  scale = std::max(1, scale);
  const Eigen::Vector3d ink(0.15, 0.15, 0.15);
  const int th = text_height(scale);
  int bx = x;
  if (!bar.title.empty()) {
    draw_text(image, x, y + std::max(0, (h - th) / 2 - 2 * scale), bar.title, ink, scale);
    bx = x + text_width(bar.title, scale) + 6 * scale;
  }
  // Room for half a label on either end.
  const std::string lo_label = format_tick(bar.min);
  const std::string hi_label = (bar.max_is_clamped ? ">=" : "") + format_tick(bar.max);
  const int pad = std::max(text_width(lo_label, scale), text_width(hi_label, scale)) / 2 + scale;
  const int bar_x = bx + pad, bar_w = std::max(2, x + w - pad - bar_x);
  const int bar_h = std::max(4 * scale, h - th - 5 * scale);
  const int bar_y = y;
  for (int i = 0; i < bar_w; ++i) {
    const Eigen::Vector3d c = bar.map(bar_w > 1 ? double(i) / (bar_w - 1) : 0.0);
    fill_rect(image, bar_x + i, bar_y, 1, bar_h, c);
  }
  // Frame.
  fill_rect(image, bar_x - 1, bar_y - 1, bar_w + 2, 1, ink);
  fill_rect(image, bar_x - 1, bar_y + bar_h, bar_w + 2, 1, ink);
  fill_rect(image, bar_x - 1, bar_y - 1, 1, bar_h + 2, ink);
  fill_rect(image, bar_x + bar_w, bar_y - 1, 1, bar_h + 2, ink);
  const int ticks = std::max(2, bar.ticks);
  for (int t = 0; t < ticks; ++t) {
    const double u = double(t) / (ticks - 1);
    const int tx = bar_x + static_cast<int>(std::lround(u * (bar_w - 1)));
    fill_rect(image, tx, bar_y + bar_h, std::max(1, scale / 2 + 1), 2 * scale + 1, ink);
    std::string label = format_tick(bar.min + u * (bar.max - bar.min));
    if (t == ticks - 1 && bar.max_is_clamped) label = hi_label;
    const int lw = text_width(label, scale);
    draw_text(image, tx - lw / 2, bar_y + bar_h + 3 * scale + 1, label, ink, scale);
  }
}

Image hstack(const std::vector<Image>& panels, int gap, const Eigen::Vector3d& background) {
  int w = 0, h = 0;
  for (size_t i = 0; i < panels.size(); ++i) {
    w += panels[i].width + (i ? gap : 0);
    h = std::max(h, panels[i].height);
  }
  Image out(w, h, background);
  int x = 0;
  for (const Image& p : panels) {
    blit(out, p, x, 0);
    x += p.width + gap;
  }
  return out;
}

Image vstack(const std::vector<Image>& panels, int gap, const Eigen::Vector3d& background) {
  int w = 0, h = 0;
  for (size_t i = 0; i < panels.size(); ++i) {
    h += panels[i].height + (i ? gap : 0);
    w = std::max(w, panels[i].width);
  }
  Image out(w, h, background);
  int y = 0;
  for (const Image& p : panels) {
    blit(out, p, 0, y);
    y += p.height + gap;
  }
  return out;
}

}  // namespace msmesh
