#include "msmesh/noise.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/geometry.h"

namespace msmesh {

namespace {

// splitmix64 (Steele, Lea & Flood 2014): expands the user's seed into generator state, so
// that nearby seeds (0, 1, 2, …) give unrelated streams.
std::uint64_t splitmix64(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// xoshiro256** (Blackman & Vigna 2018) with Box–Muller normals. Everything is specified down
// to the bit (no std:: distribution, whose output is implementation-defined), so a seed gives
// the same stream on every platform; only libm's log/cos/sin enter the Gaussian values.
class Random {
 public:
  explicit Random(std::uint64_t seed) {
    for (auto& w : s_) w = splitmix64(seed);
  }

  std::uint64_t next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  /// Uniform in [0, 1) with 53 random bits.
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }

  /// Uniform integer in [0, n), n > 0, without modulo bias (rejection sampling).
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() - std::numeric_limits<std::uint64_t>::max() % n;
    std::uint64_t r;
    do r = next();
    while (r >= limit);
    return r % n;
  }

  /// Standard normal N(0,1) by Box–Muller; the second value of each pair is kept for the next call.
  double gaussian() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - uniform();  // (0, 1]: log is finite
    const double u2 = uniform();
    const double r = std::sqrt(-2.0 * std::log(u1));
    const double a = 6.283185307179586476925286766559 * u2;  // 2π
    spare_ = r * std::sin(a);
    has_spare_ = true;
    return r * std::cos(a);
  }

  /// Unit vector uniformly distributed on the sphere (a normalised isotropic Gaussian vector).
  Eigen::RowVector3d direction() {
    for (;;) {
      Eigen::RowVector3d d(gaussian(), gaussian(), gaussian());
      const double len = d.norm();
      if (len > 1e-12) return d / len;
    }
  }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4];
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace

void NoiseOptions::validate() const {
  if (!std::isfinite(sigma) || sigma < 0) {
    std::ostringstream os;
    os << "noise: sigma = " << sigma << " is invalid; it must be a finite number >= 0 (in mean edge lengths)";
    throw InvalidInput(os.str());
  }
  if (!(impulsive_fraction >= 0 && impulsive_fraction <= 1)) {  // also rejects NaN
    std::ostringstream os;
    os << "noise: impulsive_fraction = " << impulsive_fraction << " is invalid; it must lie in [0, 1]";
    throw InvalidInput(os.str());
  }
  if (direction != NoiseDirection::Normal && direction != NoiseDirection::Random)
    throw InvalidInput("noise: direction must be NoiseDirection::Normal or NoiseDirection::Random");
}

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

  Random rng(options.seed);
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

  for (int v : chosen) {
    // Normal: n·σ·g. Random: u·σ·g with u uniform on the unit sphere, so both modes displace
    // by the same RMS length σ (as bldeng/GuidedDenoising, which generated the public
    // benchmark meshes, does) rather than by σ per component.
    if (options.direction == NoiseDirection::Normal) {
      out.row(v) += N.row(v) * (stddev * rng.gaussian());
    } else {
      const Eigen::RowVector3d u = rng.direction();
      out.row(v) += u * (stddev * rng.gaussian());
    }
  }
  return out;
}

}  // namespace msmesh
