// Bindings of denoising: the option structs of Algorithms 1 and 2 and of the bilateral
// baseline, presets, denoise(), filter_normals(), update_vertices() and the thread setting.
#include <map>
#include <string>

#include "bindings.h"
#include "msmesh/denoise.h"
#include "msmesh/noise_estimate.h"
#include "msmesh/presets.h"
#include "msmesh/second_round.h"
#include "msmesh/taubin.h"
#include "msmesh/topology.h"

namespace py = pybind11;

namespace msmesh::python {

namespace {

// denoise_in_rounds (second_round.h): `second_round` and `strength` are those auto resolved
// (0: one round, as denoise()); the second round's options get the first's method and solvers and
// `overrides` (the caller's parameters, by name).
py::dict denoise_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const DenoiseOptions& options,
                         const py::object& progress, double second_round, double strength,
                         const std::map<std::string, double>& overrides) {
  ResolvedPreset first;
  first.second_round = second_round;
  first.strength = strength;
  const AdjustOptions adjust = [&](DenoiseOptions& o) {
    o.method = options.method;
    o.normals.solver = options.normals.solver;
    o.vertices.solver = options.vertices.solver;
    for (const auto& [name, value] : overrides) set_denoise_parameter(o, name, value);
  };
  SecondRound second;
  const DenoiseResult r = run_without_gil(progress, [&](const ProgressCallback& cb) {
    return denoise_in_rounds(V, F, first, options, adjust, cb, &second);
  });
  py::dict d = normal_report(r.normal_report);
  if (second.weight > 0) {
    d["second_round_preset"] = second.preset.preset;
    d["second_round_reason"] = second.preset.reason();
    d["second_round_noise_sigma_rms"] = second.preset.noise.sigma_rms;
  }
  add_vertex_report(d, r.vertex_report);
  d["V"] = to_numpy(r.V);
  d["normals"] = to_numpy(r.normals);
  if (options.method == DenoiseMethod::Bilateral) {
    d["v"] = py::none();
    d["edges"] = py::none();
    // Bilateral filtering runs a fixed number of passes.
    d["normal_iterations"] = options.bilateral.normal_iterations;
    d["vertex_iterations"] = options.bilateral.vertex_iterations;
  } else {
    d["v"] = to_numpy(r.v);
    d["edges"] = to_numpy(r.edges);
  }
  d["seconds_normals"] = r.seconds_normals;
  d["seconds_vertices"] = r.seconds_vertices;
  d["despiked_vertices"] = static_cast<long long>(r.despiked_vertices);
  d["planar_regions"] = static_cast<long long>(r.planar_regions);
  d["planar_faces"] = static_cast<long long>(r.planar_faces);
  d["jet_faces"] = static_cast<long long>(r.jet_faces);
  d["unreachable_faces"] = static_cast<long long>(r.unreachable_faces);
  d["kept_components"] = static_cast<long long>(r.kept_components);
  d["kept_faces"] = static_cast<long long>(r.kept_faces);
  return d;
}

py::dict filter_normals_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const NormalFilterOptions& options,
                                const Eigen::MatrixXd& normals0, const py::object& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const NormalFilterResult r = run_without_gil(
      progress, [&](const ProgressCallback& cb) { return filter_normals(V, F, options, {}, cb, normals0); });
  py::dict d = normal_report(r);
  d["seconds_normals"] = seconds_since(t0);
  d["normals"] = to_numpy(r.normals);
  d["v"] = to_numpy(r.v);
  d["edges"] = to_numpy(r.edges);
  return d;
}

py::dict update_vertices_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& N,
                                 const Eigen::VectorXd& v, const VertexUpdateOptions& options,
                                 const py::object& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const VertexUpdateResult r = run_without_gil(
      progress, [&](const ProgressCallback& cb) { return update_vertices(V, F, N, v, options, {}, cb); });
  py::dict d;
  add_vertex_report(d, r);
  d["seconds_vertices"] = seconds_since(t0);
  d["V"] = to_numpy(r.V);
  return d;
}

py::dict choose_preset_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  const PresetChoice c = run_without_gil(py::none(), [&](const ProgressCallback&) { return choose_preset(V, F); });
  py::dict d;
  d["preset"] = c.preset;
  d["sharp_fraction"] = c.sharp_fraction;
  d["crease_line_fraction"] = c.crease_line_fraction;
  d["steep_line_fraction"] = c.steep_line_fraction;
  d["flat_fraction"] = c.flat_fraction;
  d["noise_level"] = c.noise_level;
  d["reason"] = c.reason;
  return d;
}

py::dict estimate_noise_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  const NoiseEstimate e = run_without_gil(py::none(), [&](const ProgressCallback&) { return estimate_noise(V, F); });
  py::dict d;
  d["sigma"] = e.sigma;
  d["sigma_rms"] = e.sigma_rms;
  d["outlier_fraction"] = e.outlier_fraction;
  d["sigma_noise"] = e.sigma_noise;
  d["detail"] = e.detail;
  d["across_ratio"] = e.across_ratio;
  d["summary"] = e.summary();
  return d;
}

Eigen::MatrixXd taubin_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, int iterations, double lambda,
                               double mu) {
  TaubinOptions o;
  o.iterations = iterations;
  o.lambda = lambda;
  o.mu = mu;
  return run_without_gil(py::none(), [&](const ProgressCallback&) { return taubin_smooth(V, F, o); });
}

void set_threads_binding(int n) {
  msmesh::set_threads(n);  // checks n
  g_threads = n;
}

}  // namespace

void bind_denoise(py::module_& m) {
  py::class_<ProgressEvent>(m, "ProgressEvent", "One progress report: stage, iteration, max_iterations, residual.")
      .def_readonly("stage", &ProgressEvent::stage)
      .def_readonly("iteration", &ProgressEvent::iteration)
      .def_readonly("max_iterations", &ProgressEvent::max_iterations)
      .def_readonly("residual", &ProgressEvent::residual)
      .def("__repr__", [](const ProgressEvent& e) {
        return "ProgressEvent(stage=" + std::string(py::repr(py::str(e.stage))) +
               ", iteration=" + std::to_string(e.iteration) + ", max_iterations=" + std::to_string(e.max_iterations) +
               ", residual=" + std::string(py::repr(py::float_(e.residual))) + ")";
      });

  py::enum_<DenoiseMethod>(m, "DenoiseMethod")
      .value("NMSTV", DenoiseMethod::NMSTV)
      .value("MSTV", DenoiseMethod::MSTV)
      .value("Bilateral", DenoiseMethod::Bilateral);

  py::enum_<LinearSolver>(m, "LinearSolver", "Solver of the fixed systems (see solver.h).")
      .value("Auto", LinearSolver::Auto)
      .value("Cholesky", LinearSolver::Cholesky)
      .value("CG", LinearSolver::CG);

  py::class_<NormalFilterOptions>(m, "NormalFilterOptions", "Options of Algorithm 1 (see normal_filter.h).")
      .def(py::init<>())
      .def_readwrite("alpha", &NormalFilterOptions::alpha)
      .def_readwrite("beta", &NormalFilterOptions::beta)
      .def_readwrite("gamma", &NormalFilterOptions::gamma)
      .def_readwrite("epsilon", &NormalFilterOptions::epsilon)
      .def_readwrite("rho", &NormalFilterOptions::rho)
      .def_readwrite("penalty", &NormalFilterOptions::penalty)
      .def_readwrite("relaxation", &NormalFilterOptions::relaxation)
      .def_readwrite("max_iterations", &NormalFilterOptions::max_iterations)
      .def_readwrite("tolerance", &NormalFilterOptions::tolerance)
      .def_readwrite("reweight", &NormalFilterOptions::reweight)
      .def_readwrite("v_initial", &NormalFilterOptions::v_initial)
      .def_readwrite("project_each_iteration", &NormalFilterOptions::project_each_iteration)
      .def_readwrite("solver", &NormalFilterOptions::solver)
      .def_readwrite("solver_tolerance", &NormalFilterOptions::solver_tolerance)
      .def("validate", &NormalFilterOptions::validate);

  py::class_<VertexUpdateOptions>(m, "VertexUpdateOptions", "Options of Algorithm 2 (see vertex_update.h).")
      .def(py::init<>())
      .def_readwrite("omega1", &VertexUpdateOptions::omega1)
      .def_readwrite("omega2", &VertexUpdateOptions::omega2)
      .def_readwrite("omega3", &VertexUpdateOptions::omega3)
      .def_readwrite("fairness_tangential", &VertexUpdateOptions::fairness_tangential)
      .def_readwrite("max_iterations", &VertexUpdateOptions::max_iterations)
      .def_readwrite("tolerance", &VertexUpdateOptions::tolerance)
      .def_readwrite("solver", &VertexUpdateOptions::solver)
      .def_readwrite("solver_tolerance", &VertexUpdateOptions::solver_tolerance)
      .def("validate", &VertexUpdateOptions::validate);

  py::class_<BilateralOptions>(m, "BilateralOptions", "Options of bilateral normal filtering (see bilateral.h).")
      .def(py::init<>())
      .def_readwrite("normal_iterations", &BilateralOptions::normal_iterations)
      .def_readwrite("sigma_r", &BilateralOptions::sigma_r)
      .def_readwrite("sigma_s", &BilateralOptions::sigma_s)
      .def_readwrite("vertex_iterations", &BilateralOptions::vertex_iterations)
      .def("validate", &BilateralOptions::validate);

  // Nested members are returned by reference, so `options.normals.alpha = 3` edits `options`.
  py::class_<DenoiseOptions>(m, "DenoiseOptions", "Options of denoise(): method and the three option sets.")
      .def(py::init<>())
      .def_readwrite("method", &DenoiseOptions::method)
      .def_readwrite("normals", &DenoiseOptions::normals)
      .def_readwrite("vertices", &DenoiseOptions::vertices)
      .def_readwrite("bilateral", &DenoiseOptions::bilateral)
      .def("validate", &DenoiseOptions::validate);

  m.def("preset_names", &preset_names);
  m.def("preset_options", &preset_options, py::arg("name"));
  m.def("choose_preset", &choose_preset_binding, py::arg("V"), py::arg("F"));
  m.def("estimate_noise", &estimate_noise_binding, py::arg("V"), py::arg("F"));
  m.def("taubin_smooth", &taubin_binding, py::arg("V"), py::arg("F"), py::arg("iterations"), py::arg("lambda_"),
        py::arg("mu"));
  m.def("denoise", &denoise_binding, py::arg("V"), py::arg("F"), py::arg("options"), py::arg("progress") = py::none(),
        py::arg("second_round") = 0.0, py::arg("strength") = 1.0,
        py::arg("overrides") = std::map<std::string, double>{});
  m.def("filter_normals", &filter_normals_binding, py::arg("V"), py::arg("F"), py::arg("options"), py::arg("normals0"),
        py::arg("progress") = py::none());
  m.def("update_vertices", &update_vertices_binding, py::arg("V"), py::arg("F"), py::arg("N"), py::arg("v"),
        py::arg("options"), py::arg("progress") = py::none());
  m.def("set_threads", &set_threads_binding, py::arg("n"));
  m.def("threads", [] {
    msmesh::set_threads(g_threads.load());
    return msmesh::threads();
  });
}

}  // namespace msmesh::python
