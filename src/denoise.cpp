#include "msmesh/denoise.h"

#include <chrono>
#include <cmath>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/memory.h"
#include "msmesh/mesh.h"
#include "msmesh/topology.h"

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

}  // namespace

void DenoiseOptions::validate() const {
  if (method == DenoiseMethod::Bilateral) {
    bilateral.validate();
  } else {
    normals.validate();
    vertices.validate();
  }
}

std::vector<std::string> preset_names() { return {"cad", "smooth", "auto"}; }

DenoiseOptions preset_options(const std::string& name) {
  DenoiseOptions o;
  // Units: mean edge length 1 (DESIGN.md §"Scale"). See docs/presets.md for how these
  // values were chosen on the public test meshes.
  if (name == "cad") {
    o.normals.alpha = 2.5;
    o.normals.beta = 0.02;
    o.normals.gamma = 2.0;
    o.normals.rho = 0.1;
    o.normals.penalty = 2.0;
    o.vertices.omega2 = 0.03;
    o.vertices.omega3 = 0.1;
  } else if (name == "smooth") {
    o.normals.alpha = 2.0;
    o.normals.beta = 2.0;      // v ≈ 1 everywhere: the edge field only hurts organic shapes
    o.normals.gamma = 2.0;
    o.normals.rho = 0.9;
    o.normals.penalty = 0.1;   // slow ADMM = 30 iterations stop well short of the TV staircase
    o.vertices.omega2 = 0.3;
    o.vertices.omega3 = 0.3;
  } else {
    throw InvalidInput("unknown preset '" + name + "'; valid: cad, smooth, auto");
  }
  return o;
}

PresetChoice choose_preset(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  validate_mesh(V, F, "preset choice");
  PresetChoice c;
  // Pre-smooth the normals with bilateral passes, then look at the dihedral angles of the
  // smoothed normals, weighted by edge length. CAD parts (and scans of them) have either a
  // clear set of strong creases (> 30°) or mostly flat regions (< 1°); organic shapes have
  // neither. Thresholds measured on the 17 public noisy meshes (docs/presets.md).
  BilateralOptions bo;
  bo.normal_iterations = 15;
  const Eigen::MatrixXd N = bilateral_filter_normals(V, F, bo);
  const Eigen::MatrixXd N0 = face_normals(V, F);
  const Topology t = build_topology(F, V.rows());
  const Eigen::VectorXd len = edge_lengths(V, t);
  double total = 0, flat = 0, sharp = 0, raw_dev = 0;
  for (Eigen::Index e = 0; e < t.num_edges(); ++e) {
    if (!t.edge_is_interior[e]) continue;
    const double a = std::acos(std::clamp(N.row(t.edge_faces(e, 0)).dot(N.row(t.edge_faces(e, 1))), -1.0, 1.0));
    total += len(e);
    if (a < 1.0 * M_PI / 180) flat += len(e);
    if (a > 30.0 * M_PI / 180) sharp += len(e);
  }
  for (Eigen::Index f = 0; f < F.rows(); ++f) raw_dev += std::acos(std::clamp(N.row(f).dot(N0.row(f)), -1.0, 1.0));
  c.sharp_fraction = total > 0 ? sharp / total : 0;
  c.flat_fraction = total > 0 ? flat / total : 0;
  c.noise_level = F.rows() ? raw_dev / double(F.rows()) : 0;
  c.preset = (c.sharp_fraction >= 0.03 || c.flat_fraction >= 0.5) ? "cad" : "smooth";
  return c;
}

double denoise_memory_estimate(Eigen::Index num_vertices, Eigen::Index num_faces, const DenoiseOptions& o) {
  const double per_face = o.method == DenoiseMethod::Bilateral ? kBilateralBytesPerFace : kBytesPerFace;
  return per_face * static_cast<double>(num_faces) + kBytesPerVertex * static_cast<double>(num_vertices);
}

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
  if (o.method == DenoiseMethod::Bilateral) {
    r.normals = bilateral_filter_normals(V, F, o.bilateral, progress);
    const auto t1 = clock::now();
    r.V = classic_vertex_update(V, F, r.normals, o.bilateral.vertex_iterations, progress);
    keep_unreferenced(V, F, r.V);
    r.seconds_normals = std::chrono::duration<double>(t1 - t0).count();
    r.seconds_vertices = std::chrono::duration<double>(clock::now() - t1).count();
    return r;
  }
  NormalFilterOptions no = o.normals;
  no.reweight = (o.method == DenoiseMethod::NMSTV);
  r.normal_report = filter_normals(V, F, no, {}, progress);
  r.normals = r.normal_report.normals;
  r.v = r.normal_report.v;
  const auto t1 = clock::now();
  r.vertex_report = update_vertices(V, F, r.normals, r.v.cwiseMax(0.0).cwiseMin(1.0), o.vertices, {}, progress);
  r.V = r.vertex_report.V;
  keep_unreferenced(V, F, r.V);
  r.seconds_normals = std::chrono::duration<double>(t1 - t0).count();
  r.seconds_vertices = std::chrono::duration<double>(clock::now() - t1).count();
  return r;
}

}  // namespace msmesh
