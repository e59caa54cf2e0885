#include "msmesh/presets.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "msmesh/bilateral.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/topology.h"

namespace msmesh {

namespace {

// The "auto" rule's thresholds (docs/presets.md, measured on the 17 public noisy meshes).
constexpr double kCreaseAngleDeg = 30.0;     // a pre-smoothed dihedral above this is a crease
constexpr double kFlatAngleDeg = 1.0;        // ... below this, flat
constexpr double kCadCreaseFraction = 0.03;  // cad when creases make at least this much edge length
constexpr double kCadFlatFraction = 0.5;     // ... or flat edges at least this much
constexpr int kPreSmoothingPasses = 15;      // bilateral passes before measuring

std::string fixed(double x, int digits) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(digits);
  os << x;
  return os.str();
}

}  // namespace

std::vector<std::string> preset_names() { return {"cad", "smooth"}; }

const char* default_preset() { return "auto"; }

DenoiseOptions preset_options(const std::string& name) {
  // Units: mean edge length 1 (DESIGN.md §"Scale"). docs/presets.md says how these values were
  // chosen on the public test meshes.
  DenoiseOptions o;  // the struct defaults are "cad": α 2.5, β 0.02, γ 2, ρ 0.1, r 2, ω₂ 0.03, ω₃ 0.1
  if (name == "cad") return o;
  if (name == "smooth") {
    o.normals.alpha = 2.0;
    o.normals.beta = 2.0;  // v ≈ 1 everywhere: the edge field only hurts organic shapes
    o.normals.gamma = 2.0;
    o.normals.rho = 0.9;
    o.normals.penalty = 0.1;  // slow ADMM = 30 iterations stop well short of the TV staircase
    o.vertices.omega2 = 0.3;
    o.vertices.omega3 = 0.3;
    return o;
  }
  if (name == "auto") throw InvalidInput("preset 'auto' is chosen from the mesh: use resolve_preset(\"auto\", V, F)");
  throw InvalidInput("unknown preset '" + name + "'; valid: auto, cad, smooth");
}

PresetChoice choose_preset(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  validate_mesh(V, F, "preset choice");
  PresetChoice c;
  // Pre-smooth the normals with bilateral passes, then look at the dihedral angles of the
  // smoothed normals, weighted by edge length. CAD parts (and scans of them) have either a
  // clear set of strong creases or mostly flat regions; organic shapes have neither.
  BilateralOptions bo;
  bo.normal_iterations = kPreSmoothingPasses;
  const Eigen::MatrixXd N = bilateral_filter_normals(V, F, bo);
  const Eigen::MatrixXd N0 = face_normals(V, F);
  const Topology t = build_topology(F, V.rows());
  const Eigen::VectorXd len = edge_lengths(V, t);
  double total = 0, flat = 0, sharp = 0, raw_dev = 0;
  for (Eigen::Index e = 0; e < t.num_edges(); ++e) {
    if (!t.edge_is_interior[e]) continue;
    const double a = std::acos(std::clamp(N.row(t.edge_faces(e, 0)).dot(N.row(t.edge_faces(e, 1))), -1.0, 1.0));
    total += len(e);
    if (a < kFlatAngleDeg * M_PI / 180) flat += len(e);
    if (a > kCreaseAngleDeg * M_PI / 180) sharp += len(e);
  }
  for (Eigen::Index f = 0; f < F.rows(); ++f) raw_dev += std::acos(std::clamp(N.row(f).dot(N0.row(f)), -1.0, 1.0));
  c.sharp_fraction = total > 0 ? sharp / total : 0;
  c.flat_fraction = total > 0 ? flat / total : 0;
  c.noise_level = F.rows() ? raw_dev / double(F.rows()) : 0;
  const bool creases = c.sharp_fraction >= kCadCreaseFraction, flats = c.flat_fraction >= kCadFlatFraction;
  c.preset = (creases || flats) ? "cad" : "smooth";
  c.reason = "crease fraction " + fixed(c.sharp_fraction, 3) + (creases ? " >= " : " < ") +
             fixed(kCadCreaseFraction, 2) + ", flat fraction " + fixed(c.flat_fraction, 2) + (flats ? " >= " : " < ") +
             fixed(kCadFlatFraction, 2) + (c.preset == "cad" ? ": cad" : ": smooth");
  return c;
}

std::string ResolvedPreset::reason() const {
  if (automatic) return "chosen automatically (" + choice.reason + ")";
  return "requested";
}

ResolvedPreset resolve_preset(const std::string& name, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  ResolvedPreset r;
  r.requested = name;
  if (name == "auto") {
    r.automatic = true;
    r.choice = choose_preset(V, F);
    r.preset = r.choice.preset;
  } else {
    r.preset = name;
  }
  r.options = preset_options(r.preset);
  return r;
}

NormalFilterOptions segment_normal_options() { return preset_options("cad").normals; }

NormalFilterOptions inpaint_normal_options() {
  NormalFilterOptions o;
  o.alpha = 2.0;
  o.beta = 0.02;
  o.gamma = 0.5;
  o.rho = 0.1;
  o.penalty = 1.0;
  // Inside a hole the fidelity is ~0, so only the unit-length projection keeps the normals
  // from shrinking towards their average across a crease (the relaxed problem is then a
  // vector TV whose minimiser blends the two sides): project after every N-step, as the paper.
  o.project_each_iteration = true;
  return o;
}

VertexUpdateOptions inpaint_vertex_options() {
  VertexUpdateOptions o;
  o.omega1 = 1.0;
  o.omega2 = 0.0;
  o.omega3 = 0.1;
  o.max_iterations = 60;
  return o;
}

}  // namespace msmesh
