// msmesh features: feature lines (chains of edges where the NMSTV edge field v is low).
#include <chrono>
#include <iostream>

#include "command.h"
#include "json.h"
#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "msmesh/normal_filter.h"
#include "msmesh/presets.h"
#include "msmesh/segment.h"
#include "number_option.h"
#include "output_plan.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::string input, output, preset = "cad";
  double threshold = 0.5;
  int min_edges = 1;
  bool denoise_first = false, json = false, quiet = false, in_place = false;
};

void run(const Args& a) {
  OutputPlan plan;  // every file of the run, checked before any work; outputs committed together
  plan.input(a.input).in_place(a.in_place).output(a.output, OutputKind::Polylines, "-o");
  plan.begin();
  const auto t0 = std::chrono::steady_clock::now();
  Mesh mesh = read_mesh(a.input);
  const DenoiseOptions preset = preset_options(a.preset);
  const ProgressCallback progress = make_progress_bar(a.quiet || a.json);
  if (a.denoise_first) {
    mesh.V = denoise(mesh.V, mesh.F, preset, progress).V;
    finish_progress_line();
  }
  const NormalFilterResult nf = filter_normals(mesh.V, mesh.F, preset.normals, {}, progress);
  finish_progress_line();
  const auto lines = feature_lines(mesh.V, mesh.F, nf.v, a.threshold, a.min_edges);
  write_polylines(a.output, mesh.V, lines);
  plan.commit();
  long long edges = 0, closed = 0;
  double length = 0;
  for (const auto& l : lines) {
    edges += static_cast<long long>(l.size()) - 1;
    if (l.size() > 2 && l.front() == l.back()) ++closed;
    for (size_t k = 0; k + 1 < l.size(); ++k) length += (mesh.V.row(l[k + 1]) - mesh.V.row(l[k])).norm();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (a.json) {
    Json j;
    j.add("input", a.input).add("output", a.output).add("preset", a.preset).add("denoised", a.denoise_first);
    j.add("threshold", a.threshold).add("min_edges", a.min_edges);
    j.add("polylines", static_cast<long long>(lines.size()))
        .add("closed_loops", closed)
        .add("edges", edges)
        .add("length", length)
        .add("seconds", seconds);
    std::cout << j.str() << "\n";
    return;
  }
  if (a.quiet) return;
  std::cout << "feature lines of " << a.input << " -> " << a.output << (a.denoise_first ? " (denoised first)" : "")
            << "\n";
  std::cout << "  " << lines.size() << " polylines (" << closed << " closed), " << edges << " edges, length "
            << fmt(length) << ", threshold " << fmt(a.threshold) << " on normalised v, " << fmt(seconds, 3) << " s\n";
}

const Registrar kRegistration("features", 75, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c = app.add_subcommand("features", "Extract feature lines where the NMSTV edge field is low");
  c->add_option("input", a->input, "Input mesh (obj, off, ply, stl, gltf, glb; also .gz)")->required();
  c->add_option("-o,--output", a->output, "Output polylines: .obj (v/l records) or .ply (edges)")->required();
  using T = ParameterType;
  add_number_option(c, "--threshold", a->threshold, cli_number("features", "threshold", T::Real, {0, 1, true, false}),
                    "Edges with normalised v below this are features");
  add_number_option(c, "--min-edges", a->min_edges, cli_number("features", "min-edges", T::Integer, {1, 2147483647}),
                    "Drop polylines with fewer edges than this");
  c->add_flag("--denoise", a->denoise_first, "Denoise first (same preset), then extract the lines");
  c->add_option("--preset", a->preset, "Normal filter parameters: cad (sharp features) or smooth (organic)")
      ->check(CLI::IsMember({"cad", "smooth"}))
      ->capture_default_str();
  c->add_flag("--json", a->json, "Print one JSON object instead of the summary");
  add_quiet_flag(c, a->quiet);
  c->add_flag("--in-place", a->in_place, "Allow the output to overwrite the input file");
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
