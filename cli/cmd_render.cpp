// msmesh render: one mesh to a PNG picture (software rasteriser of msmesh/render.h, draw/).
#include <iostream>
#include <memory>

#include "command.h"
#include "field_files.h"
#include "figures.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "msmesh/metrics.h"
#include "msmesh/render.h"
#include "number_option.h"
#include "output_plan.h"
#include "view_options.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::string input, output, color = "auto", truth, field, labels, size = "800x600";
  ViewArgs view;
  bool quiet = false;
  double feature_angle = 0, error_max = 0, line_width = 0;
  int supersample = 2;
};

void run(const Args& a) {
  RenderOptions ro;
  std::tie(ro.width, ro.height) = parse_size(a.size);
  apply_view(a.view, ro);
  ro.supersample = a.supersample;
  // Field and label lines carry the information: thicker than feature edges by default.
  ro.line_width = a.line_width > 0 ? a.line_width : (a.color == "field" || a.color == "labels" ? 2.5 : 1.5);
  ro.validate();
  if (a.color == "error" && a.truth.empty()) throw InvalidInput("render: --color error needs --truth GT");
  if (a.color == "field" && a.field.empty())
    throw InvalidInput("render: --color field needs --field FILE (from denoise --save-field)");
  if (a.color == "labels" && a.labels.empty())
    throw InvalidInput("render: --color labels needs --labels FILE (from segment --labels)");
  OutputPlan plan;  // every file of the run, checked before any work; outputs committed together
  plan.input(a.input).input(a.truth, "--truth").input(a.field, "--field").input(a.labels, "--labels");
  plan.output(a.output, OutputKind::Png, "-o");
  plan.begin();
  const Mesh mesh = read_mesh(a.input);

  // auto: the file's own colours when it has them, else grey.
  std::string color = a.color;
  if (color == "auto") color = mesh.vertex_colors.size() ? "file" : "none";
  Coloring c;
  if (color == "file") {
    if (mesh.vertex_colors.size() == 0)
      throw InvalidInput("render: --color file: '" + a.input + "' has no vertex colours");
    c = vertex_coloring(mesh.vertex_colors, mesh.V.rows());
  } else if (a.color == "error") {
    const Mesh truth = read_mesh(a.truth);
    const NormalErrors e = normal_errors(mesh.V, mesh.F, truth.V, truth.F);
    c = error_coloring(e.angle_rad * (180.0 / M_PI), a.error_max);
  } else if (a.color == "field") {
    c = field_coloring(mesh.F, mesh.V.rows(), read_edge_field(a.field, build_topology(mesh.F, mesh.V.rows())));
  } else if (a.color == "labels") {
    c = label_coloring(mesh.F, mesh.V.rows(), read_face_labels(a.labels, mesh.F.rows()));
  }
  if (a.feature_angle > 0 && c.style.lines.rows() == 0) {
    c.style.lines = sharp_edges(mesh.V, mesh.F, a.feature_angle);
    c.style.line_colors = Eigen::RowVector3d(0.1, 0.1, 0.1);
  }
  const Image image = add_color_bar(render_mesh(mesh.V, mesh.F, c.style, ro), c);
  write_png(a.output, image);
  plan.commit();
  if (!a.quiet) {
    std::cout << "rendered " << a.input << " -> " << a.output << " (" << image.width << "x" << image.height << ", view "
              << describe_view(a.view) << ", colour " << color;
    if (!c.summary.empty()) std::cout << ": " << c.summary;
    std::cout << ")\n";
  }
}

const Registrar kRegistration("render", 90, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c = app.add_subcommand("render", "Render a mesh to a PNG picture (flat shading, colour maps)");
  c->add_option("input", a->input, "Mesh to render (obj, off, ply, stl)")->required();
  c->add_option("-o,--output", a->output, "Output .png (- for standard output)")->required();
  c->add_option("--color", a->color,
                "auto (the file's vertex colours when it has them, else none), none (grey), file (the file's vertex "
                "colours), field (edge field v as coloured edges, --field), error (angle to --truth per face), "
                "labels (one colour per segment, --labels)")
      ->check(CLI::IsMember({"auto", "none", "file", "field", "error", "labels"}))
      ->capture_default_str();
  c->add_option("--truth", a->truth, "Ground truth (same faces) for --color error");
  c->add_option("--field", a->field, "Edge field from denoise --save-field (.txt 'i j v' or .ply) for --color field");
  c->add_option("--labels", a->labels, "One label per face (segment --labels) for --color labels");
  add_view_options(c, a->view);
  add_size_option(c, a->size, "Picture size WxH in pixels (a colour bar adds a strip below)");
  add_feature_edges_option(c, a->feature_angle,
                           "Draw edges sharper than this dihedral angle as thin dark lines (0: off)");
  add_error_max_option(c, a->error_max, "Top of the error colour scale (0: 98th percentile, rounded up)");
  using T = ParameterType;
  add_number_option(c, "--line-width", a->line_width, cli_number("render", "line-width", T::Real, {0, 20}, "pixels"),
                    "Width of edge lines (0: 2.5 for field and labels, else 1.5)");
  add_supersample_option(c, a->supersample);
  add_quiet_flag(c, a->quiet);
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
