#include "msmesh/noise.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/parameters.h"
#include "msmesh/topology.h"
#include "random.h"

namespace msmesh {

const ParameterTable<NoiseOptions>& noise_parameters() {
  using O = NoiseOptions;
  using T = ParameterType;
  static const ParameterTable<O> t = {
      // σ beyond a million mean edge lengths only moves vertices out of any meaningful range
      // (1e308 made every coordinate infinite).
      bind_parameter(
          ParameterInfo{
              "sigma", "σ", "mean edge lengths", T::Real, {0, 1e6}, "standard deviation of the displacement", "noise"},
          &O::sigma),
      bind_parameter(ParameterInfo{"impulsive",
                                   "",
                                   "",
                                   T::Real,
                                   {0, 1},
                                   "displace only this fraction of the vertices (0: every vertex)",
                                   "noise"},
                     &O::impulsive_fraction),
      bind_parameter(ParameterInfo{"seed",
                                   "",
                                   "",
                                   T::Integer,
                                   {0, kLargestExactInteger},
                                   "random seed; the same seed gives the same mesh on any machine",
                                   "noise"},
                     &O::seed),
      bind_parameter(ParameterInfo{"correlation",
                                   "",
                                   "passes",
                                   T::Integer,
                                   {0, 1000},
                                   "average the displacements with their neighbours' this many times (0: white "
                                   "noise), then scale back to sigma: correlated noise like a depth camera's",
                                   "noise"},
                     &O::correlation),
  };
  return t;
}

void NoiseOptions::validate() const {
  check_parameters(noise_parameters(), *this);
  if (direction != NoiseDirection::Normal && direction != NoiseDirection::Random)
    throw InvalidInput("noise: direction must be NoiseDirection::Normal or NoiseDirection::Random");
  if (correlation > 0 && impulsive_fraction > 0)
    throw InvalidInput("noise: correlation (" + std::to_string(correlation) +
                       ") is for Gaussian noise on every vertex; it cannot be combined with impulsive (" +
                       std::to_string(impulsive_fraction) + ")");
}

namespace {

// Averages each displacement with its neighbours' `passes` times, then rescales them to their
// RMS length before (unreferenced vertices have none and no neighbours: they stay at 0). Normal noise stays along the
// normals only approximately after averaging (neighbouring normals differ), as a depth camera's does.
void correlate(Eigen::MatrixXd& D, const Eigen::MatrixXi& F, int passes) {
  const double before = D.squaredNorm();
  const Topology topo = build_topology(F, D.rows());
  Eigen::VectorXd degree = Eigen::VectorXd::Ones(D.rows());
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
    degree(topo.edges(e, 0)) += 1;
    degree(topo.edges(e, 1)) += 1;
  }
  Eigen::MatrixXd next(D.rows(), 3);
  for (int pass = 0; pass < passes; ++pass) {
    next = D;
    for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
      const int a = topo.edges(e, 0), b = topo.edges(e, 1);
      next.row(a) += D.row(b);
      next.row(b) += D.row(a);
    }
    D = next.array().colwise() / degree.array();
  }
  const double after = D.squaredNorm();
  // All displacements cancelled (a single vertex or an exactly balanced draw): nothing to scale.
  if (after > 0) D *= std::sqrt(before / after);
}

}  // namespace

Eigen::MatrixXd add_noise(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const NoiseOptions& options) {
  options.validate();
  validate_mesh(V, F, "noise");
  Eigen::MatrixXd out = V;
  if (options.sigma == 0 || F.rows() == 0) return out;

  // σ is relative to the mean edge length l̄ₑ, as in the literature (DESIGN.md).
  const double stddev = options.sigma * mean_edge_length(V, F);
  const Eigen::MatrixXd N = options.direction == NoiseDirection::Normal ? vertex_normals(V, F) : Eigen::MatrixXd();

  // Only vertices referenced by a face are displaced; isolated ones stay where they are.
  std::vector<bool> referenced(V.rows(), false);
  for (Eigen::Index i = 0; i < F.size(); ++i) referenced[F(i)] = true;
  std::vector<int> candidates;
  candidates.reserve(V.rows());
  for (Eigen::Index v = 0; v < V.rows(); ++v)
    if (referenced[v]) candidates.push_back(int(v));

  detail::Random<detail::Xoshiro256StarStar> rng(options.seed);
  std::vector<int> chosen;
  if (options.impulsive_fraction > 0) {
    // Impulsive: round(fraction × #referenced) distinct vertices (at least one), drawn by a
    // partial Fisher–Yates shuffle, then displaced in increasing index order.
    const auto n = static_cast<std::uint64_t>(candidates.size());
    std::uint64_t k = static_cast<std::uint64_t>(std::llround(options.impulsive_fraction * double(n)));
    k = std::clamp<std::uint64_t>(k, 1, n);
    for (std::uint64_t i = 0; i < k; ++i) std::swap(candidates[i], candidates[i + rng.below(n - i)]);
    chosen.assign(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(k));
    std::sort(chosen.begin(), chosen.end());
  } else {
    chosen = std::move(candidates);
  }

  // The displacement of each chosen vertex. Normal: n·σ·g. Random: u·σ·g with u
  // uniform on the unit sphere, so both modes displace by the same RMS length σ (as
  // bldeng/GuidedDenoising, which generated the public benchmark meshes, does) rather than by σ
  // per component. Drawn and added as before correlation existed, so a seed's white noise is the
  // same to the bit.
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(V.rows(), 3);
  for (int v : chosen) {
    if (options.direction == NoiseDirection::Normal) {
      D.row(v) = N.row(v) * (stddev * rng.gaussian());
    } else {
      const Eigen::RowVector3d u = rng.direction();
      D.row(v) = u * (stddev * rng.gaussian());
    }
  }
  if (options.correlation > 0) correlate(D, F, options.correlation);
  for (int v : chosen) out.row(v) += D.row(v);
  if (!out.allFinite())
    throw InvalidInput("noise: sigma = " + std::to_string(options.sigma) +
                       " mean edge lengths moves vertices beyond the range of finite coordinates");
  return out;
}

}  // namespace msmesh
