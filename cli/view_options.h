// The camera options `msmesh render` and `msmesh compare` share: --view, --up, --azimuth,
// --elevation and --perspective (azimuth and elevation from the render parameter table).
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "msmesh/parameters.h"
#include "msmesh/render.h"
#include "number_option.h"

namespace msmesh::cli {

struct ViewArgs {
  std::string view = "iso", up = "y";
  RenderOptions angles;  ///< azimuth_deg and elevation_deg, set by the table's options
  bool perspective = false;
};

inline void add_view_options(CLI::App* c, ViewArgs& v) {
  c->add_option("--view", v.view, "iso, front, back, left, right, top or bottom (seen with --up pointing up)")
      ->check(CLI::IsMember(view_names()))
      ->capture_default_str();
  std::vector<std::string> axes = up_axis_names();
  for (const std::string& a : up_axis_names())
    if (a[0] != '-') axes.push_back("+" + a);
  c->add_option("--up", v.up,
                "World axis shown upwards: y (OBJ, glTF, most scans; front looks from +z), z (CAD, STL; front looks "
                "from -y), x, or -x, -y, -z (upside down)")
      ->check(CLI::IsMember(axes))
      ->capture_default_str();
  const ParameterTable<RenderOptions>& t = render_parameters();
  add_number_option(c, "--azimuth", *find_parameter(t, "azimuth"), v.angles,
                    "Turn the camera about the up axis from the view, counter-clockwise seen from above");
  add_number_option(c, "--elevation", *find_parameter(t, "elevation"), v.angles,
                    "Raise the camera towards the up axis from the view (negative: lower it)");
  c->add_flag("--perspective", v.perspective, "Perspective camera (default orthographic)");
}

/// Sets the view, up axis, camera angles and projection of `o`.
inline void apply_view(const ViewArgs& v, RenderOptions& o) {
  o.view = view_from_name(v.view);
  o.up = up_axis_from_name(v.up);
  o.azimuth_deg = v.angles.azimuth_deg;
  o.elevation_deg = v.angles.elevation_deg;
  o.projection = v.perspective ? Projection::Perspective : Projection::Orthographic;
}

/// "iso, up y" plus the camera angles when set: the view as the summaries print it.
inline std::string describe_view(const ViewArgs& v) {
  const ParameterInfo& degrees = find_parameter(render_parameters(), "azimuth")->info;
  std::string s = v.view;
  if (v.up != "y" && v.up != "+y") s += ", up " + v.up;
  if (v.angles.azimuth_deg != 0) s += ", azimuth " + degrees.format(v.angles.azimuth_deg);
  if (v.angles.elevation_deg != 0) s += ", elevation " + degrees.format(v.angles.elevation_deg);
  if (v.perspective) s += ", perspective";
  return s;
}

}  // namespace msmesh::cli
