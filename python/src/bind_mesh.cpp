// Bindings of meshes as data: noise, error figures, reading and writing, repair, test shapes.
#include <cstdint>
#include <string>

#include "bindings.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "msmesh/mesh.h"
#include "msmesh/metrics.h"
#include "msmesh/noise.h"
#include "msmesh/repair.h"
#include "msmesh/shapes.h"

namespace py = pybind11;

namespace msmesh::python {

namespace {

py::object add_noise_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, double sigma,
                             const std::string& direction, double impulsive, std::uint64_t seed) {
  NoiseOptions o;
  o.sigma = sigma;
  if (direction == "normal")
    o.direction = NoiseDirection::Normal;
  else if (direction == "random")
    o.direction = NoiseDirection::Random;
  else
    throw InvalidInput("unknown noise direction '" + direction + "'; valid: normal, random");
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

py::dict repair_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const RepairOptions& options) {
  Mesh mesh;
  mesh.V = V;
  mesh.F = F;
  const RepairReport r =
      run_without_gil(py::none(), [&](const ProgressCallback&) { return repair_mesh(mesh, options); });
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

py::tuple make_shape_binding(const std::string& name, int resolution) {
  const Mesh mesh = run_without_gil(py::none(), [&](const ProgressCallback&) { return make_shape(name, resolution); });
  return py::make_tuple(to_numpy(mesh.V), to_numpy(mesh.F));
}

}  // namespace

void bind_mesh(py::module_& m) {
  m.def("add_noise", &add_noise_binding, py::arg("V"), py::arg("F"), py::arg("sigma"), py::arg("direction"),
        py::arg("impulsive"), py::arg("seed"));
  m.def("evaluate", &evaluate_binding, py::arg("V"), py::arg("F"), py::arg("V_truth"), py::arg("F_truth"));
  m.def("read_mesh", &read_mesh_binding, py::arg("path"));
  m.def("write_mesh", &write_mesh_binding, py::arg("path"), py::arg("V"), py::arg("F"), py::arg("binary"));
  m.def("make_shape", &make_shape_binding, py::arg("name"), py::arg("resolution"));
  m.def("shape_names", &shape_names);
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
}

}  // namespace msmesh::python
