// Bindings of a mesh's figures: info(), the fields of `msmesh info --json` that come from the
// mesh itself (counts, defects, size, area, volume, watertightness, genus, components).
#include <algorithm>
#include <vector>

#include "bindings.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh_statistics.h"
#include "msmesh/topology.h"

namespace py = pybind11;

namespace msmesh::python {

namespace {

/// How many of the largest boundary loops and how many components are listed, as the CLI.
constexpr std::size_t kLargestLoops = 5;
constexpr std::size_t kListedComponents = 20;

struct Info {
  Topology topo;
  TopologySummary summary;
  MeshStatistics stats;
  double mean_edge = 0;
};

py::object genus_or_none(Eigen::Index g) { return g >= 0 ? py::cast(static_cast<long long>(g)) : py::none(); }

py::dict info_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  const Info in = run_without_gil(py::none(), [&](const ProgressCallback&) {
    Info r;
    r.stats = mesh_statistics(V, F);  // validates the mesh
    r.topo = build_topology(F, V.rows());
    r.summary = summarize_topology(F, r.topo);
    r.mean_edge = mean_edge_length(V, F);
    return r;
  });
  const TopologySummary& s = in.summary;
  const MeshStatistics& st = in.stats;
  std::vector<long long> loops;
  for (const auto& loop : s.boundary_loops) loops.push_back(static_cast<long long>(loop.size()));
  std::sort(loops.rbegin(), loops.rend());
  loops.resize(std::min(loops.size(), kLargestLoops));
  py::dict d;
  d["vertices"] = static_cast<long long>(V.rows());
  d["faces"] = static_cast<long long>(F.rows());
  d["edges"] = static_cast<long long>(in.topo.num_edges());
  d["boundary_edges"] = static_cast<long long>(s.boundary_edges);
  d["boundary_loops"] = static_cast<long long>(s.boundary_loops.size());
  d["largest_boundary_loops"] = loops;
  d["non_manifold_edges"] = static_cast<long long>(s.non_manifold_edges);
  d["non_manifold_vertices"] = static_cast<long long>(s.non_manifold_vertices);
  d["unreferenced_vertices"] = static_cast<long long>(s.unreferenced_vertices);
  d["inconsistently_oriented_edges"] = static_cast<long long>(s.inconsistently_oriented_edges);
  d["components"] = static_cast<long long>(s.components);
  d["mean_edge_length"] = in.mean_edge;
  const Eigen::RowVector3d lo = V.rows() ? Eigen::RowVector3d(V.colwise().minCoeff()) : Eigen::RowVector3d::Zero();
  const Eigen::RowVector3d hi = V.rows() ? Eigen::RowVector3d(V.colwise().maxCoeff()) : Eigen::RowVector3d::Zero();
  d["bbox_min"] = std::vector<double>{lo(0), lo(1), lo(2)};
  d["bbox_max"] = std::vector<double>{hi(0), hi(1), hi(2)};
  d["bbox_diagonal"] = (hi - lo).norm();
  d["area"] = st.area;
  d["volume"] = st.closed_components > 0 ? py::cast(st.volume) : py::none();
  d["closed_components"] = static_cast<long long>(st.closed_components);
  d["watertight"] = st.watertight;
  d["euler_characteristic"] = static_cast<long long>(st.euler_characteristic);
  d["genus"] = genus_or_none(st.genus);
  py::list parts;
  for (std::size_t i = 0; i < std::min(st.per_component.size(), kListedComponents); ++i) {
    const ComponentStatistics& c = st.per_component[i];
    py::dict p;
    p["faces"] = static_cast<long long>(c.faces);
    p["vertices"] = static_cast<long long>(c.vertices);
    p["edges"] = static_cast<long long>(c.edges);
    p["area"] = c.area;
    p["closed"] = c.closed;
    p["manifold"] = c.manifold;
    p["orientable"] = c.orientable;
    p["consistently_oriented"] = c.consistently_oriented;
    p["volume"] = c.closed && c.orientable ? py::cast(c.volume) : py::none();
    p["euler_characteristic"] = static_cast<long long>(c.euler_characteristic);
    p["boundary_loops"] = static_cast<long long>(c.boundary_loops);
    p["genus"] = genus_or_none(c.genus);
    parts.append(p);
  }
  d["component_details"] = parts;
  return d;
}

}  // namespace

void bind_statistics(py::module_& m) { m.def("info", &info_binding, py::arg("V"), py::arg("F")); }

}  // namespace msmesh::python
