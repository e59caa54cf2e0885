// msmesh info: counts, defects, size, area, volume, watertightness and genus of a mesh, as read
// (after triangulation and dropping degenerate faces). The figures: msmesh/mesh_statistics.h,
// the same as msmesh.info() in Python.
#include <algorithm>
#include <iostream>
#include <memory>

#include "command.h"
#include "json.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/io.h"
#include "msmesh/mesh_statistics.h"
#include "msmesh/topology.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::string input;
  bool json = false, quiet = false;
};

/// How many of the largest boundary loops to list.
constexpr std::size_t kLargestLoops = 5;

/// How many components `info` lists one by one (text and JSON).
constexpr std::size_t kListedComponents = 20;

/// The volume line: the sum over closed components, or "open".
std::string volume_text(const MeshStatistics& st) {
  if (st.closed_components == 0) return "open (no closed component)";
  std::string t = fmt(st.volume, 6);
  if (st.closed_components < st.components)
    t += " (" + std::to_string(st.closed_components) + " closed of " + std::to_string(st.components) +
         " components; the open ones have none)";
  return t;
}

/// The genus line: the number, with the boundary loops it was counted with; "-" where undefined.
std::string genus_text(const MeshStatistics& st) {
  if (st.genus < 0) return "- (not defined: a component is non-manifold or non-orientable)";
  std::string t = std::to_string(st.genus);
  if (st.boundary_loops > 0)
    t += " (surface with " + std::to_string(st.boundary_loops) +
         (st.boundary_loops == 1 ? " boundary loop)" : " boundary loops)");
  return t;
}

Json component_json(const ComponentStatistics& c) {
  Json j;
  j.add("faces", static_cast<long long>(c.faces))
      .add("vertices", static_cast<long long>(c.vertices))
      .add("edges", static_cast<long long>(c.edges))
      .add("area", c.area)
      .add("closed", c.closed)
      .add("manifold", c.manifold)
      .add("orientable", c.orientable)
      .add("consistently_oriented", c.consistently_oriented);
  if (c.closed && c.orientable)
    j.add("volume", c.volume);
  else
    j.raw("volume", "null");
  j.add("euler_characteristic", static_cast<long long>(c.euler_characteristic))
      .add("boundary_loops", static_cast<long long>(c.boundary_loops));
  if (c.genus >= 0)
    j.add("genus", static_cast<long long>(c.genus));
  else
    j.raw("genus", "null");
  return j;
}

std::string join_vector(const Eigen::RowVector3d& v) { return fmt(v(0), 6) + " " + fmt(v(1), 6) + " " + fmt(v(2), 6); }

void run(const Args& a) {
  ReadNotes notes;
  const Mesh mesh = read_mesh(a.input, notes);
  const Eigen::Index dropped = notes.dropped_degenerate;
  const Topology topo = build_topology(mesh.F, mesh.V.rows());
  const TopologySummary s = summarize_topology(mesh.F, topo);
  const double mean_edge = mean_edge_length(mesh.V, mesh.F);
  const Eigen::RowVector3d bb_min = mesh.V.colwise().minCoeff(), bb_max = mesh.V.colwise().maxCoeff();
  const double diagonal = (bb_max - bb_min).norm();
  const MeshStatistics st = mesh_statistics(mesh.V, mesh.F);

  std::vector<std::size_t> loop_sizes;
  for (const auto& loop : s.boundary_loops) loop_sizes.push_back(loop.size());
  std::sort(loop_sizes.rbegin(), loop_sizes.rend());
  const std::size_t shown = std::min(loop_sizes.size(), kLargestLoops);

  if (a.json) {
    auto vec = [](const Eigen::RowVector3d& v) { return std::vector<double>{v(0), v(1), v(2)}; };
    std::string sizes = "[";
    for (std::size_t i = 0; i < shown; ++i) sizes += (i ? "," : "") + std::to_string(loop_sizes[i]);
    sizes += "]";
    Json j;
    j.add("file", a.input)
        .add("vertices", static_cast<long long>(mesh.V.rows()))
        .add("faces", static_cast<long long>(mesh.F.rows()))
        .add("edges", static_cast<long long>(topo.num_edges()))
        .add("boundary_edges", static_cast<long long>(s.boundary_edges))
        .add("boundary_loops", static_cast<long long>(s.boundary_loops.size()))
        .raw("largest_boundary_loops", sizes)
        .add("non_manifold_edges", static_cast<long long>(s.non_manifold_edges))
        .add("non_manifold_vertices", static_cast<long long>(s.non_manifold_vertices))
        .add("unreferenced_vertices", static_cast<long long>(s.unreferenced_vertices))
        .add("inconsistently_oriented_edges", static_cast<long long>(s.inconsistently_oriented_edges))
        .add("components", static_cast<long long>(s.components))
        .add("mean_edge_length", mean_edge)
        .add("bbox_min", vec(bb_min))
        .add("bbox_max", vec(bb_max))
        .add("bbox_diagonal", diagonal)
        .add("dropped_degenerate_faces", static_cast<long long>(dropped))
        .add("vertex_colors", mesh.vertex_colors.size() > 0)
        .add("texture_coordinates", mesh.uv.size() > 0)
        .add("texture_coordinates_with_seams", notes.uv_seams)
        .add("vertex_normals", notes.had_normals)
        .add("area", st.area);
    if (st.closed_components > 0)
      j.add("volume", st.volume);
    else
      j.raw("volume", "null");
    j.add("closed_components", static_cast<long long>(st.closed_components))
        .add("watertight", st.watertight)
        .add("euler_characteristic", static_cast<long long>(st.euler_characteristic));
    if (st.genus >= 0)
      j.add("genus", static_cast<long long>(st.genus));
    else
      j.raw("genus", "null");
    std::vector<Json> parts;
    for (std::size_t i = 0; i < std::min(st.per_component.size(), kListedComponents); ++i)
      parts.push_back(component_json(st.per_component[i]));
    j.add("component_details", parts);
    std::cout << j.str() << "\n";
    return;
  }

  std::string loops = std::to_string(s.boundary_loops.size());
  if (shown > 0) {
    loops += shown < loop_sizes.size() ? " (largest " : " (sizes ";
    for (std::size_t i = 0; i < shown; ++i) loops += (i ? ", " : "") + std::to_string(loop_sizes[i]);
    loops += " edges)";
  }
  if (a.quiet) return;
  std::cout << a.input << "\n"
            << "  vertices:                      " << mesh.V.rows() << "\n"
            << "  faces:                         " << mesh.F.rows() << "\n"
            << "  edges:                         " << topo.num_edges() << "\n"
            << "  boundary edges:                " << s.boundary_edges << "\n"
            << "  boundary loops:                " << loops << "\n"
            << "  non-manifold edges:            " << s.non_manifold_edges << "\n"
            << "  non-manifold vertices:         " << s.non_manifold_vertices << "\n"
            << "  unreferenced vertices:         " << s.unreferenced_vertices << "\n"
            << "  inconsistently oriented edges: " << s.inconsistently_oriented_edges << "\n"
            << "  connected components:          " << s.components << "\n"
            << "  surface area:                  " << fmt(st.area, 6) << "\n"
            << "  volume:                        " << volume_text(st) << "\n"
            << "  watertight:                    " << (st.watertight ? "yes" : "no") << "\n"
            << "  Euler characteristic:          " << st.euler_characteristic << "\n"
            << "  genus:                         " << genus_text(st) << "\n"
            << "  mean edge length:              " << fmt(mean_edge, 6) << "\n"
            << "  bounding box min:              " << join_vector(bb_min) << "\n"
            << "  bounding box max:              " << join_vector(bb_max) << "\n"
            << "  bounding box diagonal:         " << fmt(diagonal, 6) << "\n"
            << "  dropped degenerate faces:      " << dropped << "\n";
  if (mesh.vertex_colors.size() > 0) std::cout << "  vertex colours:                yes\n";
  if (mesh.uv.size() > 0) std::cout << "  texture coordinates:           yes (per vertex)\n";
  if (notes.uv_seams) std::cout << "  texture coordinates:           with seams (per corner; kept by every command)\n";
  if (notes.had_normals) std::cout << "  vertex normals:                yes (recomputed when vertices move)\n";
  if (st.per_component.size() > 1) {
    std::cout << "  components (in the order of their first face; "
              << std::min(st.per_component.size(), kListedComponents) << " of " << st.per_component.size() << "):\n";
    for (std::size_t i = 0; i < std::min(st.per_component.size(), kListedComponents); ++i) {
      const ComponentStatistics& c = st.per_component[i];
      std::cout << "    " << i << ": " << c.faces << " faces, area " << fmt(c.area, 6) << ", "
                << (c.closed
                        ? (c.orientable ? "closed, volume " + fmt(c.volume, 6) : std::string("closed, non-orientable"))
                        : std::to_string(c.boundary_loops) + " boundary loops")
                << ", genus " << (c.genus >= 0 ? std::to_string(c.genus) : std::string("-")) << "\n";
    }
  }
}

const Registrar kRegistration("info", 10, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c = app.add_subcommand(
      "info",
      "Counts, defects (boundaries, non-manifold parts), size, area, volume, watertightness and genus of a mesh");
  c->add_option("input", a->input, "Mesh file (obj, off, ply, stl)")->required();
  c->add_flag("--json", a->json, "Print one JSON object instead of the summary");
  add_quiet_flag(c, a->quiet);
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
