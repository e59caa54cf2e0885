// msmesh denoise: NMSTV normal filtering + vertex updating (or the MSTV / bilateral baselines).
#include <chrono>
#include <iostream>
#include <map>

#include "command.h"
#include "field_output.h"
#include "json.h"
#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/io.h"
#include "msmesh/memory.h"
#include "msmesh/metrics.h"
#include "msmesh/repair.h"
#include "msmesh/threads.h"
#include "msmesh/topology.h"
#include "report.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::string input, output, truth, field, preset = "auto", method = "nmstv", solver = "auto";
  double solver_tolerance = 1e-8;
  bool json = false, quiet = false, in_place = false, ascii = false, repair = false;
  double alpha = 0, beta = 0, gamma = 0, rho = 0, epsilon = 0, penalty = 0, nu = 0, v0 = 0;
  int normal_iterations = 0, vertex_iterations = 0;
  double omega1 = 0, omega2 = 0, omega3 = 0;
  double sigma_r = 0, sigma_s = 0;
  int bilateral_iterations = 0;
  std::string report;  // --report: HTML report (cli/report.h)
};

struct Overrides {
  std::map<std::string, CLI::Option*> opts;
  bool given(const std::string& name) const {
    auto it = opts.find(name);
    return it != opts.end() && it->second->count() > 0;
  }
};

void run(const Args& a, const Overrides& ov) {
  check_not_overwriting_input(a.input, a.output, a.in_place);
  const auto t_read0 = std::chrono::steady_clock::now();
  ReadNotes notes;
  Mesh mesh = read_mesh(a.input, notes);
  std::vector<std::string> repairs;  // --repair: what repair_mesh did (vertex order kept)
  if (a.repair) {
    const RepairReport rr = repair_mesh(mesh);
    repairs = rr.actions();
    if (mesh.F.rows() == 0) throw InvalidInput(a.input + ": --repair removed every face (all are degenerate)");
  }
  const double t_read = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_read0).count();

  std::string preset = a.preset;
  PresetChoice choice;
  if (preset == "auto" && a.method == "bilateral") {
    preset = "cad";  // the bilateral baseline has its own parameters; the preset is unused
  } else if (preset == "auto") {
    choice = choose_preset(mesh.V, mesh.F);
    preset = choice.preset;
  }
  DenoiseOptions o = preset_options(preset);
  if (a.method == "nmstv") o.method = DenoiseMethod::NMSTV;
  else if (a.method == "mstv") o.method = DenoiseMethod::MSTV;
  else if (a.method == "bilateral") o.method = DenoiseMethod::Bilateral;
  else throw InvalidInput("unknown method '" + a.method + "'; valid: nmstv, mstv, bilateral");
  if (ov.given("--alpha")) o.normals.alpha = a.alpha;
  if (ov.given("--beta")) o.normals.beta = a.beta;
  if (ov.given("--gamma")) o.normals.gamma = a.gamma;
  if (ov.given("--rho")) o.normals.rho = a.rho;
  if (ov.given("--epsilon")) o.normals.epsilon = a.epsilon;
  if (ov.given("--penalty")) o.normals.penalty = a.penalty;
  if (ov.given("--nu")) o.normals.relaxation = a.nu;
  if (ov.given("--v0")) o.normals.v_initial = a.v0;
  if (ov.given("--normal-iterations")) o.normals.max_iterations = a.normal_iterations;
  if (ov.given("--vertex-iterations")) {
    o.vertices.max_iterations = a.vertex_iterations;
    o.bilateral.vertex_iterations = a.vertex_iterations;
  }
  if (ov.given("--omega1")) o.vertices.omega1 = a.omega1;
  if (ov.given("--omega2")) o.vertices.omega2 = a.omega2;
  if (ov.given("--omega3")) o.vertices.omega3 = a.omega3;
  if (ov.given("--sigma-r")) o.bilateral.sigma_r = a.sigma_r;
  if (ov.given("--sigma-s")) o.bilateral.sigma_s = a.sigma_s;
  if (ov.given("--bilateral-iterations")) o.bilateral.normal_iterations = a.bilateral_iterations;
  const LinearSolver solver = a.solver == "cholesky" ? LinearSolver::Cholesky
                              : a.solver == "cg"     ? LinearSolver::CG
                                                     : LinearSolver::Auto;
  o.normals.solver = o.vertices.solver = solver;
  o.normals.solver_tolerance = o.vertices.solver_tolerance = a.solver_tolerance;
  o.validate();
  check_memory(denoise_memory_estimate(mesh.V.rows(), mesh.F.rows(), o), a.input + ": denoising " +
               std::to_string(mesh.V.rows()) + " vertices and " + std::to_string(mesh.F.rows()) + " faces");

  Mesh truth;
  if (!a.truth.empty()) truth = read_mesh(a.truth);

  const DenoiseResult r = denoise(mesh.V, mesh.F, o, make_progress_bar(a.quiet || a.json));
  finish_progress_line();
  Mesh out = mesh;  // same faces, order, colours and uv; normals recomputed for the result
  out.V = r.V;
  if (mesh.vertex_normals.size() > 0) out.vertex_normals = vertex_normals(out.V, out.F);
  const auto t_w0 = std::chrono::steady_clock::now();
  WriteOptions wo;
  wo.binary = !a.ascii;
  write_mesh(a.output, out, wo);
  if (!a.field.empty()) {
    if (r.v.size() == 0) throw InvalidInput("--save-field needs --method nmstv or mstv (bilateral has no edge field)");
    write_edge_field(a.field, r.V, build_topology(mesh.F, mesh.V.rows()), r.v);
  }
  const double t_write = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_w0).count();

  Evaluation ev_in, ev_out;
  if (!a.truth.empty()) {
    ev_in = evaluate(mesh.V, mesh.F, truth.V, truth.F);
    ev_out = evaluate(out.V, out.F, truth.V, truth.F);
  }
  if (!a.report.empty())
    write_denoise_report(a.report, a.input, mesh, out.V, a.truth.empty() ? nullptr : &truth, a.method, preset, o, r);

  if (a.json) {
    Json j;
    j.add("input", a.input).add("output", a.output).add("preset", preset).add("method", a.method);
    if (a.preset == "auto")
      j.add("auto_sharp_fraction", choice.sharp_fraction).add("auto_flat_fraction", choice.flat_fraction);
    j.add("vertices", static_cast<long long>(mesh.V.rows())).add("faces", static_cast<long long>(mesh.F.rows()));
    j.add("dropped_degenerate_faces", static_cast<long long>(notes.dropped_degenerate));
    if (a.repair) {
      std::vector<Json> done;
      for (const std::string& line : repairs) done.push_back(Json().add("action", line));
      j.add("repair", done);
    }
    Json params;
    params.add("alpha", o.normals.alpha).add("beta", o.normals.beta).add("gamma", o.normals.gamma)
        .add("rho", o.normals.rho).add("epsilon", o.normals.epsilon).add("omega1", o.vertices.omega1)
        .add("omega2", o.vertices.omega2).add("omega3", o.vertices.omega3);
    j.add("parameters", params);
    j.add("seconds_read", t_read).add("seconds_normals", r.seconds_normals)
        .add("seconds_vertices", r.seconds_vertices).add("seconds_write", t_write)
        .add("threads", threads());
    j.add("normal_iterations", r.normal_report.iterations).add("vertex_iterations", r.vertex_report.iterations);
    j.add("n_step_cg_sweeps", r.normal_report.n_solver_iterations)
        .add("v_step_cg_sweeps", r.vertex_report.solver_iterations);
    j.add("residual_history", r.normal_report.residual_history);
    j.add("normal_change_history", r.normal_report.change_history);
    j.add("vertex_change_history", r.vertex_report.change_history);
    if (!a.truth.empty()) {
      auto fig = [](const Evaluation& e) {
        Json k;
        if (e.same_connectivity)
          k.add("msae_e3", e.normals.msae * 1e3).add("mean_angle_deg", e.normals.mean_angle_deg)
              .add("flipped", static_cast<long long>(e.normals.flipped));
        k.add("dist_mean_e3", e.distances.mean * 1e3).add("dist_rms_e3", e.distances.rms * 1e3)
            .add("dist_max_e3", e.distances.max * 1e3);
        return k;
      };
      j.add("input_errors", fig(ev_in)).add("result_errors", fig(ev_out));
    }
    std::cout << j.str() << "\n";
    return;
  }
  std::cout << "denoised " << a.input << " -> " << a.output << " (" << mesh.V.rows() << " vertices, "
            << mesh.F.rows() << " faces)\n";
  if (notes.dropped_degenerate > 0)
    std::cout << "  note: " << notes.dropped_degenerate << " face(s) repeating a vertex were dropped on reading\n";
  for (const std::string& line : repairs) std::cout << "  repair: " << line << "\n";
  if (notes.uv_dropped)
    std::cout << "  note: the input's texture coordinates have seams (not per-vertex) and were not carried over\n";
  std::cout << "  method " << a.method;
  if (o.method != DenoiseMethod::Bilateral) {
    std::cout << ", preset " << preset;
    if (a.preset == "auto") std::cout << " (chosen automatically)";
  }
  std::cout << "\n";
  if (o.method != DenoiseMethod::Bilateral) {
    std::cout << "  normal filtering: " << r.normal_report.iterations << " iterations, "
              << fmt(r.seconds_normals, 3) << " s, residual |p - grad N| "
              << fmt(r.normal_report.residual_history.empty() ? 0.0 : r.normal_report.residual_history.back()) << "\n";
    std::cout << "  vertex update:    " << r.vertex_report.iterations << " iterations, "
              << fmt(r.seconds_vertices, 3) << " s\n";
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
      std::cout << " distance mean/RMS/max " << fmt(e.distances.mean * 1e3) << "/" << fmt(e.distances.rms * 1e3)
                << "/" << fmt(e.distances.max * 1e3) << " e-3 of bbox diagonal\n";
    };
    line("input: ", ev_in);
    line("result:", ev_out);
  }
  if (!a.field.empty()) std::cout << "  edge field v written to " << a.field << "\n";
  if (!a.report.empty()) std::cout << "  report written to " << a.report << "\n";
}

const Registrar reg("denoise", 50, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  auto ov = std::make_shared<Overrides>();
  CLI::App* c = app.add_subcommand("denoise", "Denoise a mesh: NMSTV normal filtering + vertex updating");
  c->add_option("input", a->input, "Input mesh (obj, off, ply, stl)")->required();
  c->add_option("-o,--output", a->output, "Output mesh; format from the extension")->required();
  c->add_option("--preset", a->preset, "cad (sharp features), smooth (organic, scans) or auto (chosen from the mesh)")
      ->check(CLI::IsMember({"cad", "smooth", "auto"}))
      ->capture_default_str();
  c->add_option("--method", a->method, "nmstv (the paper), mstv (all IRLA weights 1), bilateral (Zheng et al. 2011)")
      ->check(CLI::IsMember({"nmstv", "mstv", "bilateral"}))
      ->capture_default_str();
  auto add = [&](const std::string& name, auto* target, const std::string& help) {
    ov->opts[name] = c->add_option(name, *target, help)->group("Parameters (override the preset)");
  };
  add("--alpha", &a->alpha, "alpha > 0: fidelity to the input normals");
  add("--beta", &a->beta, "beta > 0: weight of the edge-set (Ambrosio-Tortorelli) term");
  add("--gamma", &a->gamma, "gamma > 0: weight of the normal variation term");
  add("--rho", &a->rho, "rho > 0: non-convexity of the log penalty (0.9 CAD, 0.1 organic)");
  add("--epsilon", &a->epsilon, "epsilon > 0: phase-field width (default 0.001)");
  add("--penalty", &a->penalty, "ADMM penalty r > 0 (default 1)");
  add("--nu", &a->nu, "ADMM relaxation in (0, 1.618) (default 1.618)");
  add("--v0", &a->v0, "initial edge field in [0,1] (default 0)");
  add("--normal-iterations", &a->normal_iterations, "maximum normal filtering iterations (default 30)");
  add("--vertex-iterations", &a->vertex_iterations, "maximum vertex update iterations (default 30)");
  add("--omega1", &a->omega1, "omega1 > 0: normal matching weight (default 1)");
  add("--omega2", &a->omega2, "omega2 >= 0: fairness weight");
  add("--omega3", &a->omega3, "omega3 > 0: closeness to the input positions");
  add("--sigma-r", &a->sigma_r, "bilateral: range width in (0, 2] (default 0.35)");
  add("--sigma-s", &a->sigma_s, "bilateral: spatial width in mean edge lengths (default: automatic)");
  add("--bilateral-iterations", &a->bilateral_iterations, "bilateral: normal filtering passes (default 20)");
  c->add_option("--truth", a->truth, "Ground-truth mesh: print error figures of input and result");
  c->add_option("--save-field", a->field, "Write the edge field v (.txt: 'i j v' per edge; .ply: coloured edges)");
  c->add_option("--report", a->report, "Write an HTML report: 3D viewer, parameters, errors, convergence plots");
  c->add_option("--solver", a->solver,
                "Linear solver of the fixed systems: auto (Cholesky below 80K faces, conjugate gradients above), "
                "cholesky, cg")
      ->check(CLI::IsMember({"auto", "cholesky", "cg"}))
      ->capture_default_str()
      ->group("Performance");
  c->add_option("--solver-tolerance", a->solver_tolerance, "Relative residual at which conjugate gradients stop, in (0, 1)")
      ->capture_default_str()
      ->group("Performance");
  c->add_flag("--json", a->json, "Print one JSON object instead of the summary");
  c->add_flag("-q,--quiet", a->quiet, "No progress bar");
  c->add_flag("--ascii", a->ascii, "Write PLY/STL as ascii instead of binary");
  c->add_flag("--in-place", a->in_place, "Allow the output to overwrite the input file");
  c->add_flag("--repair", a->repair,
              "First repair the mesh as `msmesh repair` does by default (duplicate vertices, degenerate and "
              "duplicate faces, orientation); removed faces change the face count");
  c->callback([a, ov]() { run(*a, *ov); });
});

}  // namespace
}  // namespace msmesh::cli
