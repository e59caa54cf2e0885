// msmesh compare: several meshes from the same view side by side, with captions and (with a
// ground truth) their error figures under each panel, like Fig. 11 of the paper. The sheet
// itself is drawn by the drawing library (msmesh/compare_sheet.h), as for msmesh.compare().
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "command.h"
#include "figures.h"
#include "msmesh/color_bar.h"
#include "msmesh/compare_sheet.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "msmesh/render.h"
#include "number_option.h"
#include "output_plan.h"
#include "usage_error.h"
#include "view_options.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::vector<std::string> inputs;
  std::string output, truth, captions, color = "auto", title, noisy = "auto";
  std::string size = std::to_string(kComparePanelSize) + "x" + std::to_string(kComparePanelSize);
  ViewArgs view;
  bool quiet = false;
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

/// --noisy-panel: auto, none, or a panel number from 1.
int noisy_panel(const std::string& text, size_t panels) {
  if (text == "auto") return kNoisyPanelAuto;
  if (text == "none") return kNoNoisyPanel;
  const ParameterInfo info{"noisy-panel", "", "", ParameterType::Integer, {1, double(panels)}, "", "compare"};
  try {
    return static_cast<int>(parse_parameter(info, text, "--noisy-panel")) - 1;
  } catch (const InvalidInput& e) {
    throw UsageError(std::string(e.what()) + " (or auto, none)");
  }
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

  CompareOptions co;
  std::tie(co.render.width, co.render.height) = parse_size(a.size);
  apply_view(a.view, co.render);
  co.render.supersample = a.supersample;
  co.color = sheet_color_from_name(a.color);
  co.feature_angle = a.feature_angle;
  co.error_max = a.error_max;
  co.noisy_panel = noisy_panel(a.noisy, n);
  co.title = a.title;
  co.validate();

  OutputPlan plan;  // every file of the run, checked before any work; outputs committed together
  for (const std::string& p : a.inputs) plan.input(p);
  plan.input(a.truth, "--truth").output(a.output, OutputKind::Png, "-o");
  plan.begin();
  std::vector<ComparePanel> panels;
  for (size_t i = 0; i < n; ++i) {
    Mesh m = read_mesh(a.inputs[i]);
    panels.push_back({std::move(m.V), std::move(m.F), std::move(m.vertex_colors), captions[i]});
  }
  Mesh truth;
  if (!a.truth.empty()) truth = read_mesh(a.truth);
  CompareSheet sheet;
  try {
    sheet = compare_sheet(panels, truth.V, truth.F, co);
  } catch (const InvalidInput& e) {
    // Name the file rather than the panel number.
    std::string what = e.what();
    for (size_t i = 0; i < n; ++i) {
      const std::string panel = "panel " + std::to_string(i) + " (" + captions[i] + ")";
      const size_t at = what.find(panel);
      if (at != std::string::npos) what.replace(at, panel.size(), "'" + a.inputs[i] + "'");
    }
    throw InvalidInput(what);
  }
  write_png(a.output, sheet.image);
  plan.commit();

  if (!a.quiet) {
    std::cout << "compared " << n << " meshes -> " << a.output << " (" << sheet.image.width << "x" << sheet.image.height
              << ", view " << describe_view(a.view) << ")\n";
    if (!a.truth.empty())
      for (size_t i = 0; i < n; ++i) {
        const Evaluation& e = sheet.evaluations[i];
        std::cout << "  " << captions[i] << ": ";
        if (e.same_connectivity)
          std::cout << "MSAE " << fmt(e.normals.msae * 1e3) << " e-3, mean angle " << fmt(e.normals.mean_angle_deg)
                    << " deg, flipped " << e.normals.flipped
                    << (static_cast<int>(i) == sheet.noisy_panel ? " (the noisy input)" : "") << "\n";
        else
          std::cout << "distance RMS " << fmt(e.distances.rms * 1e3) << " e-3 (faces differ from the truth)\n";
      }
    if (co.color == SheetColor::Error)
      std::cout << "  error colours 0-" << format_tick(sheet.error_top) << " deg: " << sheet.scale_note << "\n";
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
  c->add_option("--color", a->color,
                "auto (the files' vertex colours where present, else grey), none (grey), file (vertex colours), "
                "error (angle to --truth per face, one shared scale)")
      ->check(CLI::IsMember(sheet_color_names()))
      ->capture_default_str();
  c->add_option("--noisy-panel", a->noisy,
                "The panel (1 = first) holding the noisy input, left out of the automatic error scale so that the "
                "results are not washed out (its larger errors saturate); auto: the panel whose mean error is at "
                "least twice every other's; none")
      ->capture_default_str();
  add_view_options(c, a->view);
  add_size_option(c, a->size, "Size WxH of each panel in pixels");
  c->add_option("--title", a->title, "A title line above the panels");
  add_feature_edges_option(c, a->feature_angle, "Draw edges sharper than this angle dark (0: off)");
  add_error_max_option(c, a->error_max, "Top of the error colour scale (0: from the results, see --noisy-panel)");
  add_supersample_option(c, a->supersample);
  add_quiet_flag(c, a->quiet);
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
