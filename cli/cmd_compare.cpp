// msmesh compare: several meshes from the same view side by side, with captions and (with a
// ground truth) their error figures under each panel, like Fig. 11 of the paper.
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "command.h"
#include "field_files.h"
#include "figures.h"
#include "msmesh/color_bar.h"
#include "msmesh/errors.h"
#include "msmesh/image.h"
#include "msmesh/io.h"
#include "msmesh/metrics.h"
#include "msmesh/render.h"
#include "msmesh/text.h"
#include "output_plan.h"
#include "run_reports.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::vector<std::string> inputs;
  std::string output, truth, captions, color = "none", view = "iso", size = "400x400", title;
  bool perspective = false, quiet = false;
  double feature_angle = 0, error_max = 0;
  int supersample = 2;
};

std::vector<std::string> split_captions(const std::string& s) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream is(s);
  while (std::getline(is, item, ',')) out.push_back(item);
  if (!s.empty() && s.back() == ',') out.push_back("");
  return out;
}

/// Text centred in a white strip of the given width.
void centered(Image& img, int y, const std::string& text, int scale, const Eigen::Vector3d& ink) {
  draw_text(img, (img.width - text_width(text, scale)) / 2, y, text, ink, scale);
}

void run(const Args& a) {
  const size_t n = a.inputs.size();
  std::vector<std::string> captions = split_captions(a.captions);
  if (!a.captions.empty() && captions.size() != n)
    throw InvalidInput("compare: --captions has " + std::to_string(captions.size()) + " entries for " +
                       std::to_string(n) + " meshes");
  if (a.captions.empty())
    for (const auto& p : a.inputs) captions.push_back(std::filesystem::path(p).stem().string());
  if (a.color == "error" && a.truth.empty()) throw InvalidInput("compare: --color error needs --truth GT");

  RenderOptions ro;
  std::tie(ro.width, ro.height) = parse_size(a.size);
  ro.view = view_from_name(a.view);
  ro.projection = a.perspective ? Projection::Perspective : Projection::Orthographic;
  ro.supersample = a.supersample;
  ro.validate();

  OutputPlan plan;  // every file of the run, checked before any work; outputs committed together
  for (const std::string& p : a.inputs) plan.input(p);
  plan.input(a.truth, "--truth").output(a.output, OutputKind::Png, "-o");
  plan.begin();
  std::vector<Mesh> meshes;
  for (const auto& p : a.inputs) meshes.push_back(read_mesh(p));
  Mesh truth;
  if (!a.truth.empty()) truth = read_mesh(a.truth);

  // One framing for all panels (all their vertices), so that they show the same view at the
  // same scale. (Unreferenced vertices count too; meshes rarely have far-away ones.)
  Eigen::Index total = 0;
  for (const Mesh& m : meshes) total += m.V.rows();
  ro.frame_points.resize(total, 3);
  total = 0;
  for (const Mesh& m : meshes) {
    ro.frame_points.middleRows(total, m.V.rows()) = m.V;
    total += m.V.rows();
  }

  // Error figures and per-face angles.
  std::vector<Evaluation> ev(n);
  std::vector<Eigen::VectorXd> angles(n);
  Eigen::VectorXd all_angles;
  if (!a.truth.empty()) {
    std::vector<double> pooled;
    for (size_t i = 0; i < n; ++i) {
      ev[i] = evaluate(meshes[i].V, meshes[i].F, truth.V, truth.F);
      if (ev[i].same_connectivity) {
        angles[i] = ev[i].normals.angle_rad * (180.0 / M_PI);
        pooled.insert(pooled.end(), angles[i].data(), angles[i].data() + angles[i].size());
      }
    }
    all_angles = Eigen::Map<Eigen::VectorXd>(pooled.data(), static_cast<Eigen::Index>(pooled.size()));
  }
  const double error_top = a.error_max > 0 ? a.error_max : error_scale(all_angles);

  const int scale = ro.width >= 300 ? 2 : 1;
  const Eigen::Vector3d ink(0.1, 0.1, 0.1), muted(0.35, 0.35, 0.4);
  std::vector<Image> panels;
  Coloring bar_coloring;
  for (size_t i = 0; i < n; ++i) {
    const Mesh& m = meshes[i];
    Coloring c;
    if (a.color == "error") {
      if (!ev[i].same_connectivity)
        throw InvalidInput("compare: --color error needs every mesh to have the faces of the truth; '" + a.inputs[i] +
                           "' does not");
      c = error_coloring(angles[i], error_top);
      bar_coloring = c;
      bar_coloring.bar.max_is_clamped = all_angles.size() && all_angles.maxCoeff() > error_top;
    }
    if (a.feature_angle > 0) {
      c.style.lines = sharp_edges(m.V, m.F, a.feature_angle);
      c.style.line_colors = Eigen::RowVector3d(0.1, 0.1, 0.1);
    }
    const Image picture = render_mesh(m.V, m.F, c.style, ro);
    const int lines = a.truth.empty() ? 1 : 2;
    Image label(ro.width, lines * (text_height(scale) + 4 * scale) + 6 * scale);
    centered(label, 2 * scale, captions[i], scale, ink);
    if (!a.truth.empty()) {
      std::string fig;
      if (ev[i].same_connectivity)
        fig = "MSAE " + format_tick(ev[i].normals.msae * 1e3) +
              " \xC3\x97"
              "1e-3, " +
              format_tick(ev[i].normals.mean_angle_deg) + "\xC2\xB0 mean";
      else
        fig = "RMS dist. " + format_tick(ev[i].distances.rms * 1e3) +
              " \xC3\x97"
              "1e-3";
      const int s2 = text_width(fig, scale) <= ro.width - 8 ? scale : 1;
      centered(label, 2 * scale + text_height(scale) + 4 * scale, fig, s2, muted);
    }
    panels.push_back(vstack({picture, label}));
  }
  Image sheet = hstack(panels, 8 * scale);
  if (!a.title.empty()) {
    Image head(sheet.width, text_height(scale) + 12 * scale);
    centered(head, 6 * scale, a.title, scale, ink);
    sheet = vstack({head, sheet});
  }
  if (a.color == "error") sheet = add_color_bar(sheet, bar_coloring);
  // A thin margin all round.
  Image framed(sheet.width + 16, sheet.height + 12);
  blit(framed, sheet, 8, 6);
  write_png(a.output, framed);
  plan.commit();

  if (!a.quiet) {
    std::cout << "compared " << n << " meshes -> " << a.output << " (" << framed.width << "x" << framed.height
              << ", view " << a.view << ")\n";
    if (!a.truth.empty())
      for (size_t i = 0; i < n; ++i) {
        std::cout << "  " << captions[i] << ": ";
        if (ev[i].same_connectivity)
          std::cout << "MSAE " << fmt(ev[i].normals.msae * 1e3) << " e-3, mean angle "
                    << fmt(ev[i].normals.mean_angle_deg) << " deg, flipped " << ev[i].normals.flipped << "\n";
        else
          std::cout << "distance RMS " << fmt(ev[i].distances.rms * 1e3) << " e-3 (faces differ from the truth)\n";
      }
  }
}

const Registrar kRegistration("compare", 95, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c =
      app.add_subcommand("compare", "Render several meshes side by side into one PNG sheet (with error figures)");
  c->add_option("inputs", a->inputs, "Meshes to show, left to right")->required();
  c->add_option("-o,--output", a->output, "Output .png (- for standard output)")->required();
  c->add_option("--truth", a->truth, "Ground truth: print MSAE (x1e-3) and mean angle under each panel");
  c->add_option("--captions", a->captions, "Comma-separated captions, one per mesh (default: file names)");
  c->add_option("--color", a->color, "none (grey) or error (angle to --truth per face, one shared scale)")
      ->check(CLI::IsMember({"none", "error"}))
      ->capture_default_str();
  c->add_option("--view", a->view, "iso, front, back, left, right, top or bottom (+y is up)")
      ->check(CLI::IsMember(view_names()))
      ->capture_default_str();
  add_size_option(c, a->size, "Size WxH of each panel in pixels");
  c->add_option("--title", a->title, "A title line above the panels");
  c->add_flag("--perspective", a->perspective, "Perspective camera (default orthographic)");
  add_feature_edges_option(c, a->feature_angle, "Draw edges sharper than this angle dark (0: off)");
  add_error_max_option(c, a->error_max, "Top of the error colour scale (0: automatic)");
  add_supersample_option(c, a->supersample);
  add_quiet_flag(c, a->quiet);
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
