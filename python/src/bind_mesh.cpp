// Bindings of meshes as data: noise, error figures, reading and writing, repair, test shapes.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

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
                             const std::string& direction, double impulsive, std::uint64_t seed, int correlation) {
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
  o.correlation = correlation;
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
    d["truth_folded"] = static_cast<long long>(e.normals.truth_folded);
    d["flipped_outside_folds"] = static_cast<long long>(e.normals.flipped_outside_folds);
    d["msae_outside_folds_e3"] = e.normals.msae_outside_folds * 1e3;
  } else {  // normal errors need equal connectivity
    for (const char* key : {"msae", "msae_e3", "mean_angle_deg", "flipped", "angle_rad", "truth_folded",
                            "flipped_outside_folds", "msae_outside_folds_e3"})
      d[key] = py::none();
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

const char* const kScalarTypes[] = {"int8", "uint8", "int16", "uint16", "int32", "uint32", "float32", "float64"};

ScalarType scalar_type_from(const std::string& name, const std::string& what) {
  for (int k = 0; k < 8; ++k)
    if (name == kScalarTypes[k]) return static_cast<ScalarType>(k);
  throw InvalidInput(what + ": unknown scalar type '" + name +
                     "'; valid: int8, uint8, int16, uint16, int32, uint32, float32, float64");
}

/// Every attribute of a mesh as a dict (None for absent arrays), plus the reading notes.
py::dict mesh_to_dict(const Mesh& m, const ReadNotes* notes) {
  py::dict d;
  auto opt = [](const auto& M) { return M.size() > 0 ? to_numpy(M) : py::object(py::none()); };
  auto opt_index = [](const Eigen::VectorXi& x) { return x.size() > 0 ? py::cast(x) : py::object(py::none()); };
  d["V"] = to_numpy(m.V);
  d["F"] = to_numpy(m.F);
  d["vertex_colors"] = opt(m.vertex_colors);
  d["uv"] = opt(m.uv);
  d["vertex_normals"] = opt(m.vertex_normals);
  d["face_colors"] = opt(m.face_colors);
  d["texcoords"] = m.face_texcoords.size() > 0 ? to_numpy(m.texcoords) : py::object(py::none());
  d["face_texcoords"] = opt(m.face_texcoords);
  d["material_libraries"] = m.material_libraries;
  d["material_names"] = m.material_names;
  d["face_materials"] = opt_index(m.face_materials);
  d["group_names"] = m.group_names;
  d["face_groups"] = opt_index(m.face_groups);
  d["object_names"] = m.object_names;
  d["face_objects"] = opt_index(m.face_objects);
  py::dict props, types;
  for (const VertexProperty& p : m.vertex_properties) {
    props[py::str(p.name)] = to_numpy(p.values);
    types[py::str(p.name)] = kScalarTypes[static_cast<int>(p.type)];
  }
  d["vertex_properties"] = props;
  d["vertex_property_types"] = types;
  d["position_type"] = kScalarTypes[static_cast<int>(m.position_type)];
  d["gltf_document"] = m.gltf_document ? py::object(py::bytes(*m.gltf_document)) : py::object(py::none());
  if (notes) {
    d["dropped_degenerate"] = static_cast<long long>(notes->dropped_degenerate);
    d["notes"] = notes->dropped;
  }
  return d;
}

/// The Mesh of a dict as mesh_to_dict makes it (missing keys and None: absent).
Mesh mesh_from_dict(const py::dict& d) {
  Mesh m;
  auto has = [&](const char* key) { return d.contains(key) && !d[key].is_none(); };
  m.V = d["V"].cast<Eigen::MatrixXd>();
  m.F = d["F"].cast<Eigen::MatrixXi>();
  if (has("vertex_colors")) m.vertex_colors = d["vertex_colors"].cast<Eigen::MatrixXd>();
  if (has("uv")) m.uv = d["uv"].cast<Eigen::MatrixXd>();
  if (has("vertex_normals")) m.vertex_normals = d["vertex_normals"].cast<Eigen::MatrixXd>();
  if (has("face_colors")) m.face_colors = d["face_colors"].cast<Eigen::MatrixXd>();
  if (has("texcoords")) m.texcoords = d["texcoords"].cast<Eigen::MatrixXd>();
  if (has("face_texcoords")) m.face_texcoords = d["face_texcoords"].cast<Eigen::MatrixXi>();
  if (has("material_libraries")) m.material_libraries = d["material_libraries"].cast<std::vector<std::string>>();
  if (has("material_names")) m.material_names = d["material_names"].cast<std::vector<std::string>>();
  if (has("face_materials")) m.face_materials = d["face_materials"].cast<Eigen::VectorXi>();
  if (has("group_names")) m.group_names = d["group_names"].cast<std::vector<std::string>>();
  if (has("face_groups")) m.face_groups = d["face_groups"].cast<Eigen::VectorXi>();
  if (has("object_names")) m.object_names = d["object_names"].cast<std::vector<std::string>>();
  if (has("face_objects")) m.face_objects = d["face_objects"].cast<Eigen::VectorXi>();
  py::dict types = has("vertex_property_types") ? d["vertex_property_types"].cast<py::dict>() : py::dict();
  if (has("vertex_properties"))
    for (const auto& [key, value] : d["vertex_properties"].cast<py::dict>()) {
      VertexProperty p;
      p.name = key.cast<std::string>();
      p.values = value.cast<Eigen::VectorXd>();
      if (types.contains(key)) p.type = scalar_type_from(types[key].cast<std::string>(), "vertex property " + p.name);
      m.vertex_properties.push_back(std::move(p));
    }
  if (has("position_type")) m.position_type = scalar_type_from(d["position_type"].cast<std::string>(), "position_type");
  if (has("gltf_document"))
    m.gltf_document = std::make_shared<const std::string>(d["gltf_document"].cast<std::string>());
  validate_attributes(m, "mesh");
  return m;
}

py::dict read_mesh_attributes_binding(const std::string& path) {
  ReadNotes notes;
  const Mesh mesh = run_without_gil(py::none(), [&](const ProgressCallback&) { return read_mesh(path, notes); });
  return mesh_to_dict(mesh, &notes);
}

std::vector<std::string> write_mesh_attributes_binding(const std::string& path, const py::dict& d, bool binary) {
  const Mesh mesh = mesh_from_dict(d);
  WriteOptions o;
  o.binary = binary;
  return run_without_gil(py::none(), [&](const ProgressCallback&) {
    write_mesh(path, mesh, o);
    return unsupported_attributes(mesh, path);
  });
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
        py::arg("impulsive"), py::arg("seed"), py::arg("correlation"));
  m.def("evaluate", &evaluate_binding, py::arg("V"), py::arg("F"), py::arg("V_truth"), py::arg("F_truth"));
  m.def("read_mesh", &read_mesh_binding, py::arg("path"));
  m.def("write_mesh", &write_mesh_binding, py::arg("path"), py::arg("V"), py::arg("F"), py::arg("binary"));
  m.def("read_mesh_attributes", &read_mesh_attributes_binding, py::arg("path"));
  m.def("write_mesh_attributes", &write_mesh_attributes_binding, py::arg("path"), py::arg("mesh"), py::arg("binary"));
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
