#include "msmesh/denoise.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "jet_targets.h"
#include "mesh_components.h"
#include "msmesh/despike.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/memory.h"
#include "msmesh/mesh.h"
#include "msmesh/parameters.h"
#include "msmesh/prepared_mesh.h"
#include "msmesh/taubin.h"
#include "msmesh/topology.h"
#include "planar_regions.h"
#include "retargeted_update.h"
#include "sub_mesh.h"
#include "unreachable_targets.h"

namespace msmesh {

namespace {
// Peak resident memory of denoising, rounded down from measurements (fandisk, 42k and 264k
// faces, /usr/bin/time max RSS of msmesh denoise, including reading): NMSTV ~1160 bytes per
// face, bilateral ~230. Lower estimates, so that only hopeless cases are refused.
constexpr double kBytesPerFace = 1000.0;
constexpr double kBilateralBytesPerFace = 200.0;
constexpr double kBytesPerVertex = 0.0;  // included in the per-face figures (#V ~ #F/2)

/// Vertices no face refers to come back bit for bit (the scale normalisation round trip
/// would otherwise move them by an ulp).
void keep_unreferenced(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, Eigen::MatrixXd& out) {
  std::vector<bool> used(static_cast<std::size_t>(V.rows()), false);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) used[static_cast<std::size_t>(F(f, k))] = true;
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    if (!used[static_cast<std::size_t>(i)]) out.row(i) = V.row(i);
}

/// Components whose mean edge lengths differ by more than this are denoised one by one, each
/// with its own scale normalisation: together, the small part's systems are below the
/// solvers' tolerance relative to the large part's ("v-step conjugate gradient did not
/// converge" on a bolt beside a 1e-5 washer).
constexpr double kComponentScaleRatio = 100.0;

/// True when the mean edge lengths of the components differ by more than kComponentScaleRatio.
bool components_differ_in_scale(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::vector<int>& label,
                                int count) {
  std::vector<double> sum(static_cast<std::size_t>(count), 0.0);
  std::vector<long long> n(static_cast<std::size_t>(count), 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      sum[static_cast<std::size_t>(label[f])] += (V.row(F(f, k)) - V.row(F(f, (k + 1) % 3))).norm();
      ++n[static_cast<std::size_t>(label[f])];
    }
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (int c = 0; c < count; ++c) {
    const double mean = sum[c] / static_cast<double>(n[c]);
    if (!(mean > 0)) continue;
    lo = std::min(lo, mean);
    hi = std::max(hi, mean);
  }
  return hi > kComponentScaleRatio * lo;
}

}  // namespace

void DenoiseOptions::validate() const {
  if (method == DenoiseMethod::Bilateral) {
    bilateral.validate();
  } else {
    normals.validate();
    vertices.validate();
    check_parameter(find_parameter(denoise_parameters(), "prefilter")->info, prefilter_iterations);
    check_parameter(find_parameter(denoise_parameters(), "despike")->info, despike_threshold);
    check_parameter(find_parameter(denoise_parameters(), "planes")->info, plane_min_faces);
    check_parameter(find_parameter(denoise_parameters(), "jet-rings")->info, jet_rings);
    check_parameter(find_parameter(denoise_parameters(), "unreachable-angle")->info, unreachable_angle);
    check_parameter(find_parameter(denoise_parameters(), "min-component-faces")->info, min_component_faces);
  }
}

double denoise_memory_estimate(Eigen::Index num_vertices, Eigen::Index num_faces, const DenoiseOptions& o) {
  const double per_face = o.method == DenoiseMethod::Bilateral ? kBilateralBytesPerFace : kBytesPerFace;
  return per_face * static_cast<double>(num_faces) + kBytesPerVertex * static_cast<double>(num_vertices);
}

namespace {

/// The denoised sub-mesh `sub` of the faces `faces` put into `r` in the input's numbering:
/// positions, normals and (with a field) the edge field on the edges `topo` of the whole mesh.
void put_back(const DenoiseResult& part, const detail::SubMesh& sub, const std::vector<Eigen::Index>& faces,
              const Topology& topo, DenoiseResult& r) {
  for (std::size_t i = 0; i < sub.global.size(); ++i) r.V.row(sub.global[i]) = part.V.row(static_cast<Eigen::Index>(i));
  for (std::size_t i = 0; i < faces.size(); ++i)
    r.normals.row(faces[i]) = part.normals.row(static_cast<Eigen::Index>(i));
  if (part.v.size() > 0) {
    const Topology tc = build_topology(sub.F, sub.V.rows());
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (int k = 0; k < 3; ++k)
        r.v(topo.face_edges(faces[i], k)) = part.v(tc.face_edges(static_cast<Eigen::Index>(i), k));
  }
  r.seconds_normals += part.seconds_normals;
  r.seconds_vertices += part.seconds_vertices;
  r.despiked_vertices += part.despiked_vertices;
  r.planar_regions += part.planar_regions;
  r.planar_faces += part.planar_faces;
  r.jet_faces += part.jet_faces;
  r.unreachable_faces += part.unreachable_faces;
}

/// The result of denoising some groups of faces (each group on its own, with its own scale
/// normalisation), every other face kept as it is: the input's positions and face normals, and
/// an edge field of 1 (no feature). The reports are those of the group with the most faces.
DenoiseResult denoise_groups(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                             const std::vector<std::vector<Eigen::Index>>& groups, const DenoiseOptions& o,
                             const ProgressCallback& progress) {
  DenoiseResult r;
  r.V = V;
  r.normals = face_normals(V, F);
  const Topology topo = build_topology(F, V.rows());
  if (o.method != DenoiseMethod::Bilateral) {
    r.v = Eigen::VectorXd::Ones(topo.num_edges());
    r.edges = topo.edges;
  }
  std::vector<int> local(static_cast<std::size_t>(V.rows()), -1);
  std::size_t largest = 0;
  for (const std::vector<Eigen::Index>& faces : groups) {
    if (faces.empty()) continue;
    const detail::SubMesh sub = detail::sub_mesh(V, F, faces, local);
    if (!(mean_edge_length(sub.V, sub.F) > 0)) continue;  // all faces degenerate: nothing to scale, kept as it is
    DenoiseResult part = denoise(sub.V, sub.F, o, progress);
    put_back(part, sub, faces, topo, r);
    if (faces.size() > largest) {
      largest = faces.size();
      r.normal_report = std::move(part.normal_report);
      r.vertex_report = std::move(part.vertex_report);
    }
  }
  return r;
}

}  // namespace

DenoiseResult denoise(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const DenoiseOptions& o,
                      const ProgressCallback& progress) {
  o.validate();
  validate_mesh(V, F, "denoise");
  check_memory(denoise_memory_estimate(V.rows(), F.rows(), o),
               "denoise (" + std::to_string(V.rows()) + " vertices, " + std::to_string(F.rows()) + " faces)");
  DenoiseResult r;
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  if (F.rows() == 0) {
    r.V = V;
    return r;
  }
  int components = 0;
  const std::vector<int> label = detail::face_component_labels(F, V.rows(), components);
  if (o.method != DenoiseMethod::Bilateral && o.min_component_faces > 1) {
    detail::ComponentSplit split = detail::split_small_components(label, components, o.min_component_faces);
    if (split.small_faces > 0) {
      // The large components are denoised as a mesh of their own (the rules below apply to it),
      // the small ones kept.
      DenoiseOptions large = o;
      large.min_component_faces = 0;
      DenoiseResult kept = denoise_groups(V, F, {std::move(split.large_faces)}, large, progress);
      kept.kept_components = split.small_components;
      kept.kept_faces = split.small_faces;
      return kept;
    }
  }
  if (components > 1 && components_differ_in_scale(V, F, label, components)) {
    std::vector<std::vector<Eigen::Index>> groups(static_cast<std::size_t>(components));
    for (Eigen::Index f = 0; f < F.rows(); ++f) groups[static_cast<std::size_t>(label[f])].push_back(f);
    return denoise_groups(V, F, groups, o, progress);
  }
  if (o.method == DenoiseMethod::Bilateral) {
    r.normals = bilateral_filter_normals(V, F, o.bilateral, progress);
    const auto t1 = clock::now();
    r.V = classic_vertex_update(V, F, r.normals, o.bilateral.vertex_iterations, progress);
    keep_unreferenced(V, F, r.V);
    r.seconds_normals = std::chrono::duration<double>(t1 - t0).count();
    r.seconds_vertices = std::chrono::duration<double>(clock::now() - t1).count();
    return r;
  }
  DespikeResult spikes;
  if (o.despike_threshold > 0) spikes = despike(V, F, o.despike_threshold);
  // Checked, normalised and connected once for both stages.
  const PreparedMesh mesh(o.despike_threshold > 0 ? spikes.V : V, F, "denoise");
  r.despiked_vertices = spikes.moved;
  NormalFilterOptions no = o.normals;
  no.reweight = (o.method == DenoiseMethod::NMSTV);
  Eigen::MatrixXd normals0;  // empty: the input's face normals
  if (o.prefilter_iterations > 0) {
    TaubinOptions to;
    to.iterations = o.prefilter_iterations;
    normals0 = face_normals(taubin_smooth(mesh.positions(), mesh.faces(), to), mesh.faces());
  }
  NormalFilterResult nr = filter_normals(mesh, no, {}, progress, normals0);
  r.normals = std::move(nr.normals);
  const detail::PlanarRegions planes = detail::snap_planar_regions(mesh, r.normals, o.plane_min_faces);
  r.planar_regions = planes.regions;
  r.planar_faces = planes.faces;
  r.v = std::move(nr.v);
  r.edges = std::move(nr.edges);
  r.normal_report = std::move(static_cast<NormalFilterStats&>(nr));
  const auto t1 = clock::now();
  // Jet-fitted targets and unreachable ones: after the update, second-order targets from its
  // positions, the targets it could not reach dropped, and the update again from there on the
  // system it built.
  detail::Retarget retarget;
  detail::UnreachableTargets dropped;
  std::vector<std::pair<Eigen::Index, Eigen::RowVector3d>> dropped_targets;
  if (o.jet_rings > 0 || o.unreachable_angle > 0)
    retarget = [&](const Eigen::MatrixXd& X, Eigen::MatrixXd& N) {
      dropped = detail::unreachable_targets(X, mesh.faces(), N, o.unreachable_angle);
      r.unreachable_faces = dropped.faces;
      if (o.jet_rings > 0) {
        // (no fit for a face whose target is dropped)
        std::vector<bool> fixed = planes.snapped;
        if (dropped.faces > 0) {
          fixed.resize(static_cast<std::size_t>(N.rows()), false);
          for (std::size_t f = 0; f < fixed.size(); ++f) fixed[f] = fixed[f] || dropped.marked[f];
        }
        r.jet_faces = detail::fit_jet_targets(mesh, X, N, o.jet_rings, fixed).faces;
      }
      if (r.jet_faces == 0 && r.unreachable_faces == 0) return false;
      for (Eigen::Index f = 0; f < N.rows(); ++f)
        if (dropped.marked[static_cast<std::size_t>(f)]) dropped_targets.emplace_back(f, N.row(f));
      detail::drop_targets(dropped.marked, N);
      r.normals = N;  // the result's targets (the update read its first ones already)
      return true;
    };
  VertexUpdateResult vr = detail::update_vertices_retargeted(mesh, r.normals, r.v.cwiseMax(0.0).cwiseMin(1.0),
                                                             o.vertices, {}, progress, retarget);
  if (!dropped_targets.empty()) {
    // A dropped target is reported as the normal its face ended with (as it was, if the face
    // collapsed).
    const Eigen::MatrixXd reached = face_normals(vr.V, mesh.faces());
    for (const auto& [f, target] : dropped_targets)
      r.normals.row(f) = reached.row(f).squaredNorm() > 0 ? Eigen::RowVector3d(reached.row(f)) : target;
  }
  r.V = std::move(vr.V);
  r.vertex_report = std::move(static_cast<VertexUpdateStats&>(vr));
  keep_unreferenced(V, F, r.V);
  r.seconds_normals = std::chrono::duration<double>(t1 - t0).count();
  r.seconds_vertices = std::chrono::duration<double>(clock::now() - t1).count();
  return r;
}

}  // namespace msmesh
