// Colour maps (color_map.h).
#include "msmesh/color_map.h"

#include <algorithm>
#include <cmath>

namespace msmesh {

Eigen::Vector3d heat_color(double x) {
  // ColorBrewer's 9-class YlOrRd, linear between the classes.
  static const double stops[9][3] = {{255, 255, 204}, {255, 237, 160}, {254, 217, 118}, {254, 178, 76}, {253, 141, 60},
                                     {252, 78, 42},   {227, 26, 28},   {189, 0, 38},    {128, 0, 38}};
  if (!(x > 0)) x = 0;  // also NaN
  x = std::min(x, 1.0) * 8.0;
  const int i = std::min(7, static_cast<int>(x));
  const double t = x - i;
  Eigen::Vector3d c;
  for (int k = 0; k < 3; ++k) c(k) = (stops[i][k] + t * (stops[i + 1][k] - stops[i][k])) / 255.0;
  return c;
}

Eigen::Vector3d field_color(double x) {
  x = std::clamp(x, 0.0, 1.0);
  const Eigen::Vector3d a(0.45, 0.0, 0.05), b(1.0, 0.8, 0.1), c(0.85, 0.85, 0.85);
  return x < 0.5 ? Eigen::Vector3d(a + (b - a) * (x / 0.5)) : Eigen::Vector3d(b + (c - b) * ((x - 0.5) / 0.5));
}

Eigen::Vector3d label_color(int label) {
  // Distinct colours: hues stepped by the golden ratio, so neighbouring labels differ a lot.
  // Used for pictures, reports and segment's .ply output alike.
  if (label < 0) return {0.5, 0.5, 0.5};
  const double h = std::fmod(0.11 + 0.618033988749895 * label, 1.0) * 6.0;
  const double s = (label % 3 == 2) ? 0.45 : 0.7, v = (label % 2) ? 0.8 : 0.95;
  const int i = static_cast<int>(h) % 6;
  const double f = h - std::floor(h), p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  switch (i) {
    case 0:
      return {v, t, p};
    case 1:
      return {q, v, p};
    case 2:
      return {p, v, t};
    case 3:
      return {p, q, v};
    case 4:
      return {t, p, v};
    default:
      return {v, p, q};
  }
}

}  // namespace msmesh
