// Bindings of segmentation: SegmentOptions, MulticutOptions, segment(), feature_lines(), rand_index().
#include "bindings.h"
#include "msmesh/multicut.h"
#include "msmesh/segment.h"
#include "msmesh/topology.h"

namespace py = pybind11;

namespace msmesh::python {

namespace {

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
  d["edges"] = to_numpy(r.edges);
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

}  // namespace

void bind_segment(py::module_& m) {
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
  m.def("segment", &segment_binding, py::arg("V"), py::arg("F"), py::arg("options"), py::arg("progress") = py::none());
  m.def("feature_lines", &feature_lines_binding, py::arg("V"), py::arg("F"), py::arg("v"), py::arg("threshold"),
        py::arg("min_edges"));
  m.def("rand_index", &rand_index_binding, py::arg("labels_a"), py::arg("labels_b"));
}

}  // namespace msmesh::python
