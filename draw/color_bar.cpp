// Colour bars (color_bar.h).
#include "msmesh/color_bar.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "msmesh/errors.h"
#include "msmesh/text.h"

namespace msmesh {

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

}  // namespace msmesh
