// Minimum-cost multicut: small graphs with known optima, brute force over all partitions of
// random graphs, validity of the labelling and the objective convention.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/multicut.h"

using namespace msmesh;

namespace {

struct Graph {
  int n = 0;
  Eigen::MatrixXi edges;
  Eigen::VectorXd costs;
};

Graph make_graph(int n, const std::vector<std::array<int, 2>>& e, const std::vector<double>& c) {
  Graph g;
  g.n = n;
  g.edges.resize(static_cast<Eigen::Index>(e.size()), 2);
  g.costs.resize(static_cast<Eigen::Index>(c.size()));
  for (size_t k = 0; k < e.size(); ++k) {
    g.edges(k, 0) = e[k][0];
    g.edges(k, 1) = e[k][1];
    g.costs(k) = c[k];
  }
  return g;
}

// Random graph: each pair an edge with probability `density`, costs ~ N(mu, 1).
Graph random_graph(int n, double density, double mu, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> gauss(mu, 1.0);
  std::vector<std::array<int, 2>> e;
  std::vector<double> c;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (u(rng) < density) {
        e.push_back({i, j});
        c.push_back(gauss(rng));
      }
  return make_graph(n, e, c);
}

// Minimum over all set partitions (restricted growth strings); Bell(8) = 4140.
double brute_force_optimum(const Graph& g) {
  Eigen::VectorXi L = Eigen::VectorXi::Zero(g.n);
  double best = 0;  // everything joined
  std::function<void(int, int)> rec = [&](int i, int max_label) {
    if (i == g.n) {
      best = std::min(best, multicut_objective(g.edges, g.costs, L));
      return;
    }
    for (int l = 0; l <= max_label + 1; ++l) {
      L(i) = l;
      rec(i + 1, std::max(max_label, l));
    }
  };
  if (g.n > 0) {
    L(0) = 0;
    rec(1, 0);
  }
  return best;
}

void expect_consistent(const Graph& g, const MulticutResult& r) {
  ASSERT_EQ(r.labels.size(), g.n);
  EXPECT_TRUE(is_valid_multicut(g.n, g.edges, r.labels));
  EXPECT_NEAR(r.objective, multicut_objective(g.edges, g.costs, r.labels), 1e-9);
  if (g.n > 0) {
    EXPECT_EQ(r.labels.minCoeff(), 0);
    EXPECT_EQ(r.labels.maxCoeff(), r.count - 1);
  }
  EXPECT_LE(r.objective, r.objective_greedy + 1e-9);
}

}  // namespace

TEST(Multicut, TriangleWithOneRepulsiveEdge) {
  // Cutting only the −3 edge is not a multicut (0 and 2 stay connected through 1); the
  // optimum cuts it together with one +1 edge: −2.
  const Graph g = make_graph(3, {{0, 1}, {1, 2}, {0, 2}}, {1, 1, -3});
  const MulticutResult r = solve_multicut(g.n, g.edges, g.costs);
  expect_consistent(g, r);
  EXPECT_EQ(r.count, 2);
  EXPECT_NEAR(r.objective, -2.0, 1e-12);
  EXPECT_NE(r.labels(0), r.labels(2));
}

TEST(Multicut, AllPositiveGivesOneClusterPerComponent) {
  const Graph g = make_graph(6, {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}}, {0.5, 2, 1, 3, 0.1});
  const MulticutResult r = solve_multicut(g.n, g.edges, g.costs);
  expect_consistent(g, r);
  EXPECT_EQ(r.count, 2);  // two connected components
  EXPECT_EQ(r.objective, 0.0);
  EXPECT_EQ(r.labels(0), r.labels(2));
  EXPECT_EQ(r.labels(3), r.labels(5));
}

TEST(Multicut, AllNegativeGivesSingletons) {
  std::mt19937_64 rng(5);
  Graph g = random_graph(12, 0.6, 0.0, rng);
  g.costs = -g.costs.cwiseAbs() - Eigen::VectorXd::Constant(g.costs.size(), 0.01);
  const MulticutResult r = solve_multicut(g.n, g.edges, g.costs);
  expect_consistent(g, r);
  EXPECT_EQ(r.count, 12);
  EXPECT_NEAR(r.objective, g.costs.sum(), 1e-12);
}

TEST(Multicut, ParallelEdgesAreSummedAndSelfLoopsIgnored) {
  // 0–1 twice: +1 and −3 → net −2 (cut); 1–2: +1 (join); self-loop on 2 ignored.
  const Graph g = make_graph(3, {{0, 1}, {1, 0}, {1, 2}, {2, 2}}, {1, -3, 1, -10});
  const MulticutResult r = solve_multicut(g.n, g.edges, g.costs);
  EXPECT_EQ(r.count, 2);
  EXPECT_NE(r.labels(0), r.labels(1));
  EXPECT_EQ(r.labels(1), r.labels(2));
  EXPECT_NEAR(r.objective, -2.0, 1e-12);
  EXPECT_NEAR(multicut_objective(g.edges, g.costs, r.labels), -2.0, 1e-12);
}

TEST(Multicut, EmptyAndEdgelessGraphs) {
  const MulticutResult r0 = solve_multicut(0, Eigen::MatrixXi(0, 2), Eigen::VectorXd(0));
  EXPECT_EQ(r0.count, 0);
  const MulticutResult r1 = solve_multicut(4, Eigen::MatrixXi(0, 2), Eigen::VectorXd(0));
  EXPECT_EQ(r1.count, 4);
  EXPECT_EQ(r1.objective, 0.0);
}

TEST(Multicut, MatchesBruteForceOnRandomSmallGraphs) {
  std::mt19937_64 rng(2024);
  int optimal = 0, trials = 0, greedy_optimal = 0;
  double total_gap = 0, worst_gap = 0;
  for (int t = 0; t < 300; ++t) {
    const int n = 3 + t % 6;  // 3..8 nodes
    const double density = (t % 3 == 0) ? 1.0 : 0.55;
    const double mu = (t % 4) * 0.25 - 0.5;  // from repulsive-leaning to attractive-leaning mixes
    const Graph g = random_graph(n, density, mu, rng);
    const MulticutResult r = solve_multicut(g.n, g.edges, g.costs);
    expect_consistent(g, r);
    const double opt = brute_force_optimum(g);
    const double gap = r.objective - opt;
    ASSERT_GE(gap, -1e-9) << "better than the brute-force optimum: objective is miscomputed";
    ++trials;
    if (gap < 1e-9) ++optimal;
    if (r.objective_greedy - opt < 1e-9) ++greedy_optimal;
    total_gap += gap / std::max(1.0, std::abs(opt));
    worst_gap = std::max(worst_gap, gap / std::max(1.0, std::abs(opt)));
  }
  RecordProperty("optimal_fraction", std::to_string(double(optimal) / trials));
  std::printf("[multicut brute force] GAEC optimal %d/%d, GAEC+KL optimal %d/%d, mean rel. gap %.4f, worst %.4f\n",
              greedy_optimal, trials, optimal, trials, total_gap / trials, worst_gap);
  EXPECT_GE(optimal, 0.9 * trials);
  EXPECT_LT(total_gap / trials, 0.01);
  EXPECT_GE(optimal, greedy_optimal);
}

TEST(Multicut, GridSplitAlongARepulsiveLine) {
  // 20×20 grid graph, attractive everywhere except across the vertical line x = 9|10 and the
  // horizontal line y = 4|5, which are repulsive: four clusters.
  const int w = 20;
  std::vector<std::array<int, 2>> e;
  std::vector<double> c;
  for (int y = 0; y < w; ++y)
    for (int x = 0; x < w; ++x) {
      const int i = y * w + x;
      if (x + 1 < w) {
        e.push_back({i, i + 1});
        c.push_back(x == 9 ? -1.0 : 2.0);
      }
      if (y + 1 < w) {
        e.push_back({i, i + w});
        c.push_back(y == 4 ? -1.0 : 2.0);
      }
    }
  const Graph g = make_graph(w * w, e, c);
  const MulticutResult r = solve_multicut(g.n, g.edges, g.costs);
  expect_consistent(g, r);
  EXPECT_EQ(r.count, 4);
  EXPECT_NEAR(r.objective, -2.0 * w, 1e-9);
}

TEST(Multicut, LocalSearchNeverWorsensGreedy) {
  std::mt19937_64 rng(7);
  for (int t = 0; t < 20; ++t) {
    const Graph g = random_graph(40, 0.15, 0.2, rng);
    MulticutOptions greedy_only;
    greedy_only.local_search = false;
    const MulticutResult a = solve_multicut(g.n, g.edges, g.costs, greedy_only);
    const MulticutResult b = solve_multicut(g.n, g.edges, g.costs);
    expect_consistent(g, a);
    expect_consistent(g, b);
    EXPECT_NEAR(a.objective, b.objective_greedy, 1e-12);
    EXPECT_LE(b.objective, a.objective + 1e-12);
  }
}

TEST(Multicut, RejectsBadInput) {
  Eigen::MatrixXi e(1, 2);
  e << 0, 3;
  EXPECT_THROW(solve_multicut(3, e, Eigen::VectorXd::Ones(1)), InvalidInput);
  e << 0, 1;
  EXPECT_THROW(solve_multicut(3, e, Eigen::VectorXd::Ones(2)), InvalidInput);
  EXPECT_THROW(solve_multicut(3, e, Eigen::VectorXd::Constant(1, std::nan(""))), InvalidInput);
  MulticutOptions o;
  o.tolerance = -1;
  EXPECT_THROW(solve_multicut(3, e, Eigen::VectorXd::Ones(1), o), InvalidInput);
}

TEST(Multicut, ProgressCanCancel) {
  std::mt19937_64 rng(3);
  const Graph g = random_graph(30, 0.3, 0.0, rng);
  EXPECT_THROW(solve_multicut(g.n, g.edges, g.costs, {}, [](const ProgressEvent&) { return false; }), Cancelled);
}
