// Bindings of inpainting: InpaintOptions, find_holes(), inpaint(), inpaint_errors(), punch_holes().
#include <cstdint>

#include "bindings.h"
#include "msmesh/holes.h"
#include "msmesh/inpaint.h"
#include "msmesh/metrics.h"
#include "msmesh/punch_holes.h"

namespace py = pybind11;

namespace msmesh::python {

namespace {

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

}  // namespace

void bind_inpaint(py::module_& m) {
  py::class_<InpaintOptions>(m, "InpaintOptions", "Options of inpaint() (see inpaint.h).")
      .def(py::init<>())
      .def_readwrite("max_hole_edges", &InpaintOptions::max_hole_edges)
      .def_readwrite("max_hole_diameter", &InpaintOptions::max_hole_diameter)
      .def_readwrite("holes", &InpaintOptions::holes)
      .def_readwrite("fill_outer_boundary", &InpaintOptions::fill_outer_boundary)
      .def_readwrite("recover_features", &InpaintOptions::recover_features)
      .def_readwrite("free_ring", &InpaintOptions::free_ring)
      .def_readwrite("density", &InpaintOptions::density)
      .def_readwrite("feature_density", &InpaintOptions::feature_density)
      .def_readwrite("feature_angle", &InpaintOptions::feature_angle)
      .def_readwrite("smooth_angle", &InpaintOptions::smooth_angle)
      .def_readwrite("all_holes_featured", &InpaintOptions::all_holes_featured)
      .def_readwrite("smooth_normals", &InpaintOptions::smooth_normals)
      .def_readwrite("smooth_jump_angle", &InpaintOptions::smooth_jump_angle)
      .def_readwrite("orthogonal_placement", &InpaintOptions::orthogonal_placement)
      .def_readwrite("placement_smoothing", &InpaintOptions::placement_smoothing)
      .def_readwrite("crease_flips", &InpaintOptions::crease_flips)
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
  m.def("find_holes", &find_holes_binding, py::arg("V"), py::arg("F"));
  m.def("inpaint", &inpaint_binding, py::arg("V"), py::arg("F"), py::arg("options"), py::arg("progress") = py::none());
  m.def("inpaint_errors", &inpaint_errors_binding, py::arg("V_input"), py::arg("F_input"), py::arg("V_result"),
        py::arg("F_result"), py::arg("new_faces"), py::arg("V_truth"), py::arg("F_truth"));
  m.def("punch_holes", &punch_holes_binding, py::arg("V"), py::arg("F"), py::arg("count"), py::arg("radius"),
        py::arg("seed"), py::arg("on_features"));
}

}  // namespace msmesh::python
