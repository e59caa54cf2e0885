// msmesh denoise: NMSTV normal filtering + vertex updating (or the MSTV / bilateral baselines).
#include <chrono>
#include <iostream>
#include <memory>

#include "command.h"
#include "data_notes.h"
#include "field_files.h"
#include "figures.h"
#include "heap_prefault.h"
#include "json.h"
#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/io.h"
#include "msmesh/memory.h"
#include "msmesh/metrics.h"
#include "msmesh/parameters.h"
#include "msmesh/presets.h"
#include "msmesh/repair.h"
#include "msmesh/second_round.h"
#include "msmesh/threads.h"
#include "msmesh/topology.h"
#include "number_option.h"
#include "output_plan.h"
#include "parameter_options.h"
#include "run_reports.h"
#include "usage_error.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::string input, output, truth, field, preset = default_preset(), method = "nmstv", solver = "auto";
  bool json = false, quiet = false, in_place = false, ascii = false, repair = false;
  double strength = 1.0;                                         // --strength (presets.h resolve_preset)
  std::string report;                                            // --report: HTML report (cli/run_reports.h)
  std::unique_ptr<ParameterOptions<DenoiseOptions>> parameters;  // --alpha ... (parameters.h)
};

DenoiseMethod parse_method(const std::string& m) {
  if (m == "nmstv") return DenoiseMethod::NMSTV;
  if (m == "mstv") return DenoiseMethod::MSTV;
  if (m == "bilateral") return DenoiseMethod::Bilateral;
  throw UsageError("unknown method '" + m + "'; valid: nmstv, mstv, bilateral");
}

void run(const Args& a) {
  // Every option and combination is checked before any work.
  const DenoiseMethod method = parse_method(a.method);
  a.parameters->check();
  if (!a.field.empty() && method == DenoiseMethod::Bilateral)
    throw UsageError("--save-field needs --method nmstv or mstv (bilateral has no edge field)");
  if (a.strength != 1.0 && method == DenoiseMethod::Bilateral)
    throw UsageError("--strength needs --method nmstv or mstv (the bilateral baseline has its own parameters)");
  OutputPlan plan;  // every file of the run, checked before any work; outputs committed together
  plan.input(a.input).input(a.truth, "--truth").in_place(a.in_place);
  plan.output(a.output, OutputKind::Mesh, "-o")
      .output(a.field, OutputKind::Text, "--save-field")
      .output(a.report, OutputKind::Text, "--report");
  plan.begin();
  const auto t_read0 = std::chrono::steady_clock::now();
  ReadNotes notes;
  Mesh mesh = read_mesh(a.input, notes);
  std::vector<std::string> repairs;       // --repair: what repair_mesh did (vertex order kept)
  std::vector<std::string> repair_notes;  // and what it did to the attributes
  if (a.repair) {
    const RepairReport rr = repair_mesh(mesh);
    repairs = rr.actions();
    repair_notes = rr.attribute_notes;
    if (mesh.F.rows() == 0) throw InvalidInput(a.input + ": --repair removed every face (all are degenerate)");
  }
  const double t_read = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_read0).count();

  // The memory a run needs depends on the method only (denoise_memory_estimate): checked before
  // any work, then a share of it faulted in at once (heap_prefault.h).
  DenoiseOptions sized;
  sized.method = method;
  const double memory = denoise_memory_estimate(mesh.V.rows(), mesh.F.rows(), sized);
  check_memory(memory, a.input + ": denoising " + std::to_string(mesh.V.rows()) + " vertices and " +
                           std::to_string(mesh.F.rows()) + " faces");
  prefault_heap(kPrefaultShare * memory);

  // The bilateral baseline has its own parameters; the preset is unused (and not chosen).
  const ResolvedPreset preset =
      resolve_preset(method == DenoiseMethod::Bilateral && a.preset == "auto" ? "cad" : a.preset, mesh.V, mesh.F,
                     method == DenoiseMethod::Bilateral ? 1.0 : a.strength);
  // The user's method, overrides and solver, on the preset's options (and on a second round's).
  const AdjustOptions adjust = [&](DenoiseOptions& o) {
    o.method = method;
    a.parameters->apply(o);
    o.normals.solver = o.vertices.solver = a.solver == "cholesky" ? LinearSolver::Cholesky
                                           : a.solver == "cg"     ? LinearSolver::CG
                                                                  : LinearSolver::Auto;
    o.validate();
  };
  DenoiseOptions o = preset.options;
  adjust(o);

  Mesh truth;
  if (!a.truth.empty()) truth = read_mesh(a.truth);

  SecondRound second;
  const DenoiseResult r =
      denoise_in_rounds(mesh.V, mesh.F, preset, o, adjust, make_progress_bar(a.quiet || a.json), &second);
  finish_progress_line();
  Mesh out = mesh;  // same faces, order and every attribute; normals recomputed for the result
  out.V = r.V;
  if (mesh.vertex_normals.size() > 0) out.vertex_normals = vertex_normals(out.V, out.F);
  const auto t_w0 = std::chrono::steady_clock::now();
  WriteOptions wo;
  wo.binary = !a.ascii;
  write_mesh(a.output, out, wo);
  const std::vector<std::string> notes_out = data_notes(a.input, notes, repair_notes, out, a.output);
  if (!a.field.empty()) {
    write_edge_field(a.field, r.V, r.edges, r.v);
  }
  const double t_write = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_w0).count();

  Evaluation ev_in, ev_out;
  if (!a.truth.empty()) {
    ev_in = evaluate(mesh.V, mesh.F, truth.V, truth.F);
    ev_out = evaluate(out.V, out.F, truth.V, truth.F);
  }
  // What the second round ran (auto under heavy noise), for the summary and the report.
  const std::string second_text = second.weight > 0
                                      ? "weight " + fmt(second.weight, 2) + ", auto on the result: preset " +
                                            second.preset.preset + ", " + second.preset.reason()
                                      : "";
  if (!a.report.empty())
    write_denoise_report(a.report, a.input, mesh, out.V, a.truth.empty() ? nullptr : &truth, a.method,
                         preset.preset + (preset.automatic ? ", " + preset.reason() : "") +
                             (second.weight > 0 ? "; second round " + second_text : ""),
                         o, r, ev_in, ev_out);
  plan.commit();

  if (a.json) {
    Json j;
    j.add("input", a.input).add("output", a.output).add("preset", preset.preset).add("method", a.method);
    j.add("preset_requested", preset.requested).add("preset_reason", preset.reason());
    if (preset.automatic)
      j.add("auto_sharp_fraction", preset.choice.sharp_fraction)
          .add("auto_crease_line_fraction", preset.choice.crease_line_fraction)
          .add("auto_steep_line_fraction", preset.choice.steep_line_fraction)
          .add("auto_flat_fraction", preset.choice.flat_fraction)
          .add("noise_sigma", preset.noise.sigma)
          .add("noise_sigma_rms", preset.noise.sigma_rms)
          .add("noise_outlier_fraction", preset.noise.outlier_fraction)
          .add("noise_sigma_noise", preset.noise.sigma_noise)
          .add("noise_detail", preset.noise.detail)
          .add("noise_across_ratio", preset.noise.across_ratio)
          .add("noise_level_used", preset.sigma)
          .add("noise_detail_as_noise", preset.detail_as_noise)
          .add("noise_detail_ease", preset.detail_ease)
          .add("noise_despiked", preset.despiked)
          .add("noise_sigma_rms_despiked", preset.noise_despiked.sigma_rms)
          .add("auto_quadric_excess", preset.quadric_excess)
          .add("auto_featureless_limit", preset.featureless_limit)
          .add("auto_featureless", preset.featureless)
          .add("auto_second_round", preset.second_round);
    if (second.weight > 0)
      j.add("second_round_preset", second.preset.preset)
          .add("second_round_reason", second.preset.reason())
          .add("second_round_noise_sigma_rms", second.preset.noise.sigma_rms);
    j.add("strength", preset.strength);
    j.add("vertices", static_cast<long long>(mesh.V.rows())).add("faces", static_cast<long long>(mesh.F.rows()));
    j.add("dropped_degenerate_faces", static_cast<long long>(notes.dropped_degenerate));
    add_notes(j, notes_out);
    if (a.repair) {
      std::vector<Json> done;
      for (const std::string& line : repairs) done.push_back(Json().add("action", line));
      j.add("repair", done);
    }
    j.add("parameters", parameters_json(denoise_parameters(), o)).add("solver", a.solver);
    j.add("seconds_read", t_read)
        .add("seconds_normals", r.seconds_normals)
        .add("seconds_vertices", r.seconds_vertices)
        .add("seconds_write", t_write)
        .add("threads", threads());
    j.add("normal_iterations", r.normal_report.iterations).add("vertex_iterations", r.vertex_report.iterations);
    j.add("despiked_vertices", static_cast<long long>(r.despiked_vertices));
    j.add("planar_regions", static_cast<long long>(r.planar_regions))
        .add("planar_faces", static_cast<long long>(r.planar_faces));
    j.add("jet_faces", static_cast<long long>(r.jet_faces));
    j.add("unreachable_faces", static_cast<long long>(r.unreachable_faces));
    j.add("kept_components", static_cast<long long>(r.kept_components))
        .add("kept_faces", static_cast<long long>(r.kept_faces));
    j.add("n_step_cg_sweeps", r.normal_report.n_solver_iterations)
        .add("v_step_cg_sweeps", r.vertex_report.solver_iterations);
    j.add("residual_history", r.normal_report.residual_history);
    j.add("normal_change_history", r.normal_report.change_history);
    j.add("vertex_change_history", r.vertex_report.change_history);
    if (!a.truth.empty()) {
      auto fig = [](const Evaluation& e) {
        Json k;
        if (e.same_connectivity)
          k.add("msae_e3", e.normals.msae * 1e3)
              .add("mean_angle_deg", e.normals.mean_angle_deg)
              .add("flipped", static_cast<long long>(e.normals.flipped));
        k.add("dist_mean_e3", e.distances.mean * 1e3)
            .add("dist_rms_e3", e.distances.rms * 1e3)
            .add("dist_max_e3", e.distances.max * 1e3);
        return k;
      };
      j.add("input_errors", fig(ev_in)).add("result_errors", fig(ev_out));
    }
    std::cout << j.str() << "\n";
    return;
  }
  if (!a.quiet)
    std::cout << "denoised " << a.input << " -> " << a.output << " (" << mesh.V.rows() << " vertices, " << mesh.F.rows()
              << " faces)\n";
  if (notes.dropped_degenerate > 0)
    std::cout << "  note: " << notes.dropped_degenerate << " face(s) repeating a vertex were dropped on reading\n";
  for (const std::string& line : repairs) std::cout << "  repair: " << line << "\n";
  print_notes(notes_out);
  if (a.quiet) return;  // notes of what was dropped or repaired print even then
  std::cout << "  method " << a.method;
  if (o.method != DenoiseMethod::Bilateral) {
    std::cout << ", preset " << preset.preset;
    if (preset.automatic) std::cout << ", " << preset.reason();
  }
  std::cout << "\n";
  if (second.weight > 0) std::cout << "  second round:     " << second_text << "\n";
  if (o.method != DenoiseMethod::Bilateral) {
    if (o.despike_threshold > 0)
      std::cout << "  spikes:           " << r.despiked_vertices << " vertices moved onto the low-pass surface\n";
    if (r.planar_regions > 0)
      std::cout << "  planar regions:   " << r.planar_regions << " (" << r.planar_faces
                << " faces) snapped to their fitted planes\n";
    if (r.jet_faces > 0)
      std::cout << "  jet-fitted:       " << r.jet_faces
                << " faces on curved parts took the normals of local quadrics\n";
    if (r.unreachable_faces > 0)
      std::cout << "  unreachable:      " << r.unreachable_faces << " faces ended more than "
                << fmt(o.unreachable_angle, 3) << " deg from their targets and followed their neighbours\n";
    if (r.kept_components > 0)
      std::cout << "  kept as they are: " << r.kept_components << " component(s) of fewer than "
                << o.min_component_faces << " faces (" << r.kept_faces << " faces): too few to tell noise from shape\n";
    if (r.kept_faces < mesh.F.rows()) {
      std::cout << "  normal filtering: " << r.normal_report.iterations << " iterations, " << fmt(r.seconds_normals, 3)
                << " s, residual |p - grad N| "
                << fmt(r.normal_report.residual_history.empty() ? 0.0 : r.normal_report.residual_history.back())
                << "\n";
      std::cout << "  vertex update:    " << r.vertex_report.iterations << " iterations, " << fmt(r.seconds_vertices, 3)
                << " s\n";
    }
  } else {
    std::cout << "  bilateral normals " << fmt(r.seconds_normals, 3) << " s, vertex update "
              << fmt(r.seconds_vertices, 3) << " s\n";
  }
  std::cout << "  read " << fmt(t_read, 3) << " s, write " << fmt(t_write, 3) << " s\n";
  if (!a.truth.empty()) {
    auto line = [](const char* what, const Evaluation& e) {
      std::cout << "  " << what;
      if (e.same_connectivity)
        std::cout << " MSAE " << fmt(e.normals.msae * 1e3) << " e-3, mean angle " << fmt(e.normals.mean_angle_deg)
                  << " deg, flipped " << e.normals.flipped << ",";
      std::cout << " distance mean/RMS/max " << fmt(e.distances.mean * 1e3) << "/" << fmt(e.distances.rms * 1e3) << "/"
                << fmt(e.distances.max * 1e3) << " e-3 of bbox diagonal\n";
    };
    line("input: ", ev_in);
    line("result:", ev_out);
  }
  if (!a.field.empty()) std::cout << "  edge field v written to " << a.field << "\n";
  if (!a.report.empty()) std::cout << "  report written to " << a.report << "\n";
}

const Registrar kRegistration("denoise", 50, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c = app.add_subcommand("denoise", "Denoise a mesh: NMSTV normal filtering + vertex updating");
  c->add_option("input", a->input, "Input mesh (obj, off, ply, stl, gltf, glb; also .gz)")->required();
  c->add_option("-o,--output", a->output, "Output mesh; format from the extension")->required();
  std::vector<std::string> presets = preset_names();
  presets.insert(presets.begin(), "auto");
  c->add_option("--preset", a->preset,
                "auto (from the mesh's noise and shape), cad (sharp features), smooth (organic), paper (Algorithms 1 "
                "and 2 with the paper's settings); `msmesh params` shows the values")
      ->check(CLI::IsMember(presets))
      ->capture_default_str();
  c->add_option("--method", a->method, "nmstv (the paper), mstv (all IRLA weights 1), bilateral (Zheng et al. 2011)")
      ->check(CLI::IsMember({"nmstv", "mstv", "bilateral"}))
      ->capture_default_str();
  std::vector<std::pair<std::string, DenoiseOptions>> defaults;
  for (const std::string& name : preset_names()) defaults.emplace_back(name, preset_options(name));
  a->parameters =
      std::make_unique<ParameterOptions<DenoiseOptions>>(c, denoise_parameters(), defaults, "(override the preset)");
  add_number_option(c, "--strength", a->strength,
                    cli_number("denoise", "strength", ParameterType::Real, {kMinStrength, kMaxStrength}),
                    "How much to remove: 1 the default, larger smooths more, smaller keeps more (auto: scales the "
                    "estimated noise its rules use; a named preset: divides alpha)");
  c->add_option("--truth", a->truth, "Ground-truth mesh: print error figures of input and result");
  c->add_option("--save-field", a->field,
                "Write the edge field v (.txt: 'i j v' per edge; .ply: coloured edges; -: text to standard output)");
  c->add_option("--report", a->report,
                "Write an HTML report: 3D viewer, parameters, errors, convergence plots (-: standard output)");
  c->add_option("--solver", a->solver,
                "Linear solver of the fixed systems: auto (Cholesky below ~25K faces, conjugate gradients above), "
                "cholesky, cg")
      ->check(CLI::IsMember({"auto", "cholesky", "cg"}))
      ->capture_default_str()
      ->group("Performance");
  c->add_flag("--json", a->json, "Print one JSON object instead of the summary");
  add_quiet_flag(c, a->quiet);
  c->add_flag("--ascii", a->ascii, "Write PLY/STL as ascii instead of binary");
  c->add_flag("--in-place", a->in_place, "Allow the output to overwrite the input file");
  c->add_flag("--repair", a->repair,
              "First repair the mesh as `msmesh repair` does by default (duplicate vertices, degenerate and "
              "duplicate faces, orientation); removed faces change the face count");
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
