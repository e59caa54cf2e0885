// Multicut speed on the face graph of a subdivided sphere (81,920 faces at 6 subdivisions,
// 327,680 at 7) with costs from a synthetic edge field v, mapped as segment() does
// (p = 1 − v clamped to [0.001, 0.999], cost log((1 − p)/p)): v ≈ 0.05 on the edges whose two
// faces lie on different sides of one of the coordinate planes (the optimum: 8 octants),
// v ≈ 0.95 elsewhere, both with seeded uniform noise of ±0.1, and 1% of the other edges
// given v ≈ 0.4 (weak isolated false features, which the optimum ignores).
// Run: build/bench/msmesh_bench --benchmark_filter=Multicut
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>

#include "msmesh/geometry.h"
#include "msmesh/multicut.h"
#include "msmesh/shapes.h"
#include "msmesh/topology.h"

using namespace msmesh;

namespace {

struct Problem {
  Eigen::Index faces = 0;
  Eigen::MatrixXi edges;  // face pairs
  Eigen::VectorXd costs;
};

const Problem& sphere_problem(int subdivisions) {
  static std::map<int, Problem> cache;
  auto it = cache.find(subdivisions);
  if (it != cache.end()) return it->second;
  const Mesh m = make_sphere(subdivisions);
  const Topology t = build_topology(m.F, m.V.rows());
  std::uint64_t state = 12345;
  auto uniform = [&state] {  // splitmix64
    std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  };
  Problem p;
  p.faces = m.F.rows();
  p.edges.resize(t.num_edges(), 2);
  p.costs.resize(t.num_edges());
  const Eigen::MatrixXd C = face_barycenters(m.V, m.F);
  for (Eigen::Index e = 0; e < t.num_edges(); ++e) {
    const int f = t.edge_faces(e, 0), g = t.edge_faces(e, 1);
    bool across = false;
    for (int k = 0; k < 3; ++k) across = across || ((C(f, k) < 0) != (C(g, k) < 0));
    const bool false_feature = !across && uniform() < 0.01;
    double v = (across ? 0.05 : false_feature ? 0.4 : 0.95) + 0.2 * (uniform() - 0.5);
    v = std::clamp(v, 0.0, 1.0);
    const double prob = std::clamp(1.0 - v, 0.001, 0.999);  // split probability, as segment()
    p.edges.row(e) << f, g;
    p.costs(e) = std::log((1 - prob) / prob);
  }
  return cache.emplace(subdivisions, std::move(p)).first->second;
}

void run(benchmark::State& state, bool local) {
  const Problem& p = sphere_problem(static_cast<int>(state.range(0)));
  MulticutOptions o;
  o.local_search = local;
  MulticutResult r;
  for (auto _ : state) {
    r = solve_multicut(p.faces, p.edges, p.costs, o);
    benchmark::DoNotOptimize(r.labels.data());
  }
  state.counters["faces"] = static_cast<double>(p.faces);
  state.counters["segments"] = r.count;
  state.counters["objective"] = r.objective;
  state.counters["objective_gaec"] = r.objective_greedy;
  state.counters["local_rounds"] = r.local_rounds;
}

void MulticutGreedy(benchmark::State& state) { run(state, false); }
void MulticutGreedyAndLocal(benchmark::State& state) { run(state, true); }

}  // namespace

BENCHMARK(MulticutGreedy)->Arg(6)->Arg(7)->Unit(benchmark::kMillisecond);
BENCHMARK(MulticutGreedyAndLocal)->Arg(6)->Arg(7)->Unit(benchmark::kMillisecond);
