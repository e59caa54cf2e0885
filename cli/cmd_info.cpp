// msmesh info: counts, defects and size of a mesh, as read (after triangulation and dropping
// degenerate faces).
#include <algorithm>
#include <iostream>
#include <memory>

#include "command.h"
#include "json.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/io.h"
#include "msmesh/topology.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::string input;
  bool json = false, quiet = false;
};

/// How many of the largest boundary loops to list.
constexpr std::size_t kLargestLoops = 5;

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
        .add("texture_coordinates_with_seams", notes.uv_dropped)
        .add("vertex_normals", notes.had_normals);
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
            << "  mean edge length:              " << fmt(mean_edge, 6) << "\n"
            << "  bounding box min:              " << join_vector(bb_min) << "\n"
            << "  bounding box max:              " << join_vector(bb_max) << "\n"
            << "  bounding box diagonal:         " << fmt(diagonal, 6) << "\n"
            << "  dropped degenerate faces:      " << dropped << "\n";
  if (mesh.vertex_colors.size() > 0) std::cout << "  vertex colours:                yes\n";
  if (mesh.uv.size() > 0) std::cout << "  texture coordinates:           yes (per vertex)\n";
  if (notes.uv_dropped)
    std::cout << "  texture coordinates:           with seams (per corner): not read, not carried over\n";
  if (notes.had_normals) std::cout << "  vertex normals:                yes (recomputed when vertices move)\n";
}

const Registrar kRegistration("info", 10, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c = app.add_subcommand("info", "Counts, defects (boundaries, non-manifold parts) and size of a mesh");
  c->add_option("input", a->input, "Mesh file (obj, off, ply, stl)")->required();
  c->add_flag("--json", a->json, "Print one JSON object instead of the summary");
  add_quiet_flag(c, a->quiet);
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
