#include "msmesh/multicut.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "msmesh/errors.h"
#include "msmesh/parameters.h"

namespace msmesh {

const ParameterTable<MulticutOptions>& multicut_parameters() {
  using O = MulticutOptions;
  using T = ParameterType;
  static const ParameterTable<O> t = {
      bind_parameter(ParameterInfo{"max-local-rounds",
                                   "",
                                   "",
                                   T::Integer,
                                   {0, 2147483647},
                                   "maximum rounds of the local search",
                                   "multicut"},
                     &O::max_local_rounds),
      bind_parameter(
          ParameterInfo{
              "tolerance", "", "", T::Real, {0}, "a move must lower the objective by more than this", "multicut"},
          &O::tolerance),
  };
  return t;
}

void MulticutOptions::validate() const { check_parameters(multicut_parameters(), *this); }

namespace {

// The graph with parallel edges merged (costs summed) and self-loops dropped, as adjacency
// lists in compressed form: the neighbours of i are nbr[off[i] .. off[i+1]) with costs w.
struct Graph {
  int n = 0;
  std::vector<int> off, nbr;
  std::vector<double> w;
  std::vector<int> ei, ej;  // each merged edge once (ei < ej)
  std::vector<double> ec;
};

void check_input(Eigen::Index num_nodes, const Eigen::MatrixXi& edges, const Eigen::VectorXd& costs) {
  if (num_nodes < 0 || num_nodes > std::numeric_limits<int>::max())
    throw InvalidInput("multicut: number of nodes " + std::to_string(num_nodes) + " is out of range");
  if (edges.rows() > 0 && edges.cols() != 2)
    throw InvalidInput("multicut: edges must be #E by 2, got " + std::to_string(edges.rows()) + " by " +
                       std::to_string(edges.cols()));
  if (costs.size() != edges.rows())
    throw InvalidInput("multicut: " + std::to_string(costs.size()) + " costs for " + std::to_string(edges.rows()) +
                       " edges");
  for (Eigen::Index e = 0; e < edges.rows(); ++e) {
    for (int k = 0; k < 2; ++k)
      if (edges(e, k) < 0 || edges(e, k) >= num_nodes)
        throw InvalidInput("multicut: edge " + std::to_string(e) + " refers to node " + std::to_string(edges(e, k)) +
                           ", valid: [0, " + std::to_string(num_nodes) + ")");
    if (!std::isfinite(costs(e))) throw InvalidInput("multicut: cost of edge " + std::to_string(e) + " is not finite");
  }
}

Graph build_graph(Eigen::Index num_nodes, const Eigen::MatrixXi& edges, const Eigen::VectorXd& costs) {
  Graph g;
  g.n = static_cast<int>(num_nodes);
  struct Item {
    int i, j;
    double c;
  };
  std::vector<Item> items;
  items.reserve(edges.rows());
  for (Eigen::Index e = 0; e < edges.rows(); ++e) {
    int i = edges(e, 0), j = edges(e, 1);
    if (i == j) continue;  // a self-loop is never cut
    if (i > j) std::swap(i, j);
    items.push_back({i, j, costs(e)});
  }
  std::sort(items.begin(), items.end(),
            [](const Item& a, const Item& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
  for (size_t k = 0; k < items.size();) {
    size_t l = k;
    double c = 0;
    for (; l < items.size() && items[l].i == items[k].i && items[l].j == items[k].j; ++l) c += items[l].c;
    g.ei.push_back(items[k].i);
    g.ej.push_back(items[k].j);
    g.ec.push_back(c);
    k = l;
  }
  g.off.assign(g.n + 1, 0);
  for (size_t e = 0; e < g.ei.size(); ++e) {
    ++g.off[g.ei[e] + 1];
    ++g.off[g.ej[e] + 1];
  }
  for (int i = 0; i < g.n; ++i) g.off[i + 1] += g.off[i];
  g.nbr.resize(g.off[g.n]);
  g.w.resize(g.off[g.n]);
  std::vector<int> fill(g.off.begin(), g.off.end() - 1);
  for (size_t e = 0; e < g.ei.size(); ++e) {
    g.nbr[fill[g.ei[e]]] = g.ej[e];
    g.w[fill[g.ei[e]]++] = g.ec[e];
    g.nbr[fill[g.ej[e]]] = g.ei[e];
    g.w[fill[g.ej[e]]++] = g.ec[e];
  }
  return g;
}

double objective_of(const Graph& g, const std::vector<int>& L) {
  double s = 0;
  for (size_t e = 0; e < g.ei.size(); ++e)
    if (L[g.ei[e]] != L[g.ej[e]]) s += g.ec[e];
  return s;
}

// Relabels so that every label is a connected component of the graph without the cut edges
// (same objective: no uncut edge joins two components), numbered by first node. Returns the
// number of labels.
int relabel_components(const Graph& g, std::vector<int>& L) {
  std::vector<int> out(g.n, -1), stack;
  int k = 0;
  for (int s = 0; s < g.n; ++s) {
    if (out[s] >= 0) continue;
    out[s] = k;
    stack.push_back(s);
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      for (int a = g.off[i]; a < g.off[i + 1]; ++a) {
        const int j = g.nbr[a];
        if (out[j] < 0 && L[j] == L[i]) {
          out[j] = k;
          stack.push_back(j);
        }
      }
    }
    ++k;
  }
  L.swap(out);
  return k;
}

void report(const ProgressCallback& progress, const char* stage, int it, int max_it, double residual) {
  if (progress && !progress({stage, it, max_it, residual}))
    throw Cancelled(std::string("multicut cancelled during ") + stage);
}

// Greedy additive edge contraction (Keuper et al. 2015) starting from the clusters of L
// (labels in [0, k), each cluster connected): repeatedly contracts the pair of neighbouring
// clusters with the largest positive total cost between them, merging parallel edges by
// adding their costs. Priority queue with lazy deletion; the adjacency of the smaller side
// is merged into the larger. Updates L; returns the number of contractions.
int greedy_additive_contraction(const Graph& g, std::vector<int>& L, int k, const ProgressCallback& progress) {
  std::vector<std::unordered_map<int, double>> adj(k);
  for (size_t e = 0; e < g.ei.size(); ++e) {
    const int a = L[g.ei[e]], b = L[g.ej[e]];
    if (a == b) continue;
    adj[a][b] += g.ec[e];
    adj[b][a] += g.ec[e];
  }
  struct Entry {
    double w;
    int a, b;
    bool operator<(const Entry& o) const { return w < o.w; }
  };
  std::priority_queue<Entry> pq;
  for (int a = 0; a < k; ++a)
    for (const auto& [b, w] : adj[a])
      if (a < b && w > 0) pq.push({w, a, b});
  std::vector<int> parent(k);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<char> alive(k, 1);
  int contractions = 0;
  while (!pq.empty()) {
    const Entry top = pq.top();
    pq.pop();
    if (!alive[top.a] || !alive[top.b]) continue;
    const auto it = adj[top.a].find(top.b);
    if (it == adj[top.a].end() || it->second != top.w) continue;  // stale entry
    int big = top.a, small = top.b;
    if (adj[big].size() < adj[small].size()) std::swap(big, small);
    adj[big].erase(small);
    for (const auto& [n, c] : adj[small]) {
      if (n == big) continue;
      adj[n].erase(small);
      double& x = adj[big][n];
      x += c;
      adj[n][big] = x;
      if (x > 0) pq.push({x, std::min(big, n), std::max(big, n)});
    }
    std::unordered_map<int, double>().swap(adj[small]);
    alive[small] = 0;
    parent[small] = big;
    ++contractions;
    if ((contractions & 4095) == 0) report(progress, "multicut greedy", contractions, k, top.w);
  }
  auto find = [&](int a) {
    int r = a;
    while (parent[r] != r) r = parent[r];
    while (parent[a] != r) {
      const int next = parent[a];
      parent[a] = r;
      a = next;
    }
    return r;
  };
  for (int i = 0; i < g.n; ++i) L[i] = find(L[i]);
  return contractions;
}

// Local search on a labelling with labels in [0, n) (ids of empty clusters are recycled).
class LocalSearch {
 public:
  LocalSearch(const Graph& g, std::vector<int>& L, double tol) : g_(g), L_(L), tol_(tol) {
    size_.assign(g.n, 0);
    for (int i = 0; i < g.n; ++i) ++size_[L_[i]];
    for (int l = g.n - 1; l >= 0; --l)
      if (size_[l] == 0) free_.push_back(l);
    acc_.assign(g.n, 0.0);
    mark_.assign(g.n, 0);
    stamp_.assign(g.n, 0);
    version_.assign(g.n, 0);
  }

  // Moves single nodes to a neighbouring cluster or into a new singleton cluster whenever
  // that lowers the objective, until no such move exists. Returns the moves made.
  int node_moves() {
    std::vector<int> queue;
    std::vector<char> queued(g_.n, 0);
    for (int i = 0; i < g_.n; ++i)
      if (on_boundary(i)) {
        queue.push_back(i);
        queued[i] = 1;
      }
    int moves = 0;
    std::vector<int> touched;
    for (size_t head = 0; head < queue.size(); ++head) {
      const int i = queue[head];
      queued[i] = 0;
      const int A = L_[i];
      // Sum of costs from i to each neighbouring cluster.
      touched.clear();
      for (int a = g_.off[i]; a < g_.off[i + 1]; ++a) {
        const int l = L_[g_.nbr[a]];
        if (!mark_[l]) {
          mark_[l] = 1;
          acc_[l] = 0;
          touched.push_back(l);
        }
        acc_[l] += g_.w[a];
      }
      const double cA = mark_[A] ? acc_[A] : 0.0;
      // Moving i from A to B changes the objective by cA − cB (i's edges to A become cut,
      // those to B uncut); into a new singleton by cA.
      double best = -tol_;
      int target = -1;  // -1: stay, -2: new singleton
      if (size_[A] > 1 && cA < best) {
        best = cA;
        target = -2;
      }
      for (int l : touched) {
        if (l == A) continue;
        const double d = cA - acc_[l];
        if (d < best) {
          best = d;
          target = l;
        }
      }
      for (int l : touched) mark_[l] = 0;
      if (target == -1) continue;
      if (target == -2) target = take_free_label();
      move(i, target);
      ++moves;
      for (int a = g_.off[i]; a < g_.off[i + 1]; ++a) {
        const int j = g_.nbr[a];
        if (!queued[j]) {
          queued[j] = 1;
          queue.push_back(j);
        }
      }
      if (!queued[i]) {
        queued[i] = 1;
        queue.push_back(i);
      }
    }
    return moves;
  }

  // Kernighan–Lin moves between every pair of neighbouring clusters (A, B): a sequence of
  // tentative single-node moves across the A–B boundary, each the best available even when
  // it raises the objective, each node moved at most once; the best prefix of the sequence
  // is kept when it lowers the objective. Returns the moves kept.
  int pairwise_kl() {
    // Boundary nodes per neighbouring pair, collected once; stale entries are filtered when
    // the pair is processed and new boundaries are picked up in the next round.
    std::unordered_map<long long, std::vector<int>> seeds;
    const long long n = g_.n;
    for (size_t e = 0; e < g_.ei.size(); ++e) {
      int a = L_[g_.ei[e]], b = L_[g_.ej[e]];
      if (a == b) continue;
      auto& s = seeds[std::min(a, b) * n + std::max(a, b)];
      s.push_back(g_.ei[e]);
      s.push_back(g_.ej[e]);
    }
    std::vector<long long> keys;
    keys.reserve(seeds.size());
    for (const auto& kv : seeds) keys.push_back(kv.first);
    std::sort(keys.begin(), keys.end());  // deterministic order
    int kept = 0;
    for (long long key : keys)
      kept += improve_pair(static_cast<int>(key / n), static_cast<int>(key % n), seeds[key], false);
    // Splits: the same with an empty partner, every node of the cluster a candidate
    // (a cluster that should be split in two is not reachable by single-node moves).
    std::vector<std::vector<int>> members(g_.n);
    for (int i = 0; i < g_.n; ++i) members[L_[i]].push_back(i);
    for (int A = 0; A < g_.n; ++A) {
      if (members[A].size() < 2 || size_[A] < 2 || free_.empty()) continue;
      const int B = take_free_label();
      kept += improve_pair(A, B, members[A], true);
      if (size_[B] == 0) free_.push_back(B);
    }
    return kept;
  }

 private:
  bool on_boundary(int i) const {
    for (int a = g_.off[i]; a < g_.off[i + 1]; ++a)
      if (L_[g_.nbr[a]] != L_[i]) return true;
    return false;
  }

  int take_free_label() {
    const int l = free_.back();
    free_.pop_back();
    return l;
  }

  void move(int i, int to) {
    const int from = L_[i];
    if (--size_[from] == 0) free_.push_back(from);
    ++size_[to];
    L_[i] = to;
  }

  // Gain (decrease of the objective) of moving i ∈ {A, B} to the other of the two.
  double pair_gain(int i, int A, int B, bool* touches_other) const {
    const int own = L_[i], other = own == A ? B : A;
    double g = 0;
    bool t = false;
    for (int a = g_.off[i]; a < g_.off[i + 1]; ++a) {
      const int l = L_[g_.nbr[a]];
      if (l == other) {
        g += g_.w[a];
        t = true;
      } else if (l == own) {
        g -= g_.w[a];
      }
    }
    if (touches_other) *touches_other = t;
    return g;
  }

  // KL between clusters A and B (B empty when `split`: then every node of A is a candidate,
  // otherwise only nodes with a neighbour on the other side).
  int improve_pair(int A, int B, const std::vector<int>& seed_nodes, bool split) {
    if (size_[A] == 0 || (size_[B] == 0) != split) return 0;
    ++round_stamp_;
    struct Entry {
      double g;
      int i;
      unsigned version;
      bool operator<(const Entry& o) const { return g != o.g ? g < o.g : i > o.i; }
    };
    std::priority_queue<Entry> pq;
    auto consider = [&](int i) {
      if (L_[i] != A && L_[i] != B) return;
      if (stamp_[i] == round_stamp_ && mark_[i]) return;  // locked (moved already)
      if (stamp_[i] != round_stamp_) {
        stamp_[i] = round_stamp_;
        mark_[i] = 0;
      }
      // A new version invalidates any queued entry of i, also when i no longer qualifies.
      const unsigned version = ++version_[i];
      bool touches = false;
      const double g = pair_gain(i, A, B, &touches);
      if (!touches && !(split && L_[i] == A)) return;
      pq.push({g, i, version});
    };
    for (int i : seed_nodes) consider(i);
    // Tentative moves allowed past the best prefix before giving up.
    const size_t patience = std::clamp<size_t>(seed_nodes.size() / 2, 16, 256);
    std::vector<std::pair<int, int>> sequence;  // (node, label before the move)
    double cumulative = 0, best = 0;
    size_t best_length = 0;
    while (!pq.empty()) {
      const Entry top = pq.top();
      pq.pop();
      if (top.version != version_[top.i] || mark_[top.i] || stamp_[top.i] != round_stamp_) continue;
      const int i = top.i, from = L_[i], to = from == A ? B : A;
      if (size_[from] == 1) continue;  // emptying a cluster is a join, left to the contraction
      sequence.emplace_back(i, from);
      --size_[from];
      ++size_[to];
      L_[i] = to;
      mark_[i] = 1;  // locked
      cumulative += top.g;
      if (cumulative > best + tol_) {
        best = cumulative;
        best_length = sequence.size();
      } else if (sequence.size() - best_length > patience) {
        break;
      }
      for (int a = g_.off[i]; a < g_.off[i + 1]; ++a) consider(g_.nbr[a]);
    }
    // Undo the moves after the best prefix.
    for (size_t s = sequence.size(); s > best_length; --s) {
      const auto [i, from] = sequence[s - 1];
      --size_[L_[i]];
      ++size_[from];
      L_[i] = from;
    }
    for (const auto& [i, from] : sequence) mark_[i] = 0;
    return static_cast<int>(best_length);
  }

  const Graph& g_;
  std::vector<int>& L_;
  double tol_;
  std::vector<int> size_, free_;
  std::vector<double> acc_;
  std::vector<char> mark_;
  std::vector<unsigned> stamp_, version_;
  unsigned round_stamp_ = 0;
};

}  // namespace

double multicut_objective(const Eigen::MatrixXi& edges, const Eigen::VectorXd& costs, const Eigen::VectorXi& labels) {
  if (costs.size() != edges.rows())
    throw InvalidInput("multicut objective: " + std::to_string(costs.size()) + " costs for " +
                       std::to_string(edges.rows()) + " edges");
  double s = 0;
  for (Eigen::Index e = 0; e < edges.rows(); ++e) {
    const int i = edges(e, 0), j = edges(e, 1);
    if (i < 0 || j < 0 || i >= labels.size() || j >= labels.size())
      throw InvalidInput("multicut objective: edge " + std::to_string(e) + " refers to a node without a label");
    if (labels(i) != labels(j)) s += costs(e);
  }
  return s;
}

bool is_valid_multicut(Eigen::Index num_nodes, const Eigen::MatrixXi& edges, const Eigen::VectorXi& labels) {
  if (labels.size() != num_nodes) return false;
  std::vector<int> parent(num_nodes);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int a) {
    while (parent[a] != a) a = parent[a] = parent[parent[a]];
    return a;
  };
  for (Eigen::Index e = 0; e < edges.rows(); ++e) {
    const int i = edges(e, 0), j = edges(e, 1);
    if (labels(i) == labels(j)) parent[find(i)] = find(j);
  }
  // Each label must have exactly one component root.
  std::unordered_map<int, int> root_of_label;
  for (Eigen::Index i = 0; i < num_nodes; ++i) {
    if (labels(i) < 0) return false;
    const int r = find(static_cast<int>(i));
    const auto [it, inserted] = root_of_label.emplace(labels(i), r);
    if (!inserted && it->second != r) return false;
  }
  return true;
}

MulticutResult solve_multicut(Eigen::Index num_nodes, const Eigen::MatrixXi& edges, const Eigen::VectorXd& costs,
                              const MulticutOptions& options, const ProgressCallback& progress) {
  options.validate();
  check_input(num_nodes, edges, costs);
  const Graph g = build_graph(num_nodes, edges, costs);
  MulticutResult r;
  std::vector<int> L(g.n);
  std::iota(L.begin(), L.end(), 0);
  r.contractions = greedy_additive_contraction(g, L, g.n, progress);
  int k = relabel_components(g, L);
  double objective = objective_of(g, L);
  r.objective_greedy = objective;

  if (options.local_search) {
    std::vector<int> kept = L;
    int kept_count = k;
    for (int round = 0; round < options.max_local_rounds; ++round) {
      LocalSearch ls(g, L, options.tolerance);
      int moves = ls.node_moves();
      moves += ls.pairwise_kl();
      moves += ls.node_moves();
      // Moves may split a cluster: relabel by connected components (same objective), then
      // contract neighbouring clusters whose connection became positive.
      k = relabel_components(g, L);
      moves += greedy_additive_contraction(g, L, k, {});
      k = relabel_components(g, L);
      const double next = objective_of(g, L);
      ++r.local_rounds;
      r.local_moves += moves;
      report(progress, "multicut local", round + 1, options.max_local_rounds, next);
      // Every move lowers the objective, so a round cannot raise it; keep the best labels
      // anyway, as a guard against rounding.
      if (!(next < objective - options.tolerance)) {
        if (next > objective) {
          L = kept;
          k = kept_count;
        } else {
          objective = next;
        }
        break;
      }
      objective = next;
      kept = L;
      kept_count = k;
    }
  }
  r.labels = Eigen::Map<const Eigen::VectorXi>(L.data(), g.n);
  r.count = k;
  r.objective = objective;
  return r;
}

}  // namespace msmesh
