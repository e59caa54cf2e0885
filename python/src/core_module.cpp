// msmesh._core: the pybind11 bindings under the pure-Python package msmesh (python/msmesh).
//
// This layer only converts: numpy arrays to Eigen (copies, made while the GIL is held), calls
// the library with the GIL released, and turns results into dicts of numpy arrays. Argument
// checking that gives friendly messages (shapes, dtypes, index ranges) lives in
// msmesh/__init__.py; the library validates again and throws msmesh::InvalidInput, which
// arrives in Python as msmesh.InvalidInputError (a ValueError).
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Eigen/Core>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <string>
#include <utility>

#include "msmesh/denoise.h"
#include "msmesh/presets.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "msmesh/mesh.h"
#include "msmesh/metrics.h"
#include "msmesh/noise.h"
#include "msmesh/normal_filter.h"
#include "msmesh/progress.h"
#include "msmesh/shapes.h"
#include "msmesh/threads.h"
#include "msmesh/topology.h"
#include "msmesh/vertex_update.h"

// The applications are bound when their headers are present (they arrived after the rest).
#if __has_include("msmesh/segment.h")
#include "msmesh/segment.h"
#define MSMESH_PY_SEGMENT 1
#endif
#if __has_include("msmesh/inpaint.h")
#include "msmesh/inpaint.h"
#define MSMESH_PY_INPAINT 1
#endif
#if __has_include("msmesh/repair.h")
#include "msmesh/repair.h"
#define MSMESH_PY_REPAIR 1
#endif

namespace py = pybind11;

namespace msmesh::python {
namespace {

// Results go back as C-contiguous (row-major) arrays, the layout numpy users expect.
using RowMatrixXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowMatrixXi = Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

py::object to_numpy(const Eigen::MatrixXd& M) { return py::cast(RowMatrixXd(M)); }
py::object to_numpy(const Eigen::MatrixXi& M) { return py::cast(RowMatrixXi(M)); }
py::object to_numpy(const Eigen::VectorXd& x) { return py::cast(Eigen::VectorXd(x)); }

// ---- exceptions -----------------------------------------------------------------------------

// The Python classes, created once in PYBIND11_MODULE and kept alive by the module.
struct ExceptionClasses {
  py::handle error, invalid_input, io_error, solver_error, cancelled;
};
ExceptionClasses& exception_classes() {
  static ExceptionClasses classes;
  return classes;
}

py::handle new_exception(py::module_& m, const char* name, const char* doc, const py::tuple& bases) {
  const std::string qualified = std::string("msmesh.") + name;
  PyObject* cls = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (!cls) throw py::error_already_set();
  m.attr(name) = py::reinterpret_borrow<py::object>(cls);  // the module holds one reference
  return cls;                                               // ... and the registry the other
}

void register_exceptions(py::module_& m) {
  ExceptionClasses& c = exception_classes();
  c.error = new_exception(m, "Error", "Base class of every error msmesh raises.",
                          py::make_tuple(py::handle(PyExc_Exception)));
  c.invalid_input = new_exception(m, "InvalidInputError",
                                  "An input array, mesh or parameter is not acceptable (a ValueError).",
                                  py::make_tuple(c.error, py::handle(PyExc_ValueError)));
  c.io_error = new_exception(m, "IoError", "Reading or writing a mesh file failed (an OSError).",
                             py::make_tuple(c.error, py::handle(PyExc_OSError)));
  c.solver_error = new_exception(m, "SolverError", "A linear solve or factorisation failed (a RuntimeError).",
                                 py::make_tuple(c.error, py::handle(PyExc_RuntimeError)));
  c.cancelled = new_exception(m, "Cancelled", "The progress callback returned False.", py::make_tuple(c.error));

  py::register_exception_translator([](std::exception_ptr p) {
    const ExceptionClasses& k = exception_classes();
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidInput& e) {
      PyErr_SetString(k.invalid_input.ptr(), e.what());
    } catch (const IoError& e) {
      PyErr_SetString(k.io_error.ptr(), e.what());
    } catch (const SolverError& e) {
      PyErr_SetString(k.solver_error.ptr(), e.what());
    } catch (const Cancelled& e) {
      PyErr_SetString(k.cancelled.ptr(), e.what());
    } catch (const Error& e) {
      PyErr_SetString(k.error.ptr(), e.what());
    }
  });
}

// ---- progress and the GIL -------------------------------------------------------------------

// Bridges a Python progress callable (or None) to a ProgressCallback. The callback runs on a
// thread that does not hold the GIL, so it takes the GIL for the duration of the Python call
// only. A Python exception raised by the callable (or a pending KeyboardInterrupt) is kept and
// cancels the computation; run_without_gil() re-raises it once the GIL is back.
class ProgressBridge {
 public:
  explicit ProgressBridge(py::object callable) : callable_(std::move(callable)) {}

  ProgressCallback callback() {
    return [this](const ProgressEvent& event) -> bool {
      py::gil_scoped_acquire gil;
      try {
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // Ctrl-C cancels
        if (callable_.is_none()) return true;
        const py::object answer = callable_(event);
        if (answer.is_none()) return true;  // a callback that only prints continues
        const int truth = PyObject_IsTrue(answer.ptr());
        if (truth < 0) throw py::error_already_set();
        return truth != 0;
      } catch (...) {
        error_ = std::current_exception();
        return false;
      }
    };
  }

  /// Rethrows the callback's exception, if it raised one. Call with the GIL held.
  void rethrow_if_failed() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  py::object callable_;
  std::exception_ptr error_;
};

// msmesh.set_threads(n): process-wide for Python (0: the default). The library's setting is
// OpenMP's, which belongs to each thread, so every call applies it in the thread it runs in.
std::atomic<int> g_threads{0};

void set_threads_binding(int n) {
  msmesh::set_threads(n);  // checks n
  g_threads = n;
}

/// Runs fn(progress_callback) with the GIL released, with the thread count of set_threads.
/// The callback's own exception takes precedence over the Cancelled it causes.
template <class Fn>
auto run_without_gil(const py::object& progress, Fn&& fn) {
  msmesh::set_threads(g_threads.load());
  ProgressBridge bridge(progress);
  const ProgressCallback callback = bridge.callback();
  try {
    auto result = [&] {
      py::gil_scoped_release release;
      return fn(callback);
    }();
    bridge.rethrow_if_failed();
    return result;
  } catch (...) {
    bridge.rethrow_if_failed();
    throw;
  }
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// ---- reports --------------------------------------------------------------------------------

py::dict normal_report(const NormalFilterResult& r) {
  py::dict d;
  d["normal_iterations"] = r.iterations;
  d["normal_converged"] = r.converged;
  d["residual_history"] = r.residual_history;
  d["normal_change_history"] = r.change_history;
  d["energy_history"] = r.energy_history;
  d["v_solver_iterations"] = r.v_solver_iterations;
  d["n_solver_iterations"] = r.n_solver_iterations;
  return d;
}

void add_vertex_report(py::dict& d, const VertexUpdateResult& r) {
  d["vertex_iterations"] = r.iterations;
  d["vertex_converged"] = r.converged;
  d["vertex_change_history"] = r.change_history;
  d["fallback_projections"] = static_cast<long long>(r.fallback_projections);
  d["vertex_solver_iterations"] = r.solver_iterations;
}

py::dict denoise_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const DenoiseOptions& options,
                         const py::object& progress) {
  const DenoiseResult r = run_without_gil(
      progress, [&](const ProgressCallback& cb) { return denoise(V, F, options, cb); });
  py::dict d = normal_report(r.normal_report);
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
    d["edges"] = to_numpy(build_topology(F, V.rows()).edges);
  }
  d["seconds_normals"] = r.seconds_normals;
  d["seconds_vertices"] = r.seconds_vertices;
  return d;
}

py::dict filter_normals_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                const NormalFilterOptions& options, const Eigen::MatrixXd& normals0,
                                const py::object& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const NormalFilterResult r = run_without_gil(progress, [&](const ProgressCallback& cb) {
    return filter_normals(V, F, options, {}, cb, normals0);
  });
  py::dict d = normal_report(r);
  d["seconds_normals"] = seconds_since(t0);
  d["normals"] = to_numpy(r.normals);
  d["v"] = to_numpy(r.v);
  d["edges"] = to_numpy(build_topology(F, V.rows()).edges);
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
  d["flat_fraction"] = c.flat_fraction;
  d["noise_level"] = c.noise_level;
  return d;
}

py::object add_noise_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, double sigma,
                             const std::string& direction, double impulsive, std::uint64_t seed) {
  NoiseOptions o;
  o.sigma = sigma;
  if (direction == "normal") o.direction = NoiseDirection::Normal;
  else if (direction == "random") o.direction = NoiseDirection::Random;
  else throw InvalidInput("unknown noise direction '" + direction + "'; valid: normal, random");
  o.impulsive_fraction = impulsive;
  o.seed = seed;
  const Eigen::MatrixXd noisy =
      run_without_gil(py::none(), [&](const ProgressCallback&) { return add_noise(V, F, o); });
  return to_numpy(noisy);
}

py::dict evaluate_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& V_truth,
                          const Eigen::MatrixXi& F_truth) {
  const Evaluation e =
      run_without_gil(py::none(), [&](const ProgressCallback&) { return evaluate(V, F, V_truth, F_truth); });
  py::dict d;
  d["same_connectivity"] = e.same_connectivity;
  if (e.same_connectivity) {
    d["msae"] = e.normals.msae;
    d["msae_e3"] = e.normals.msae * 1e3;
    d["mean_angle_deg"] = e.normals.mean_angle_deg;
    d["flipped"] = static_cast<long long>(e.normals.flipped);
    d["angle_rad"] = to_numpy(e.normals.angle_rad);
  } else {  // normal errors need equal connectivity
    for (const char* key : {"msae", "msae_e3", "mean_angle_deg", "flipped", "angle_rad"}) d[key] = py::none();
  }
  d["distance_mean"] = e.distances.mean;
  d["distance_rms"] = e.distances.rms;
  d["distance_max"] = e.distances.max;
  d["distance_area_weighted_rms"] = e.distances.area_weighted_rms;
  return d;
}

py::tuple read_mesh_binding(const std::string& path) {
  Eigen::Index dropped = 0;
  const Mesh mesh = run_without_gil(py::none(), [&](const ProgressCallback&) { return read_mesh(path, &dropped); });
  return py::make_tuple(to_numpy(mesh.V), to_numpy(mesh.F), static_cast<long long>(dropped));
}

void write_mesh_binding(const std::string& path, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, bool binary) {
  Mesh mesh;
  mesh.V = V;
  mesh.F = F;
  WriteOptions o;
  o.binary = binary;
  run_without_gil(py::none(), [&](const ProgressCallback&) {
    write_mesh(path, mesh, o);
    return 0;
  });
}

#ifdef MSMESH_PY_REPAIR
py::dict repair_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const RepairOptions& options) {
  Mesh mesh;
  mesh.V = V;
  mesh.F = F;
  const RepairReport r = run_without_gil(py::none(), [&](const ProgressCallback&) { return repair_mesh(mesh, options); });
  py::dict report;
  report["merged_vertices"] = r.merged_vertices;
  report["degenerate_faces_removed"] = r.degenerate_faces_removed;
  report["zero_area_faces_removed"] = r.zero_area_faces_removed;
  report["duplicate_faces_removed"] = r.duplicate_faces_removed;
  report["flipped_faces"] = r.flipped_faces;
  report["split_vertices"] = r.split_vertices;
  report["unreferenced_vertices_removed"] = r.unreferenced_vertices_removed;
  report["components"] = r.components;
  report["non_orientable_components"] = r.non_orientable_components;
  report["non_manifold_edges"] = r.non_manifold_edges;
  report["non_manifold_vertices"] = r.non_manifold_vertices;
  report["unreferenced_vertices"] = r.unreferenced_vertices;
  report["changed"] = r.changed();
  report["actions"] = r.actions();
  py::dict d;
  d["V"] = to_numpy(mesh.V);
  d["F"] = to_numpy(mesh.F);
  d["vertex_map"] = py::cast(Eigen::VectorXi(r.vertex_map));
  d["face_origin"] = py::cast(Eigen::VectorXi(r.face_origin));
  d["report"] = report;
  return d;
}
#endif

py::tuple make_shape_binding(const std::string& name, int resolution) {
  const Mesh mesh = run_without_gil(py::none(), [&](const ProgressCallback&) { return make_shape(name, resolution); });
  return py::make_tuple(to_numpy(mesh.V), to_numpy(mesh.F));
}

// ---- applications ----------------------------------------------------------------------------

py::object bool_array(const std::vector<bool>& flags) {
  py::array_t<bool> a(static_cast<py::ssize_t>(flags.size()));
  auto m = a.mutable_unchecked<1>();
  for (size_t i = 0; i < flags.size(); ++i) m(static_cast<py::ssize_t>(i)) = flags[i];
  return std::move(a);
}

#ifdef MSMESH_PY_SEGMENT
py::dict segment_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const SegmentOptions& options,
                         const py::object& progress) {
  const auto t0 = std::chrono::steady_clock::now();
  const SegmentResult r =
      run_without_gil(progress, [&](const ProgressCallback& cb) { return segment(V, F, options, cb); });
  py::dict d = normal_report(r.normal_report);
  d["seconds"] = seconds_since(t0);
  d["labels"] = py::cast(Eigen::VectorXi(r.labels));
  d["count"] = r.count;
  d["areas"] = to_numpy(r.areas);
  d["objective"] = r.objective;
  d["multicut_count"] = r.multicut_count;
  d["normals"] = to_numpy(r.normals);
  d["v"] = to_numpy(r.v);
  d["v_normalized"] = to_numpy(r.v_normalized);
  d["split_probability"] = to_numpy(r.split_probability);
  d["edges"] = to_numpy(build_topology(F, V.rows()).edges);
  const MulticutResult& mc = r.multicut_report;
  d["multicut_objective_greedy"] = mc.objective_greedy;
  d["multicut_contractions"] = mc.contractions;
  d["multicut_local_rounds"] = mc.local_rounds;
  d["multicut_local_moves"] = mc.local_moves;
  return d;
}

std::vector<py::object> feature_lines_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                              const Eigen::VectorXd& v, double threshold, int min_edges) {
  const std::vector<std::vector<int>> lines = run_without_gil(
      py::none(), [&](const ProgressCallback&) { return feature_lines(V, F, v, threshold, min_edges); });
  std::vector<py::object> out;
  out.reserve(lines.size());
  for (const auto& line : lines) out.push_back(py::array_t<int>(static_cast<py::ssize_t>(line.size()), line.data()));
  return out;
}

double rand_index_binding(const Eigen::VectorXi& a, const Eigen::VectorXi& b) { return rand_index(a, b); }
#endif

#ifdef MSMESH_PY_INPAINT
py::dict hole_dict(const Hole& h) {
  py::dict d;
  d["loop"] = py::array_t<int>(static_cast<py::ssize_t>(h.loop.size()), h.loop.data());
  d["edges"] = h.edges;
  d["diameter"] = h.diameter;
  d["length"] = h.length;
  d["component"] = h.component;
  d["outer_boundary"] = h.outer_boundary;
  d["simple"] = h.simple;
  d["touching_vertex"] = h.simple ? py::object(py::none()) : py::object(py::int_(h.touching_vertex));
  return d;
}

py::list find_holes_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  const std::vector<Hole> holes =
      run_without_gil(py::none(), [&](const ProgressCallback&) { return find_holes(V, F); });
  py::list out;
  for (const Hole& h : holes) out.append(hole_dict(h));
  return out;
}

const char* hole_action_name(HoleAction a) {
  switch (a) {
    case HoleAction::Filled: return "filled";
    case HoleAction::Skipped: return "skipped";
    case HoleAction::Failed: return "failed";
  }
  return "unknown";
}

py::dict inpaint_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const InpaintOptions& options,
                         const py::object& progress) {
  const InpaintResult r =
      run_without_gil(progress, [&](const ProgressCallback& cb) { return inpaint(V, F, options, cb); });
  py::dict d = normal_report(r.normal_report);
  add_vertex_report(d, r.vertex_report);
  d["V"] = to_numpy(r.V);
  d["F"] = to_numpy(r.F);
  d["new_faces"] = bool_array(r.new_faces);
  d["new_vertices"] = bool_array(r.new_vertices);
  py::list holes;
  for (size_t i = 0; i < r.holes.size(); ++i) {
    py::dict h = hole_dict(r.holes[i]);
    if (i < r.reports.size()) {
      const HoleReport& rep = r.reports[i];
      h["action"] = hole_action_name(rep.action);
      h["reason"] = rep.reason;
      h["new_faces"] = rep.new_faces;
      h["new_vertices"] = rep.new_vertices;
      h["faired"] = rep.faired;
    }
    holes.append(h);
  }
  d["holes"] = holes;
  d["filled"] = r.filled;
  d["skipped"] = r.skipped;
  d["failed"] = r.failed;
  d["moved_input_vertices"] = r.moved_input_vertices;
  d["seconds_fill"] = r.seconds_fill;
  d["seconds_features"] = r.seconds_features;
  return d;
}

py::dict inpaint_errors_binding(const Eigen::MatrixXd& V_input, const Eigen::MatrixXi& F_input,
                                const Eigen::MatrixXd& V_result, const Eigen::MatrixXi& F_result,
                                const std::vector<bool>& new_faces, const Eigen::MatrixXd& V_truth,
                                const Eigen::MatrixXi& F_truth) {
  const InpaintErrors e = run_without_gil(py::none(), [&](const ProgressCallback&) {
    return inpaint_errors(V_input, F_input, V_result, F_result, new_faces, V_truth, F_truth);
  });
  py::dict d;
  d["points"] = static_cast<long long>(e.points);
  d["distance_max"] = e.max;
  d["distance_mean"] = e.mean;
  d["distance_rms"] = e.rms;
  d["new_faces"] = static_cast<long long>(e.new_faces);
  d["new_face_normal_error_deg"] = e.mean_normal_error_deg;
  return d;
}

py::tuple punch_holes_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, int count, double radius,
                              std::uint64_t seed, bool on_features) {
  const PunchResult r = run_without_gil(
      py::none(), [&](const ProgressCallback&) { return punch_holes(V, F, count, radius, seed, on_features); });
  py::dict d;
  d["vertex_map"] = py::cast(Eigen::VectorXi(r.vertex_map));
  d["old_to_new"] = py::cast(Eigen::VectorXi(r.old_to_new));
  d["centers"] = r.centers;
  d["punched"] = r.punched;
  return py::make_tuple(to_numpy(r.V), to_numpy(r.F), d);
}
#endif

// ---- option structs -------------------------------------------------------------------------

void bind_options(py::module_& m) {
  py::class_<ProgressEvent>(m, "ProgressEvent", "One progress report: stage, iteration, max_iterations, residual.")
      .def_readonly("stage", &ProgressEvent::stage)
      .def_readonly("iteration", &ProgressEvent::iteration)
      .def_readonly("max_iterations", &ProgressEvent::max_iterations)
      .def_readonly("residual", &ProgressEvent::residual)
      .def("__repr__", [](const ProgressEvent& e) {
        return "ProgressEvent(stage=" + std::string(py::repr(py::str(e.stage))) +
               ", iteration=" + std::to_string(e.iteration) + ", max_iterations=" +
               std::to_string(e.max_iterations) + ", residual=" + std::string(py::repr(py::float_(e.residual))) + ")";
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
      .def_readwrite("max_iterations", &VertexUpdateOptions::max_iterations)
      .def_readwrite("tolerance", &VertexUpdateOptions::tolerance)
      .def_readwrite("solver", &VertexUpdateOptions::solver)
      .def_readwrite("solver_tolerance", &VertexUpdateOptions::solver_tolerance)
      .def("validate", &VertexUpdateOptions::validate);

  py::class_<BilateralOptions>(m, "BilateralOptions", "Options of bilateral normal filtering (see denoise.h).")
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

#ifdef MSMESH_PY_SEGMENT
  py::class_<MulticutOptions>(m, "MulticutOptions", "Options of the multicut solver (see multicut.h).")
      .def(py::init<>())
      .def_readwrite("local_search", &MulticutOptions::local_search)
      .def_readwrite("max_local_rounds", &MulticutOptions::max_local_rounds)
      .def_readwrite("tolerance", &MulticutOptions::tolerance)
      .def("validate", &MulticutOptions::validate);

  py::class_<SegmentOptions>(m, "SegmentOptions", "Options of segment() (see segment.h).")
      .def(py::init<>())
      .def_readwrite("normals", &SegmentOptions::normals)
      .def_readwrite("smooth_angle_deg", &SegmentOptions::smooth_angle_deg)
      .def_readwrite("clamp_probability", &SegmentOptions::clamp_probability)
      .def_readwrite("min_area_fraction", &SegmentOptions::min_area_fraction)
      .def_readwrite("multicut", &SegmentOptions::multicut)
      .def("validate", &SegmentOptions::validate);
#endif

#ifdef MSMESH_PY_INPAINT
  py::class_<InpaintOptions>(m, "InpaintOptions", "Options of inpaint() (see inpaint.h).")
      .def(py::init<>())
      .def_readwrite("max_hole_edges", &InpaintOptions::max_hole_edges)
      .def_readwrite("max_hole_diameter", &InpaintOptions::max_hole_diameter)
      .def_readwrite("holes", &InpaintOptions::holes)
      .def_readwrite("fill_outer_boundary", &InpaintOptions::fill_outer_boundary)
      .def_readwrite("recover_features", &InpaintOptions::recover_features)
      .def_readwrite("free_ring", &InpaintOptions::free_ring)
      .def_readwrite("normals", &InpaintOptions::normals)
      .def_readwrite("vertices", &InpaintOptions::vertices)
      .def_readwrite("outside_alpha", &InpaintOptions::outside_alpha)
      .def_readwrite("inside_alpha", &InpaintOptions::inside_alpha)
      .def_readwrite("inside_beta", &InpaintOptions::inside_beta)
      .def_readwrite("inside_omega3", &InpaintOptions::inside_omega3)
      .def_readwrite("ring_omega3", &InpaintOptions::ring_omega3)
      .def_readwrite("pinned_omega3", &InpaintOptions::pinned_omega3)
      .def_readwrite("context_rings", &InpaintOptions::context_rings)
      .def_readwrite("rounds", &InpaintOptions::rounds)
      .def("validate", &InpaintOptions::validate);
#endif
}

}  // namespace
}  // namespace msmesh::python

PYBIND11_MODULE(_core, m) {
  using namespace msmesh;
  using namespace msmesh::python;
  m.doc() = "Compiled core of msmesh; use the functions of the msmesh package, which check their inputs.";
  register_exceptions(m);
  bind_options(m);

  m.def("preset_names", &preset_names);
  m.def("preset_options", &preset_options, py::arg("name"));
  m.def("choose_preset", &choose_preset_binding, py::arg("V"), py::arg("F"));
  m.def("denoise", &denoise_binding, py::arg("V"), py::arg("F"), py::arg("options"), py::arg("progress") = py::none());
  m.def("filter_normals", &filter_normals_binding, py::arg("V"), py::arg("F"), py::arg("options"),
        py::arg("normals0"), py::arg("progress") = py::none());
  m.def("update_vertices", &update_vertices_binding, py::arg("V"), py::arg("F"), py::arg("N"), py::arg("v"),
        py::arg("options"), py::arg("progress") = py::none());
  m.def("add_noise", &add_noise_binding, py::arg("V"), py::arg("F"), py::arg("sigma"), py::arg("direction"),
        py::arg("impulsive"), py::arg("seed"));
  m.def("evaluate", &evaluate_binding, py::arg("V"), py::arg("F"), py::arg("V_truth"), py::arg("F_truth"));
  m.def("read_mesh", &read_mesh_binding, py::arg("path"));
  m.def("write_mesh", &write_mesh_binding, py::arg("path"), py::arg("V"), py::arg("F"), py::arg("binary"));
  m.def("make_shape", &make_shape_binding, py::arg("name"), py::arg("resolution"));
  m.def("shape_names", &shape_names);
  m.def("set_threads", &set_threads_binding, py::arg("n"));
  m.def("threads", [] {
    msmesh::set_threads(g_threads.load());
    return msmesh::threads();
  });

#ifdef MSMESH_PY_SEGMENT
  m.def("segment", &segment_binding, py::arg("V"), py::arg("F"), py::arg("options"), py::arg("progress") = py::none());
  m.def("feature_lines", &feature_lines_binding, py::arg("V"), py::arg("F"), py::arg("v"), py::arg("threshold"),
        py::arg("min_edges"));
  m.def("rand_index", &rand_index_binding, py::arg("labels_a"), py::arg("labels_b"));
#endif
#ifdef MSMESH_PY_REPAIR
  py::class_<RepairOptions>(m, "RepairOptions", "Options of repair() (see repair.h).")
      .def(py::init<>())
      .def_readwrite("merge_duplicate_vertices", &RepairOptions::merge_duplicate_vertices)
      .def_readwrite("weld_tolerance", &RepairOptions::weld_tolerance)
      .def_readwrite("remove_degenerate_faces", &RepairOptions::remove_degenerate_faces)
      .def_readwrite("zero_area_tolerance", &RepairOptions::zero_area_tolerance)
      .def_readwrite("remove_duplicate_faces", &RepairOptions::remove_duplicate_faces)
      .def_readwrite("orient", &RepairOptions::orient)
      .def_readwrite("split_non_manifold", &RepairOptions::split_non_manifold)
      .def_readwrite("remove_unreferenced", &RepairOptions::remove_unreferenced)
      .def("validate", &RepairOptions::validate);
  m.def("repair", &repair_binding, py::arg("V"), py::arg("F"), py::arg("options"));
#endif
#ifdef MSMESH_PY_INPAINT
  m.def("find_holes", &find_holes_binding, py::arg("V"), py::arg("F"));
  m.def("inpaint", &inpaint_binding, py::arg("V"), py::arg("F"), py::arg("options"), py::arg("progress") = py::none());
  m.def("inpaint_errors", &inpaint_errors_binding, py::arg("V_input"), py::arg("F_input"), py::arg("V_result"),
        py::arg("F_result"), py::arg("new_faces"), py::arg("V_truth"), py::arg("F_truth"));
  m.def("punch_holes", &punch_holes_binding, py::arg("V"), py::arg("F"), py::arg("count"), py::arg("radius"),
        py::arg("seed"), py::arg("on_features"));
#endif
}
