#include "msmesh/denoise.h"

#include <chrono>
#include <cmath>
#include <utility>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/memory.h"
#include "msmesh/mesh.h"
#include "msmesh/prepared_mesh.h"
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
  // Checked, normalised and connected once for both stages.
  const PreparedMesh mesh(V, F, "denoise");
  NormalFilterOptions no = o.normals;
  no.reweight = (o.method == DenoiseMethod::NMSTV);
  NormalFilterResult nr = filter_normals(mesh, no, {}, progress);
  r.normals = std::move(nr.normals);
  r.v = std::move(nr.v);
  r.edges = std::move(nr.edges);
  r.normal_report = std::move(static_cast<NormalFilterStats&>(nr));
  const auto t1 = clock::now();
  VertexUpdateResult vr = update_vertices(mesh, r.normals, r.v.cwiseMax(0.0).cwiseMin(1.0), o.vertices, {}, progress);
  r.V = std::move(vr.V);
  r.vertex_report = std::move(static_cast<VertexUpdateStats&>(vr));
  keep_unreferenced(V, F, r.V);
  r.seconds_normals = std::chrono::duration<double>(t1 - t0).count();
  r.seconds_vertices = std::chrono::duration<double>(clock::now() - t1).count();
  return r;
}

}  // namespace msmesh
