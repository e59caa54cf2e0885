// Speed per stage of a denoise, on noisy procedural cubes of about 10K, 100K and 1M faces.
// Run: build/bench/msmesh_bench --benchmark_filter=Stage
#include <benchmark/benchmark.h>

#include <map>

#include "msmesh/denoise.h"
#include "msmesh/geometry.h"
#include "msmesh/noise.h"
#include "msmesh/operators.h"
#include "msmesh/presets.h"
#include "msmesh/shapes.h"
#include "msmesh/topology.h"

using namespace msmesh;

namespace {

// n per cube face side: 12 n² faces → 29: 10K, 91: 99K, 289: 1.0M.
const Mesh& noisy_cube(int n) {
  static std::map<int, Mesh> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  Mesh m = make_cube(n);
  NoiseOptions no;
  no.sigma = 0.2;
  no.seed = 1;
  m.V = add_noise(m.V, m.F, no);
  return cache.emplace(n, std::move(m)).first->second;
}

void StageOperators(benchmark::State& state) {
  const Mesh& m = noisy_cube(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const Topology t = build_topology(m.F, m.V.rows());
    Operators ops = build_operators(m.V, m.F, t);
    benchmark::DoNotOptimize(ops.G.nonZeros());
  }
  state.counters["faces"] = static_cast<double>(m.F.rows());
}

void StageNormalFilter(benchmark::State& state) {
  const Mesh& m = noisy_cube(static_cast<int>(state.range(0)));
  NormalFilterOptions o = preset_options("cad").normals;
  o.max_iterations = static_cast<int>(state.range(1));
  o.tolerance = 0;
  for (auto _ : state) {
    NormalFilterResult r = filter_normals(m.V, m.F, o);
    benchmark::DoNotOptimize(r.normals.data());
  }
  state.counters["faces"] = static_cast<double>(m.F.rows());
  state.counters["iterations"] = static_cast<double>(o.max_iterations);
}

void StageVertexUpdate(benchmark::State& state) {
  const Mesh& m = noisy_cube(static_cast<int>(state.range(0)));
  const Mesh clean = make_cube(static_cast<int>(state.range(0)));
  const Eigen::MatrixXd N = face_normals(clean.V, clean.F);
  VertexUpdateOptions o = preset_options("cad").vertices;
  o.max_iterations = static_cast<int>(state.range(1));
  o.tolerance = 0;
  for (auto _ : state) {
    VertexUpdateResult r = update_vertices(m.V, m.F, N, {}, o);
    benchmark::DoNotOptimize(r.V.data());
  }
  state.counters["faces"] = static_cast<double>(m.F.rows());
}

void StageFullDenoise(benchmark::State& state) {
  const Mesh& m = noisy_cube(static_cast<int>(state.range(0)));
  const DenoiseOptions o = preset_options("cad");
  for (auto _ : state) {
    DenoiseResult r = denoise(m.V, m.F, o);
    benchmark::DoNotOptimize(r.V.data());
  }
  state.counters["faces"] = static_cast<double>(m.F.rows());
}

}  // namespace

BENCHMARK(StageOperators)->Arg(29)->Arg(91)->Arg(289)->Unit(benchmark::kMillisecond);
// (n, iterations): 1 iteration ≈ set-up + factorisation; 30 − 1 gives the per-iteration cost.
BENCHMARK(StageNormalFilter)
    ->Args({29, 1})
    ->Args({29, 30})
    ->Args({91, 1})
    ->Args({91, 30})
    ->Args({289, 1})
    ->Args({289, 30})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(StageVertexUpdate)
    ->Args({29, 1})
    ->Args({29, 30})
    ->Args({91, 1})
    ->Args({91, 30})
    ->Args({289, 1})
    ->Args({289, 30})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(StageFullDenoise)->Arg(29)->Arg(91)->Arg(289)->Unit(benchmark::kMillisecond)->Iterations(1);
