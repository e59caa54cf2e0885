#include "msmesh/segment.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>
#include <sstream>
#include <unordered_map>

#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/parameters.h"
#include "msmesh/prepared_mesh.h"
#include "msmesh/topology.h"

namespace msmesh {

namespace {

// Merges segments smaller than min_area into the neighbour with the longest shared boundary,
// smallest first, until none is left (or it has no neighbour). L: #F labels in [0, k).
void merge_small_segments(std::vector<int>& L, int k, const Topology& topo, const Eigen::VectorXd& face_area,
                          const Eigen::VectorXd& edge_len, double min_area) {
  std::vector<double> area(k, 0.0);
  for (size_t f = 0; f < L.size(); ++f) area[L[f]] += face_area(f);
  std::vector<std::unordered_map<int, double>> border(k);
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
    if (!topo.edge_is_interior[e]) continue;
    const int a = L[topo.edge_faces(e, 0)], b = L[topo.edge_faces(e, 1)];
    if (a == b) continue;
    border[a][b] += edge_len(e);
    border[b][a] += edge_len(e);
  }
  std::vector<int> parent(k);
  std::iota(parent.begin(), parent.end(), 0);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> pq;
  for (int s = 0; s < k; ++s)
    if (area[s] < min_area) pq.push({area[s], s});
  while (!pq.empty()) {
    const auto [a_s, s] = pq.top();
    pq.pop();
    if (parent[s] != s || a_s != area[s] || border[s].empty()) continue;  // merged or stale
    // Longest shared boundary; ties to the larger neighbour, then the lower id.
    int t = -1;
    for (const auto& [n, len] : border[s])
      if (t < 0 || len > border[s][t] || (len == border[s][t] && (area[n] > area[t] || (area[n] == area[t] && n < t))))
        t = n;
    parent[s] = t;
    area[t] += area[s];
    border[t].erase(s);
    for (const auto& [n, len] : border[s]) {
      if (n == t) continue;
      border[n].erase(s);
      border[n][t] += len;
      border[t][n] += len;
    }
    border[s].clear();
    if (area[t] < min_area) pq.push({area[t], t});
  }
  for (auto& l : L) {
    while (parent[l] != l) l = parent[l];
  }
}

}  // namespace

void SegmentOptions::validate() const {
  check_parameters(segment_parameters(), *this);  // with the normal filter's
  multicut.validate();
}

Eigen::VectorXd normalize_edge_field(const Eigen::VectorXd& v) {
  if (v.size() == 0) return v;
  if (!v.allFinite()) throw InvalidInput("edge field v has non-finite values");
  const double lo = v.minCoeff(), hi = v.maxCoeff();
  if (!(hi - lo > 1e-12 * std::max(1.0, std::abs(hi)))) return Eigen::VectorXd::Ones(v.size());
  return ((v.array() - lo) / (hi - lo)).matrix();
}

namespace {

// segment_with_field on a checked mesh (V, F) with its topology.
SegmentResult segment_checked(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Topology& topo,
                              const Eigen::MatrixXd& N, const Eigen::VectorXd& v, const SegmentOptions& o,
                              const ProgressCallback& progress) {
  if (N.rows() != F.rows() || N.cols() != 3)
    throw InvalidInput("segmentation: normals must be #F by 3 (" + std::to_string(F.rows()) + " by 3), got " +
                       std::to_string(N.rows()) + " by " + std::to_string(N.cols()));
  if (v.size() != topo.num_edges())
    throw InvalidInput("segmentation: edge field has " + std::to_string(v.size()) + " values for " +
                       std::to_string(topo.num_edges()) + " edges");
  SegmentResult r;
  r.normals = N;
  r.v = v;
  r.edges = topo.edges;
  r.v_normalized = normalize_edge_field(v);

  // Face adjacency graph over interior manifold edges, with the §6.3 split probabilities.
  const double cos_smooth = std::cos(o.smooth_angle_deg * M_PI / 180.0);
  const double pmin = o.clamp_probability, pmax = 1.0 - o.clamp_probability;
  r.split_probability = Eigen::VectorXd::Zero(topo.num_edges());
  std::vector<int> graph_edge;  // mesh edge of each graph edge
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
    if (!topo.edge_is_interior[e]) continue;
    const int f = topo.edge_faces(e, 0), g = topo.edge_faces(e, 1);
    const double c = N.row(f).dot(N.row(g)) / std::max(1e-300, N.row(f).norm() * N.row(g).norm());
    // Within the smooth angle: never split (DESIGN.md's reading of "force to 0.1%").
    const double p = c >= cos_smooth ? pmin : std::clamp(1.0 - r.v_normalized(e), pmin, pmax);
    r.split_probability(e) = p;
    graph_edge.push_back(static_cast<int>(e));
  }
  Eigen::MatrixXi edges(static_cast<Eigen::Index>(graph_edge.size()), 2);
  Eigen::VectorXd costs(static_cast<Eigen::Index>(graph_edge.size()));
  for (size_t k = 0; k < graph_edge.size(); ++k) {
    const int e = graph_edge[k];
    edges(k, 0) = topo.edge_faces(e, 0);
    edges(k, 1) = topo.edge_faces(e, 1);
    const double p = r.split_probability(e);
    costs(k) = std::log((1.0 - p) / p);  // paid when cut: positive = join
  }
  r.multicut_report = solve_multicut(F.rows(), edges, costs, o.multicut, progress);
  r.multicut_count = r.multicut_report.count;

  std::vector<int> L(r.multicut_report.labels.data(), r.multicut_report.labels.data() + F.rows());
  const Eigen::VectorXd face_area = face_areas(V, F);
  if (o.min_area_fraction > 0 && r.multicut_count > 1)
    merge_small_segments(L, r.multicut_count, topo, face_area, edge_lengths(V, topo),
                         o.min_area_fraction * face_area.sum());

  // Number segments by decreasing area, ties by first face.
  const int k0 = F.rows() ? *std::max_element(L.begin(), L.end()) + 1 : 0;
  std::vector<double> area(k0, 0.0);
  std::vector<int> first(k0, -1);
  for (size_t f = 0; f < L.size(); ++f) {
    area[L[f]] += face_area(f);
    if (first[L[f]] < 0) first[L[f]] = static_cast<int>(f);
  }
  std::vector<int> order;
  for (int s = 0; s < k0; ++s)
    if (first[s] >= 0) order.push_back(s);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return area[a] != area[b] ? area[a] > area[b] : first[a] < first[b]; });
  std::vector<int> rank(k0, -1);
  for (size_t i = 0; i < order.size(); ++i) rank[order[i]] = static_cast<int>(i);
  r.count = static_cast<int>(order.size());
  r.labels.resize(F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) r.labels(f) = rank[L[f]];
  r.areas.resize(r.count);
  for (int i = 0; i < r.count; ++i) r.areas(i) = area[order[i]];
  r.objective = multicut_objective(edges, costs, r.labels);
  return r;
}

}  // namespace

SegmentResult segment_with_field(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& N,
                                 const Eigen::VectorXd& v, const SegmentOptions& o, const ProgressCallback& progress) {
  o.validate();
  validate_mesh(V, F, "segmentation");
  return segment_checked(V, F, build_topology(F, V.rows()), N, v, o, progress);
}

SegmentResult segment(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const SegmentOptions& o,
                      const ProgressCallback& progress) {
  o.validate();
  const PreparedMesh mesh(V, F, "segmentation");  // checked and connected once for both steps
  const NormalFilterResult nf = filter_normals(mesh, o.normals, {}, progress);
  SegmentResult r = segment_checked(V, F, mesh.topology(), nf.normals, nf.v, o, progress);
  r.normal_report = nf;  // the statistics only: normals and v are in r already
  return r;
}

std::vector<std::vector<int>> feature_lines(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                            const Eigen::VectorXd& v, double threshold, int min_edges) {
  validate_mesh(V, F, "feature lines");
  check_parameter("feature lines", "threshold", threshold, {0, 1, true, false});
  const Topology topo = build_topology(F, V.rows());
  if (v.size() != topo.num_edges())
    throw InvalidInput("feature lines: edge field has " + std::to_string(v.size()) + " values for " +
                       std::to_string(topo.num_edges()) + " edges");
  const Eigen::VectorXd vn = normalize_edge_field(v);
  const Eigen::Index nv = V.rows();
  // Feature graph: vertex → incident feature edges.
  std::vector<int> degree(nv, 0);
  std::vector<char> feature(topo.num_edges(), 0);
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e)
    if (vn(e) < threshold) {
      feature[e] = 1;
      ++degree[topo.edges(e, 0)];
      ++degree[topo.edges(e, 1)];
    }
  std::vector<int> off(nv + 1, 0), inc;
  for (Eigen::Index i = 0; i < nv; ++i) off[i + 1] = off[i] + degree[i];
  inc.resize(off[nv]);
  {
    std::vector<int> fill(off.begin(), off.end() - 1);
    for (Eigen::Index e = 0; e < topo.num_edges(); ++e)
      if (feature[e]) {
        inc[fill[topo.edges(e, 0)]++] = static_cast<int>(e);
        inc[fill[topo.edges(e, 1)]++] = static_cast<int>(e);
      }
  }
  std::vector<char> used(topo.num_edges(), 0);
  std::vector<std::vector<int>> lines;
  auto other = [&](int e, int i) { return topo.edges(e, 0) == i ? topo.edges(e, 1) : topo.edges(e, 0); };
  // Walks from vertex `start` along feature edge e until a vertex of degree ≠ 2 or a used edge.
  auto walk = [&](int start, int e) {
    std::vector<int> line{start};
    int at = start;
    while (true) {
      used[e] = 1;
      at = other(e, at);
      line.push_back(at);
      if (degree[at] != 2) break;
      int next = -1;
      for (int a = off[at]; a < off[at + 1]; ++a)
        if (!used[inc[a]]) next = inc[a];
      if (next < 0) break;  // closed loop back at its start
      e = next;
    }
    return line;
  };
  // Open chains start at end points and junctions; what is left are closed loops.
  for (Eigen::Index i = 0; i < nv; ++i)
    if (degree[i] != 2)
      for (int a = off[i]; a < off[i + 1]; ++a)
        if (!used[inc[a]]) lines.push_back(walk(static_cast<int>(i), inc[a]));
  for (Eigen::Index i = 0; i < nv; ++i)
    if (degree[i] == 2)
      for (int a = off[i]; a < off[i + 1]; ++a)
        if (!used[inc[a]]) lines.push_back(walk(static_cast<int>(i), inc[a]));
  if (min_edges > 1)
    lines.erase(std::remove_if(lines.begin(), lines.end(),
                               [&](const std::vector<int>& l) { return static_cast<int>(l.size()) - 1 < min_edges; }),
                lines.end());
  return lines;
}

double rand_index(const Eigen::VectorXi& a, const Eigen::VectorXi& b) {
  if (a.size() != b.size())
    throw InvalidInput("rand index: labellings have different sizes (" + std::to_string(a.size()) + " and " +
                       std::to_string(b.size()) + ")");
  const Eigen::Index n = a.size();
  if (n < 2) return 1.0;
  if (a.minCoeff() < 0 || b.minCoeff() < 0) throw InvalidInput("rand index: labels must be >= 0");
  const long long ka = a.maxCoeff() + 1LL, kb = b.maxCoeff() + 1LL;
  auto pairs = [](double m) { return m * (m - 1) / 2; };
  // Σ C(n_ij, 2) over the contingency table, Σ C(a_i, 2), Σ C(b_j, 2).
  double same_both = 0, same_a = 0, same_b = 0;
  std::vector<double> row(ka, 0.0), col(kb, 0.0);
  for (Eigen::Index i = 0; i < n; ++i) {
    row[a(i)] += 1;
    col[b(i)] += 1;
  }
  for (double x : row) same_a += pairs(x);
  for (double x : col) same_b += pairs(x);
  if (ka * kb <= 4 * static_cast<long long>(n) + (1LL << 20)) {
    std::vector<double> table(ka * kb, 0.0);
    for (Eigen::Index i = 0; i < n; ++i) table[a(i) * kb + b(i)] += 1;
    for (double x : table) same_both += pairs(x);
  } else {
    std::vector<long long> cell(n);
    for (Eigen::Index i = 0; i < n; ++i) cell[i] = a(i) * kb + b(i);
    std::sort(cell.begin(), cell.end());
    for (size_t i = 0; i < cell.size();) {
      size_t j = i;
      while (j < cell.size() && cell[j] == cell[i]) ++j;
      same_both += pairs(double(j - i));
      i = j;
    }
  }
  // Agreements = pairs together in both + pairs apart in both.
  const double total = pairs(double(n));
  return (total + 2 * same_both - same_a - same_b) / total;
}

}  // namespace msmesh
