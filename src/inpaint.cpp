// Inpainting (inpaint.h): the options, and the driver that selects the holes, fills them with
// CGAL (hole_fill.h) and hands those a crease runs into to the feature recovery
// (feature_recovery.h).
#include "msmesh/inpaint.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <utility>

#include "feature_recovery.h"
#include "format_number.h"
#include "hole_fill.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/memory.h"
#include "msmesh/mesh.h"
#include "msmesh/parameters.h"
#include "msmesh/presets.h"
#include "msmesh/topology.h"

namespace msmesh {

using detail::crease_enters;
using detail::FilledHole;
using detail::num;
using detail::recover_features;

NormalFilterOptions InpaintOptions::default_normal_options() { return inpaint_normal_options(); }

VertexUpdateOptions InpaintOptions::default_vertex_options() { return inpaint_vertex_options(); }

const char* hole_action_name(HoleAction action) {
  switch (action) {
    case HoleAction::Filled:
      return "filled";
    case HoleAction::Skipped:
      return "skipped";
    case HoleAction::Failed:
      return "failed";
  }
  return "unknown";
}

void InpaintOptions::validate() const {
  for (int i : holes)
    if (i < 0) throw InvalidInput("inpainting: hole index " + std::to_string(i) + " is out of range; valid: >= 0");
  check_parameters(inpaint_parameters(), *this);  // with the normal filter's and vertex update's
}

double fill_density(const InpaintOptions& o) {
  return o.density > 0 ? o.density : (o.recover_features ? o.feature_density : std::sqrt(2.0));
}

double inpaint_memory_estimate(const std::vector<Hole>& holes, const InpaintOptions& o) {
  // CGAL refines a patch to about the density of the mesh around it times density²: an
  // equilateral triangle of edge 1/d covers √3/(4d²) squared mean edge lengths. About 1000
  // bytes per new face were measured for the fill and the feature recovery (as for denoising).
  const double d = fill_density(o);
  double faces = 0;
  for (const Hole& h : holes) faces += h.spanned_area * d * d * (4.0 / std::sqrt(3.0)) + h.edges;
  return 1000.0 * faces;
}

InpaintResult inpaint(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const InpaintOptions& o,
                      const ProgressCallback& progress) {
  o.validate();
  validate_mesh(V, F, "inpainting");
  InpaintResult res;
  res.V = V;
  res.F = F;
  res.new_faces.assign(static_cast<size_t>(F.rows()), false);
  res.new_vertices.assign(static_cast<size_t>(V.rows()), false);
  res.holes = find_holes(V, F);
  const auto nh = static_cast<int>(res.holes.size());
  for (int i : o.holes)
    if (i >= nh) {
      std::ostringstream os;
      os << "inpainting: hole index " << i << " does not exist (the mesh has " << nh << " holes)";
      throw InvalidInput(os.str());
    }
  res.reports.resize(res.holes.size());
  std::vector<int> selected;  // indices of holes handed to CGAL
  std::vector<bool> listed(res.holes.size(), o.holes.empty());
  for (int i : o.holes) listed[i] = true;
  for (int i = 0; i < nh; ++i) {
    const Hole& hole = res.holes[i];
    HoleReport& r = res.reports[i];
    r.index = i;
    r.action = HoleAction::Skipped;
    if (!listed[i]) {
      r.reason = "not in the list of holes to fill";
    } else if (!hole.simple) {
      r.reason =
          "its boundary touches itself at vertex " + std::to_string(hole.touching_vertex) + " (not a simple loop)";
    } else if (o.holes.empty() && hole.outer_boundary && !o.fill_outer_boundary) {
      r.reason = "outer boundary of an open surface (diameter " + num(hole.diameter) +
                 " mean edge lengths, at least half its component's bounding-box diagonal)";
    } else if (o.holes.empty() && o.max_hole_edges > 0 && hole.edges > o.max_hole_edges) {
      r.reason = std::to_string(hole.edges) + " boundary edges > max_hole_edges " + std::to_string(o.max_hole_edges);
    } else if (o.holes.empty() && o.max_hole_diameter > 0 && hole.diameter > o.max_hole_diameter) {
      r.reason =
          "diameter " + num(hole.diameter) + " mean edge lengths > max_hole_diameter " + num(o.max_hole_diameter);
    } else {
      selected.push_back(i);
    }
  }

  std::vector<Hole> chosen;
  for (int i : selected) chosen.push_back(res.holes[i]);
  check_memory(inpaint_memory_estimate(chosen, o),
               "inpainting " + std::to_string(chosen.size()) + " hole(s) at fill density " + num(fill_density(o)));

  const auto t0 = std::chrono::steady_clock::now();
  std::vector<FilledHole> filled;
  if (!selected.empty()) {
    std::vector<std::vector<int>> loops;
    for (int i : selected) loops.push_back(res.holes[i].loop);
    const double density = fill_density(o);
    detail::CgalFillResult fill = detail::fill_holes_cgal(V, F, loops, density, true);
    for (size_t s = 0; s < selected.size(); ++s) {
      const detail::CgalHoleOutcome& out = fill.holes[s];
      HoleReport& r = res.reports[selected[s]];
      if (out.filled) {
        r.action = HoleAction::Filled;
        r.new_faces = out.face_count;
        r.new_vertices = out.vertex_count;
        r.faired = out.faired;
        FilledHole fh;
        fh.index = selected[s];
        fh.loop = &res.holes[selected[s]].loop;
        fh.first_face = out.first_face;
        fh.face_count = out.face_count;
        fh.first_vertex = out.first_vertex;
        fh.vertex_count = out.vertex_count;
        filled.push_back(fh);
      } else {
        r.action = HoleAction::Failed;
        r.reason = out.error;
      }
    }
    res.V = std::move(fill.V);
    res.F = std::move(fill.F);
    res.new_faces.assign(static_cast<size_t>(res.F.rows()), false);
    res.new_vertices.assign(static_cast<size_t>(res.V.rows()), false);
    for (Eigen::Index f = F.rows(); f < res.F.rows(); ++f) res.new_faces[f] = true;
    for (Eigen::Index i = V.rows(); i < res.V.rows(); ++i) res.new_vertices[i] = true;
  }
  for (const HoleReport& r : res.reports) {
    if (r.action == HoleAction::Filled)
      ++res.filled;
    else if (r.action == HoleAction::Skipped)
      ++res.skipped;
    else
      ++res.failed;
  }
  const auto t1 = std::chrono::steady_clock::now();
  res.seconds_fill = std::chrono::duration<double>(t1 - t0).count();

  if (o.recover_features && !filled.empty()) {
    // Which holes have a crease running into them (the others keep CGAL's smooth fair patch,
    // which is what a smooth surface wants: docs/inpainting.md).
    const Topology topo = build_topology(F, V.rows());
    const Eigen::VectorXd dihedral = dihedral_angles(V, F, topo);
    std::vector<std::vector<int>> vertex_edges(static_cast<size_t>(V.rows()));
    for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
      vertex_edges[topo.edges(e, 0)].push_back(static_cast<int>(e));
      vertex_edges[topo.edges(e, 1)].push_back(static_cast<int>(e));
    }
    std::vector<FilledHole> featured;
    for (FilledHole& h : filled) {
      HoleReport& r = res.reports[h.index];
      double weakest = 180;
      const bool yes = crease_enters(*h.loop, topo, dihedral, vertex_edges, o, r.features_reason, weakest);
      h.jump_angle = o.smooth_jump_angle > 0 ? o.smooth_jump_angle : std::clamp(0.75 * weakest, 20.0, 60.0);
      r.features = o.all_holes_featured || yes;
      if (o.all_holes_featured && !yes) r.features_reason += " (forced)";
      // A patch without new vertices can still gain from the crease flips.
      if (r.features) featured.push_back(h);
    }
    res.featured = static_cast<int>(featured.size());
    if (!featured.empty()) recover_features(res.V, res.F, V.rows(), F.rows(), featured, o, progress, res);
  }
  res.seconds_features = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  return res;
}

}  // namespace msmesh
