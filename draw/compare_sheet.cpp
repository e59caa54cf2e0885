// Comparison sheets (compare_sheet.h): panels, captions, error figures and one colour bar.
#include "msmesh/compare_sheet.h"

#include <algorithm>
#include <cmath>

#include "msmesh/color_bar.h"
#include "msmesh/errors.h"
#include "msmesh/mesh.h"
#include "msmesh/mesh_coloring.h"
#include "msmesh/parameters.h"
#include "msmesh/text.h"

namespace msmesh {

std::vector<std::string> sheet_color_names() { return {"auto", "none", "file", "error"}; }

SheetColor sheet_color_from_name(const std::string& name) {
  static const SheetColor colors[] = {SheetColor::Auto, SheetColor::None, SheetColor::File, SheetColor::Error};
  const std::vector<std::string> names = sheet_color_names();
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return colors[i];
  throw InvalidInput("unknown sheet colouring '" + name + "'; valid: auto, none, file, error");
}

void CompareOptions::validate() const {
  render.validate();
  check_parameter("compare", "feature_angle", feature_angle, {0, 180, false, true});
  check_parameter("compare", "error_max", error_max, {0, 180});
  if (noisy_panel < kNoNoisyPanel)
    throw InvalidInput("compare: noisy_panel = " + std::to_string(noisy_panel) +
                       " is out of range; valid: a panel index, kNoisyPanelAuto or kNoNoisyPanel");
}

double sheet_error_scale(const std::vector<Eigen::VectorXd>& angle_deg, int noisy_panel, double error_max) {
  if (error_max > 0) return error_max;
  auto pool = [&](bool leave_out) {
    std::vector<double> all;
    for (size_t i = 0; i < angle_deg.size(); ++i) {
      const Eigen::VectorXd& a = angle_deg[i];
      if (leave_out && (static_cast<int>(i) == noisy_panel || a.size() == 0 || a.maxCoeff() <= 0)) continue;
      all.insert(all.end(), a.data(), a.data() + a.size());
    }
    return all;
  };
  std::vector<double> all = pool(true);
  if (all.empty()) all = pool(false);
  return error_scale(Eigen::Map<Eigen::VectorXd>(all.data(), static_cast<Eigen::Index>(all.size())));
}

int auto_noisy_panel(const std::vector<double>& mean_angle_deg) {
  if (mean_angle_deg.size() < 2) return -1;
  const auto top = std::max_element(mean_angle_deg.begin(), mean_angle_deg.end());
  if (!(*top > 0)) return -1;
  for (auto it = mean_angle_deg.begin(); it != mean_angle_deg.end(); ++it)
    if (it != top && !(2 * *it <= *top)) return -1;
  return static_cast<int>(top - mean_angle_deg.begin());
}

namespace {

/// Text centred in a white strip of the given width.
void centered(Image& img, int y, const std::string& text, int scale, const Eigen::Vector3d& ink) {
  draw_text(img, (img.width - text_width(text, scale)) / 2, y, text, ink, scale);
}

/// Text at `scale`, or at 1 when it does not fit into `width`.
int fitting_scale(const std::string& text, int scale, int width) {
  return text_width(text, scale) <= width - 8 ? scale : 1;
}

}  // namespace

CompareSheet compare_sheet(const std::vector<ComparePanel>& panels, const Eigen::MatrixXd& V_truth,
                           const Eigen::MatrixXi& F_truth, const CompareOptions& o) {
  o.validate();
  const size_t n = panels.size();
  if (n == 0) throw InvalidInput("compare: no meshes to show");
  if (o.noisy_panel >= static_cast<int>(n))
    throw InvalidInput("compare: noisy_panel = " + std::to_string(o.noisy_panel) + " but there are " +
                       std::to_string(n) + " panels");
  for (size_t i = 0; i < n; ++i) {
    validate_mesh(panels[i].V, panels[i].F, "compare: panel " + std::to_string(i));
    if (panels[i].vertex_colors.size()) vertex_coloring(panels[i].vertex_colors, panels[i].V.rows());
  }
  const bool has_truth = V_truth.size() > 0 || F_truth.size() > 0;
  if (has_truth) validate_mesh(V_truth, F_truth, "compare: truth");
  if (o.color == SheetColor::Error && !has_truth) throw InvalidInput("compare: error colours need a ground truth");

  RenderOptions ro = o.render;
  if (ro.frame_points.rows() == 0) {
    // One framing for all panels (all their vertices), so that they show the same view at
    // the same scale. (Unreferenced vertices count too; meshes rarely have far-away ones.)
    Eigen::Index total = 0;
    for (const ComparePanel& p : panels) total += p.V.rows();
    ro.frame_points.resize(total, 3);
    total = 0;
    for (const ComparePanel& p : panels) {
      ro.frame_points.middleRows(total, p.V.rows()) = p.V;
      total += p.V.rows();
    }
  }

  CompareSheet sheet;
  std::vector<Eigen::VectorXd> angles(n);
  if (has_truth) {
    sheet.evaluations.resize(n);
    std::vector<double> means(n, -1);
    for (size_t i = 0; i < n; ++i) {
      sheet.evaluations[i] = evaluate(panels[i].V, panels[i].F, V_truth, F_truth);
      if (sheet.evaluations[i].same_connectivity) {
        angles[i] = sheet.evaluations[i].normals.angle_rad * (180.0 / M_PI);
        means[i] = sheet.evaluations[i].normals.mean_angle_deg;
      } else if (o.color == SheetColor::Error) {
        throw InvalidInput("compare: error colours need every mesh to have the faces of the truth; panel " +
                           std::to_string(i) + " (" + panels[i].caption + ") does not");
      }
    }
    sheet.noisy_panel = o.noisy_panel == kNoisyPanelAuto ? auto_noisy_panel(means)
                        : o.noisy_panel == kNoNoisyPanel ? -1
                                                         : o.noisy_panel;
  }
  const bool error_colors = o.color == SheetColor::Error;
  Coloring bar;
  if (error_colors) {
    sheet.error_top = sheet_error_scale(angles, sheet.noisy_panel, o.error_max);
    for (const Eigen::VectorXd& a : angles)
      if (a.size() && a.maxCoeff() > sheet.error_top) sheet.saturated = true;
    const bool noisy_saturates = sheet.noisy_panel >= 0 && angles[sheet.noisy_panel].size() &&
                                 angles[sheet.noisy_panel].maxCoeff() > sheet.error_top;
    if (o.error_max > 0)
      sheet.scale_note = "scale set by hand";
    else if (sheet.noisy_panel >= 0)
      sheet.scale_note = noisy_saturates ? "scale from the results; the noisy input saturates"
                                         : "scale from the results (the noisy input left out)";
    else
      sheet.scale_note = "scale from all panels with errors";
  }

  const int scale = ro.width >= 300 ? 2 : 1;
  const Eigen::Vector3d ink(0.1, 0.1, 0.1), muted(0.35, 0.35, 0.4);
  const int line_height = text_height(scale) + 4 * scale;
  const int lines = 1 + (has_truth ? 1 : 0) + (error_colors && sheet.noisy_panel >= 0 ? 1 : 0);
  std::vector<Image> images;
  for (size_t i = 0; i < n; ++i) {
    const ComparePanel& p = panels[i];
    Coloring c;
    if (error_colors) {
      c = error_coloring(angles[i], sheet.error_top);
      bar = c;
    } else if (p.vertex_colors.size() && (o.color == SheetColor::File || o.color == SheetColor::Auto)) {
      c = vertex_coloring(p.vertex_colors, p.V.rows());
    }
    if (o.feature_angle > 0) {
      c.style.lines = sharp_edges(p.V, p.F, o.feature_angle);
      c.style.line_colors = Eigen::RowVector3d(0.1, 0.1, 0.1);
    }
    const Image picture = render_mesh(p.V, p.F, c.style, ro);
    Image label(ro.width, lines * line_height + 6 * scale);
    centered(label, 2 * scale, p.caption, fitting_scale(p.caption, scale, ro.width), ink);
    int y = 2 * scale + line_height;
    if (has_truth) {
      const Evaluation& e = sheet.evaluations[i];
      const std::string fig = e.same_connectivity ? "MSAE " + format_tick(e.normals.msae * 1e3) +
                                                        " \xC3\x97"
                                                        "1e-3, " +
                                                        format_tick(e.normals.mean_angle_deg) + "\xC2\xB0 mean"
                                                  : "RMS dist. " + format_tick(e.distances.rms * 1e3) +
                                                        " \xC3\x97"
                                                        "1e-3";
      centered(label, y, fig, fitting_scale(fig, scale, ro.width), muted);
      y += line_height;
    }
    if (error_colors && static_cast<int>(i) == sheet.noisy_panel) {
      const std::string note = angles[i].size() && angles[i].maxCoeff() > sheet.error_top
                                   ? "noisy input: saturates above " + format_tick(sheet.error_top) + "\xC2\xB0"
                                   : "noisy input: left out of the scale";
      centered(label, y, note, fitting_scale(note, scale, ro.width), muted);
    }
    images.push_back(vstack({picture, label}));
  }
  Image body = hstack(images, 8 * scale);
  if (!o.title.empty()) {
    Image head(body.width, text_height(scale) + 12 * scale);
    centered(head, 6 * scale, o.title, scale, ink);
    body = vstack({head, body});
  }
  if (error_colors) {
    bar.bar.max_is_clamped = sheet.saturated;
    body = add_color_bar(body, bar);
    // The legend's words on the scale, under the bar (at the bar's text size).
    const int bar_scale = body.width >= 700 ? 2 : 1;
    Image note(body.width, text_height(bar_scale) + 6 * bar_scale);
    centered(note, 0, sheet.scale_note, fitting_scale(sheet.scale_note, bar_scale, body.width), muted);
    body = vstack({body, note});
  }
  // A thin margin all round.
  sheet.image = Image(body.width + 16, body.height + 12);
  blit(sheet.image, body, 8, 6);
  return sheet;
}

}  // namespace msmesh
