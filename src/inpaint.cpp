#include "msmesh/inpaint.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <random>
#include <set>
#include <sstream>
#include <unordered_map>
#include <utility>

#include "hole_fill.h"
#include "msmesh/errors.h"
#include "msmesh/parameters.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/metrics.h"
#include "msmesh/presets.h"
#include "msmesh/topology.h"
#include "union_find.h"

namespace msmesh {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string num(double x) {
  std::ostringstream os;
  os.precision(4);
  os << x;
  return os.str();
}

using detail::UnionFind;

// Undirected vertex adjacency of F with edge lengths.
struct Adjacency {
  std::vector<std::vector<std::pair<int, double>>> nbr;
};

Adjacency vertex_adjacency(const Eigen::MatrixXd& V, const Topology& topo) {
  Adjacency a;
  a.nbr.resize(static_cast<size_t>(topo.num_vertices));
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
    const int i = topo.edges(e, 0), j = topo.edges(e, 1);
    const double len = (V.row(i) - V.row(j)).norm();
    a.nbr[i].emplace_back(j, len);
    a.nbr[j].emplace_back(i, len);
  }
  return a;
}

// Geodesic (Dijkstra along edges) distances from the sources, up to `limit` (larger
// distances stay +inf).
std::vector<double> dijkstra(const Adjacency& adj, const std::vector<int>& sources, double limit) {
  std::vector<double> d(adj.nbr.size(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
  for (int s : sources) {
    d[s] = 0;
    q.emplace(0.0, s);
  }
  while (!q.empty()) {
    const auto [du, u] = q.top();
    q.pop();
    if (du > d[u]) continue;
    for (const auto& [w, len] : adj.nbr[u]) {
      const double dw = du + len;
      if (dw < d[w] && dw <= limit) {
        d[w] = dw;
        q.emplace(dw, w);
      }
    }
  }
  return d;
}

// Breadth-first ring distance (in edges) from the sources, up to `limit` (-1 beyond).
std::vector<int> ring_distance(const std::vector<std::vector<int>>& nbr, const std::vector<int>& sources, int limit) {
  std::vector<int> d(nbr.size(), -1);
  std::vector<int> frontier;
  for (int s : sources)
    if (d[s] < 0) {
      d[s] = 0;
      frontier.push_back(s);
    }
  for (int k = 1; k <= limit && !frontier.empty(); ++k) {
    std::vector<int> next;
    for (int u : frontier)
      for (int w : nbr[u])
        if (d[w] < 0) {
          d[w] = k;
          next.push_back(w);
        }
    frontier = std::move(next);
  }
  return d;
}

std::vector<std::vector<int>> vertex_neighbours(const Eigen::MatrixXi& F, Eigen::Index nv) {
  std::vector<std::vector<int>> nbr(static_cast<size_t>(nv));
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      nbr[a].push_back(b);
      nbr[b].push_back(a);
    }
  for (auto& n : nbr) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  return nbr;
}

// Points hashed on a uniform grid of cell size `cell`, for "is any point within r ≤ cell".
class PointGrid {
 public:
  PointGrid(const Eigen::MatrixXd& P, const std::vector<int>& rows, double cell) : P_(P), cell_(cell) {
    for (int i : rows) cells_[key(cell_of(P.row(i)))].push_back(i);
  }
  bool any_within(const Eigen::RowVector3d& q, double r) const {
    const std::array<long long, 3> c = cell_of(q);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          auto it = cells_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (it == cells_.end()) continue;
          for (int i : it->second)
            if ((P_.row(i) - q).squaredNorm() <= r * r) return true;
        }
    return false;
  }

 private:
  std::array<long long, 3> cell_of(const Eigen::RowVector3d& p) const {
    return {static_cast<long long>(std::floor(p(0) / cell_)), static_cast<long long>(std::floor(p(1) / cell_)),
            static_cast<long long>(std::floor(p(2) / cell_))};
  }
  static unsigned long long key(const std::array<long long, 3>& c) {
    const auto u = [](long long x) { return static_cast<unsigned long long>(x) & 0x1FFFFFull; };
    return (u(c[0]) << 42) | (u(c[1]) << 21) | u(c[2]);
  }
  const Eigen::MatrixXd& P_;
  double cell_;
  std::unordered_map<unsigned long long, std::vector<int>> cells_;
};

std::vector<int> referenced_rows(const Eigen::MatrixXi& F, Eigen::Index nv) {
  std::vector<bool> used(static_cast<size_t>(nv), false);
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) used[F(f, k)] = true;
  std::vector<int> rows;
  for (Eigen::Index i = 0; i < nv; ++i)
    if (used[i]) rows.push_back(static_cast<int>(i));
  return rows;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Hole finding
// ---------------------------------------------------------------------------------------

std::vector<Hole> find_holes(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  validate_mesh(V, F, "find holes");
  std::vector<Hole> holes;
  if (F.rows() == 0) return holes;
  const Eigen::Index nv = V.rows();
  const Topology topo = build_topology(F, nv);
  double h = mean_edge_length(V, F);
  if (!(h > 0)) h = 1;

  // Boundary half-edges, directed against their face (the hole's direction).
  std::vector<std::pair<int, int>> half;  // (from, to)
  std::vector<int> half_face;
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
    if (topo.edge_face_count(e) != 1) continue;
    const int f = topo.edge_faces(e, 0);
    int k = 0;
    while (topo.face_edges(f, k) != e) ++k;
    half.emplace_back(F(f, (k + 2) % 3), F(f, (k + 1) % 3));
    half_face.push_back(f);
  }
  if (half.empty()) return holes;

  std::vector<std::vector<int>> out(static_cast<size_t>(nv));
  std::vector<int> in_degree(static_cast<size_t>(nv), 0);
  UnionFind uf(static_cast<size_t>(nv));
  for (size_t i = 0; i < half.size(); ++i) {
    out[half[i].first].push_back(static_cast<int>(i));
    ++in_degree[half[i].second];
    uf.unite(half[i].first, half[i].second);
  }
  // Group half-edges by connected boundary; order groups by their smallest vertex.
  std::unordered_map<int, std::vector<int>> groups;
  for (size_t i = 0; i < half.size(); ++i) groups[uf.find(half[i].first)].push_back(static_cast<int>(i));
  std::vector<std::pair<int, std::vector<int>>> ordered;  // (smallest vertex, half-edges)
  for (auto& [root, hs] : groups) {
    (void)root;
    int vmin = std::numeric_limits<int>::max();
    for (int i : hs) vmin = std::min({vmin, half[i].first, half[i].second});
    ordered.emplace_back(vmin, std::move(hs));
  }
  std::sort(ordered.begin(), ordered.end(), [](const auto& a, const auto& b) { return a.first < b.first; });

  int ncomp = 0;
  const Eigen::VectorXi comp = face_components(topo, &ncomp);
  std::vector<bool> used(half.size(), false);
  for (auto& [vmin, hs] : ordered) {
    Hole hole;
    hole.edges = static_cast<int>(hs.size());
    hole.component = comp(half_face[hs.front()]);
    for (int i : hs) {
      const int a = half[i].first;
      if (hole.simple && (out[a].size() != 1 || in_degree[a] != 1)) {
        hole.simple = false;
        hole.touching_vertex = a;
      }
      hole.length += (V.row(half[i].first) - V.row(half[i].second)).norm() / h;
    }
    // The closed walk (Hierholzer), starting at the smallest vertex that has an outgoing
    // half-edge; for a simple loop this is just the loop.
    int start = -1;
    for (int i : hs)
      if (start < 0 || half[i].first < start) start = half[i].first;
    std::vector<int> stack{start}, walk;
    std::unordered_map<int, size_t> next_out;
    while (!stack.empty()) {
      const int u = stack.back();
      size_t& k = next_out[u];
      while (k < out[u].size() && used[out[u][k]]) ++k;
      if (k < out[u].size()) {
        used[out[u][k]] = true;
        stack.push_back(half[out[u][k]].second);
      } else {
        walk.push_back(u);
        stack.pop_back();
      }
    }
    std::reverse(walk.begin(), walk.end());
    if (walk.size() > 1 && walk.front() == walk.back()) walk.pop_back();
    hole.loop = std::move(walk);
    // Half-edges the walk could not reach (inconsistent orientation) still belong here.
    for (int i : hs)
      if (!used[i]) {
        hole.simple = false;
        if (hole.touching_vertex < 0) hole.touching_vertex = half[i].first;
        used[i] = true;
      }
    std::vector<int> verts = hole.loop;
    std::sort(verts.begin(), verts.end());
    verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
    double d2 = 0;
    for (size_t a = 0; a < verts.size(); ++a)
      for (size_t b = a + 1; b < verts.size(); ++b) d2 = std::max(d2, (V.row(verts[a]) - V.row(verts[b])).squaredNorm());
    hole.diameter = std::sqrt(d2) / h;
    // Vector area ½ Σ p_k × p_{k+1} of the closed walk: the area of a planar loop, the
    // projected area of a bent one (a lower bound of any surface spanning it).
    Eigen::Vector3d va = Eigen::Vector3d::Zero();
    for (size_t k = 0; k < hole.loop.size(); ++k) {
      const Eigen::Vector3d p = V.row(hole.loop[k]).transpose();
      const Eigen::Vector3d q = V.row(hole.loop[(k + 1) % hole.loop.size()]).transpose();
      va += 0.5 * p.cross(q);
    }
    hole.spanned_area = va.norm() / (h * h);
    holes.push_back(std::move(hole));
  }

  // Outer-boundary rule (see the header): per component, the widest loop when the area it
  // spans is at least a quarter of the component's surface area.
  std::vector<double> comp_area(static_cast<size_t>(ncomp), 0.0);
  const Eigen::VectorXd areas = face_areas(V, F);
  for (Eigen::Index f = 0; f < F.rows(); ++f) comp_area[comp(f)] += areas(f) / (h * h);
  std::vector<int> widest(static_cast<size_t>(ncomp), -1);
  for (size_t i = 0; i < holes.size(); ++i) {
    int& w = widest[holes[i].component];
    if (w < 0 || holes[i].diameter > holes[w].diameter ||
        (holes[i].diameter == holes[w].diameter && holes[i].edges > holes[w].edges))
      w = static_cast<int>(i);
  }
  for (int c = 0; c < ncomp; ++c) {
    const int w = widest[c];
    if (w >= 0) holes[w].outer_boundary = holes[w].spanned_area >= 0.25 * comp_area[c];
  }
  return holes;
}

// ---------------------------------------------------------------------------------------
// Inpainting
// ---------------------------------------------------------------------------------------

NormalFilterOptions InpaintOptions::default_normal_options() { return inpaint_normal_options(); }

VertexUpdateOptions InpaintOptions::default_vertex_options() { return inpaint_vertex_options(); }

void InpaintOptions::validate() const {
  for (int i : holes)
    if (i < 0) throw InvalidInput("inpainting: hole index " + std::to_string(i) + " is out of range; valid: >= 0");
  check_parameters(inpaint_parameters(), *this);  // with the normal filter's and vertex update's
}

namespace {

// A filled hole as the feature recovery sees it.
struct FilledHole {
  int index = 0;                 // into InpaintResult::holes / reports
  const std::vector<int>* loop = nullptr;
  int first_face = 0, face_count = 0, first_vertex = 0, vertex_count = 0;
  double jump_angle = 60;        // degrees: normals further apart inside form the edge set
};

// Does a crease of the input run into this hole? Looks at the interior edges of the input at
// the hole's boundary vertices: at least two sharper than feature_angle (a crease enters and
// leaves, or creases meet at a corner inside), and the others mostly flat (median below
// smooth_angle), i.e. the sharp edges separate smooth patches rather than being the
// roughness of an organic surface. Returns a short description either way.
// Also returns in `weakest_crease` the smallest dihedral angle (degrees) above 30° there: the
// gentlest crease that runs into the hole (180 when there is none).
bool crease_enters(const std::vector<int>& loop, const Topology& topo, const Eigen::VectorXd& dihedral,
                   const std::vector<std::vector<int>>& vertex_edges, const InpaintOptions& o, std::string& why,
                   double& weakest_crease) {
  std::vector<int> edges;
  for (int v : loop)
    for (int e : vertex_edges[v])
      if (topo.edge_is_interior[e]) edges.push_back(e);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const double sharp_rad = o.feature_angle * kPi / 180.0;
  int sharp = 0;
  std::vector<double> other;
  weakest_crease = 180;
  for (int e : edges) {
    const double deg = dihedral(e) * 180.0 / kPi;
    if (deg > 30) weakest_crease = std::min(weakest_crease, deg);
    if (dihedral(e) > sharp_rad) ++sharp;
    else other.push_back(dihedral(e) * 180.0 / kPi);
  }
  double median = 0;
  if (!other.empty()) {
    std::nth_element(other.begin(), other.begin() + static_cast<long>(other.size() / 2), other.end());
    median = other[other.size() / 2];
  }
  const bool yes = sharp >= 2 && median < o.smooth_angle;
  why = std::to_string(sharp) + " sharp edges (> " + num(o.feature_angle) + " deg) at its boundary, median of the others " +
        num(median) + " deg";
  return yes;
}

// Angle (radians) between the normal of triangle (a, b, c) of V and the unit vector t; π when
// the triangle is degenerate.
double normal_angle(const Eigen::MatrixXd& V, int a, int b, int c, const Eigen::RowVector3d& t, double min_area2) {
  const Eigen::Vector3d ab = (V.row(b) - V.row(a)).transpose(), ac = (V.row(c) - V.row(a)).transpose();
  const Eigen::Vector3d n = ab.cross(ac);
  const double len2 = n.squaredNorm();
  if (!(len2 > min_area2)) return kPi;
  return std::acos(std::clamp(n.dot(t.transpose()) / std::sqrt(len2), -1.0, 1.0));
}

// Crease-aligning edge flips among new faces. A crease can only be rebuilt along edges: where
// the fill's triangulation has a face spanning the crease (a "bevel", e.g. a chord between two
// input vertices either side of it), no vertex position makes it match either side.
//
// A face's target normal is realisable at an input vertex when some input face at that vertex
// has a normal within 30° of it (the vertex cannot leave the surfaces it lies on); new
// vertices can go anywhere. An edge shared by two new faces is flipped when the flipped pair,
// each face taking the better of the pair's two targets, has fewer unrealisable (face, input
// vertex) incidences, or as many and a worst normal-to-target angle at least 1° smaller at the
// current positions. Only rows of new faces change. Returns the number of flips.
int flip_towards_targets(const Eigen::MatrixXd& V, Eigen::MatrixXi& F, const std::vector<bool>& is_new,
                         const Eigen::MatrixXd& targets) {
  const Eigen::Index nf = F.rows(), nv = V.rows();
  const Eigen::MatrixXd N = face_normals(V, F);
  double mean_area2 = 0;
  for (Eigen::Index f = 0; f < nf; ++f) {
    const Eigen::Vector3d ab = (V.row(F(f, 1)) - V.row(F(f, 0))).transpose();
    const Eigen::Vector3d ac = (V.row(F(f, 2)) - V.row(F(f, 0))).transpose();
    mean_area2 += ab.cross(ac).squaredNorm();
  }
  const double min_area2 = 1e-12 * mean_area2 / double(std::max<Eigen::Index>(nf, 1));
  const double margin = kPi / 180.0;
  const double realisable_cos = std::cos(kPi / 6);
  // Normals of the input faces at each vertex (none for new vertices).
  std::vector<std::vector<int>> input_faces(static_cast<size_t>(nv));
  for (Eigen::Index f = 0; f < nf; ++f)
    if (!is_new[f])
      for (int k = 0; k < 3; ++k) input_faces[F(f, k)].push_back(static_cast<int>(f));
  auto unrealisable = [&](int a, int b, int c, const Eigen::RowVector3d& t) {
    int count = 0;
    for (int v : {a, b, c}) {
      if (input_faces[v].empty()) continue;
      bool ok = false;
      for (int g : input_faces[v]) ok = ok || N.row(g).dot(t) >= realisable_cos;
      if (!ok) ++count;
    }
    return count;
  };
  Eigen::MatrixXd T = targets;  // target of each face; flipped faces take their better one
  int flips = 0;
  auto key = [](int a, int b) {
    return (static_cast<unsigned long long>(static_cast<unsigned>(a)) << 32) | static_cast<unsigned>(b);
  };
  for (int pass = 0; pass < 10; ++pass) {
    std::unordered_map<unsigned long long, int> walk;  // directed edge (a → b) → face walking it
    for (Eigen::Index f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) walk[key(F(f, k), F(f, (k + 1) % 3))] = static_cast<int>(f);
    int pass_flips = 0;
    std::vector<bool> touched(static_cast<size_t>(nf), false);
    for (Eigen::Index f = 0; f < nf; ++f) {
      if (!is_new[f] || touched[f]) continue;
      for (int k = 0; k < 3; ++k) {
        const int a = F(f, k), b = F(f, (k + 1) % 3), c = F(f, (k + 2) % 3);
        auto it = walk.find(key(b, a));
        if (it == walk.end()) continue;
        const int g = it->second;
        if (!is_new[g] || touched[g] || g == f) continue;
        int d = -1;
        for (int j = 0; j < 3; ++j)
          if (F(g, j) != a && F(g, j) != b) d = F(g, j);
        if (d < 0 || d == c || walk.count(key(c, d)) || walk.count(key(d, c))) continue;
        const Eigen::RowVector3d tf = T.row(f), tg = T.row(g);
        // Flipped faces: (c, a, d) and (d, b, c); each takes the better target.
        auto score = [&](int x, int y, int z, const Eigen::RowVector3d& t) {
          return std::make_pair(unrealisable(x, y, z, t), normal_angle(V, x, y, z, t, min_area2));
        };
        const auto f_f = score(c, a, d, tf), f_g = score(c, a, d, tg);
        const auto g_f = score(d, b, c, tf), g_g = score(d, b, c, tg);
        const auto f_new = std::min(f_f, f_g), g_new = std::min(g_f, g_g);
        const auto f_old = score(a, b, c, tf), g_old = score(b, a, d, tg);
        const int bad_old = f_old.first + g_old.first, bad_new = f_new.first + g_new.first;
        const double worst_old = std::max(f_old.second, g_old.second);
        const double worst_new = std::max(f_new.second, g_new.second);
        const bool better = bad_new < bad_old || (bad_new == bad_old && worst_new < worst_old - margin);
        if (!better || worst_new >= kPi - 1e-9) continue;  // never create a degenerate face
        F.row(f) << c, a, d;
        F.row(g) << d, b, c;
        T.row(f) = (f_f <= f_g) ? tf : tg;
        T.row(g) = (g_f <= g_g) ? tf : tg;
        touched[f] = touched[g] = true;
        ++pass_flips;
        break;
      }
    }
    flips += pass_flips;
    if (pass_flips == 0) break;
  }
  return flips;
}

// The Mumford–Shah reading of the filtered normals inside the holes: keep NMSTV's edge set, but
// make the normals smooth away from it. NMSTV's total-variation-like term (φ grows linearly)
// has no reason to bend the normals smoothly across a hole — with almost no fidelity inside,
// a curved surface comes back as flat facets (a cylinder's rim as a chord). Here the new
// faces' normals are recomputed as the harmonic interpolation (face-graph Laplacian, weights
// len(e)/|b_f − b_g|) of the surrounding normals, with no coupling across jump edges (filtered
// normals more than the hole's jump angle apart) — the edge set — and a weak pull (1e-3) towards the
// NMSTV normals so that a region enclosed by jumps stays determined. Rows are renormalised.
Eigen::MatrixXd piecewise_smooth_normals(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::vector<bool>& is_new,
                                         const Eigen::MatrixXd& N, const Eigen::VectorXd& jump_angle_deg) {
  const Eigen::Index nf = F.rows();
  std::vector<int> unknown(static_cast<size_t>(nf), -1);
  int n = 0;
  for (Eigen::Index f = 0; f < nf; ++f)
    if (is_new[f]) unknown[f] = n++;
  if (n == 0) return N;
  const Topology topo = build_topology(F, V.rows());
  const Eigen::MatrixXd B = face_barycenters(V, F);
  const Eigen::VectorXd len = edge_lengths(V, topo);
  using Triplet = Eigen::Triplet<double>;
  std::vector<Triplet> trip;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 3);
  const double pull = 1e-3;
  for (Eigen::Index f = 0; f < nf; ++f)
    if (unknown[f] >= 0) {
      trip.emplace_back(unknown[f], unknown[f], pull);
      rhs.row(unknown[f]) += pull * N.row(f);
    }
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
    if (!topo.edge_is_interior[e]) continue;
    const int f = topo.edge_faces(e, 0), g = topo.edge_faces(e, 1);
    const int a = unknown[f], b = unknown[g];
    if (a < 0 && b < 0) continue;
    // An edge of the edge set (threshold of the new face's hole): no coupling.
    const double jump = jump_angle_deg(a >= 0 ? f : g);
    if (N.row(f).dot(N.row(g)) < std::cos(jump * kPi / 180.0)) continue;
    const double w = len(e) / std::max((B.row(f) - B.row(g)).norm(), 1e-12 * len(e) + 1e-300);
    if (a >= 0) trip.emplace_back(a, a, w);
    if (b >= 0) trip.emplace_back(b, b, w);
    if (a >= 0 && b >= 0) {
      trip.emplace_back(a, b, -w);
      trip.emplace_back(b, a, -w);
    }
    if (a >= 0 && b < 0) rhs.row(a) += w * N.row(g);
    if (b >= 0 && a < 0) rhs.row(b) += w * N.row(f);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(trip.begin(), trip.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) return N;
  const Eigen::MatrixXd X = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !X.allFinite()) return N;
  Eigen::MatrixXd out = N;
  for (Eigen::Index f = 0; f < nf; ++f)
    if (unknown[f] >= 0) {
      const double l = X.row(unknown[f]).norm();
      if (l > 1e-12) out.row(f) = X.row(unknown[f]) / l;
    }
  return out;
}

// Initial placement of the free vertices for the vertex update: the positions that make every
// edge of every face with a free vertex orthogonal to the face's target normal (the linear
// constraint behind Algorithm 2's normal matching, Taubin 2001 / Sun et al. 2007), plus a small
// membrane term μ Σ‖x_i − x_j‖² over edges with a free end that spreads the vertices
// tangentially, and weight `anchor` towards their current position for freed input vertices:
//   min Σ_f Σ_{(i,j) ∈ f} (n_f·(x_i − x_j))² + μ Σ_e ‖x_i − x_j‖² + anchor Σ_ring ‖x_i − x_i⁰‖².
// Convex and solved once: it reaches shapes (a corner out of a round blob) that the local/global
// iteration of Algorithm 2 only approaches through folds. Returns false if the solve fails
// (the positions are then left as they were).
bool place_by_orthogonality(Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::vector<int>& free_index,
                            const std::vector<bool>& anchored, const Eigen::MatrixXd& targets, double mu,
                            double anchor) {
  int n = 0;
  for (int i : free_index) n = std::max(n, i + 1);
  if (n == 0) return true;
  using Triplet = Eigen::Triplet<double>;
  std::vector<Triplet> trip;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(3 * n);
  // Adds (x_i − x_j)ᵀ M (x_i − x_j) to the energy; fixed vertices go to the right-hand side.
  auto add_pair = [&](int i, int j, const Eigen::Matrix3d& M) {
    const int a = free_index[i], b = free_index[j];
    if (a < 0 && b < 0) return;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        const double m = M(r, c);
        if (a >= 0) trip.emplace_back(3 * a + r, 3 * a + c, m);
        if (b >= 0) trip.emplace_back(3 * b + r, 3 * b + c, m);
        if (a >= 0 && b >= 0) {
          trip.emplace_back(3 * a + r, 3 * b + c, -m);
          trip.emplace_back(3 * b + r, 3 * a + c, -m);
        }
        if (a >= 0 && b < 0) rhs(3 * a + r) += m * V(j, c);
        if (b >= 0 && a < 0) rhs(3 * b + r) += m * V(i, c);
      }
  };
  std::set<std::pair<int, int>> edges;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    bool any = false;
    for (int k = 0; k < 3; ++k) any = any || free_index[F(f, k)] >= 0;
    if (!any) continue;
    const Eigen::Vector3d t = targets.row(f).transpose();
    const Eigen::Matrix3d M = t * t.transpose();
    for (int k = 0; k < 3; ++k) {
      const int i = F(f, k), j = F(f, (k + 1) % 3);
      add_pair(i, j, M);
      edges.emplace(std::min(i, j), std::max(i, j));
    }
  }
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  for (const auto& [i, j] : edges) add_pair(i, j, mu * I);
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    const int a = free_index[i];
    if (a < 0 || !anchored[i]) continue;
    for (int r = 0; r < 3; ++r) {
      trip.emplace_back(3 * a + r, 3 * a + r, anchor);
      rhs(3 * a + r) += anchor * V(i, r);
    }
  }
  Eigen::SparseMatrix<double> A(3 * n, 3 * n);
  A.setFromTriplets(trip.begin(), trip.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
  if (solver.info() != Eigen::Success) return false;
  const Eigen::VectorXd x = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !x.allFinite()) return false;
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    if (free_index[i] >= 0) V.row(i) = x.segment<3>(3 * free_index[i]).transpose();
  return true;
}

// Feature recovery on the filled mesh (V1, F1), in place: the paper's §6.2 weighting on a
// submesh made of the new faces of the holes in `holes` and `context_rings` rings of faces
// around them. Everything outside those holes is pinned.
void recover_features(Eigen::MatrixXd& V1, Eigen::MatrixXi& F1, Eigen::Index nv0, Eigen::Index nf0,
                      const std::vector<FilledHole>& holes, const InpaintOptions& o, const ProgressCallback& progress,
                      InpaintResult& res) {
  const Eigen::Index nv1 = V1.rows(), nf1 = F1.rows();
  const auto nbr = vertex_neighbours(F1, nv1);

  std::vector<bool> is_free(static_cast<size_t>(nv1), false), new_face(static_cast<size_t>(nf1), false);
  std::vector<int> boundary, seeds;
  for (const FilledHole& h : holes) {
    boundary.insert(boundary.end(), h.loop->begin(), h.loop->end());
    for (int i = h.first_vertex; i < h.first_vertex + h.vertex_count; ++i) {
      is_free[i] = true;
      seeds.push_back(i);
    }
    for (int f = h.first_face; f < h.first_face + h.face_count; ++f) new_face[f] = true;
  }
  seeds.insert(seeds.end(), boundary.begin(), boundary.end());
  // Freed input vertices: within free_ring − 1 edges of a hole's boundary, along input faces.
  if (o.free_ring > 0) {
    const auto nbr0 = vertex_neighbours(F1.topRows(nf0), nv0);
    const std::vector<int> d = ring_distance(nbr0, boundary, o.free_ring - 1);
    for (Eigen::Index i = 0; i < nv0; ++i)
      if (d[i] >= 0) {
        is_free[i] = true;
        ++res.moved_input_vertices;
      }
  }

  // The working region: faces touching a vertex within context_rings of the filled region.
  const std::vector<int> dist = ring_distance(nbr, seeds, o.context_rings);
  std::vector<int> sub_faces;
  for (Eigen::Index f = 0; f < nf1; ++f) {
    bool in = new_face[f];
    for (int k = 0; k < 3 && !in; ++k) in = dist[F1(f, k)] >= 0 && dist[F1(f, k)] < o.context_rings;
    if (in) sub_faces.push_back(static_cast<int>(f));
  }
  std::vector<int> local(static_cast<size_t>(nv1), -1), global;
  Eigen::MatrixXi Fs(static_cast<Eigen::Index>(sub_faces.size()), 3);
  for (size_t s = 0; s < sub_faces.size(); ++s)
    for (int k = 0; k < 3; ++k) {
      const int g = F1(sub_faces[s], k);
      if (local[g] < 0) {
        local[g] = static_cast<int>(global.size());
        global.push_back(g);
      }
      Fs(static_cast<Eigen::Index>(s), k) = local[g];
    }
  const auto nvs = static_cast<Eigen::Index>(global.size());
  const auto nfs = static_cast<Eigen::Index>(sub_faces.size());
  Eigen::MatrixXd Vs(nvs, 3);
  for (Eigen::Index i = 0; i < nvs; ++i) Vs.row(i) = V1.row(global[i]);

  // Weights (paper §6.2): α large outside, ≈0 inside (the fill's normals carry no information);
  // β/10 on edges of new faces; ω₃ pinning outside, very small inside.
  std::vector<bool> sub_new(static_cast<size_t>(nfs));
  for (Eigen::Index s = 0; s < nfs; ++s) sub_new[s] = new_face[sub_faces[s]];
  Eigen::VectorXd jump_angle = Eigen::VectorXd::Constant(nfs, 60.0);  // per submesh face, degrees
  {
    std::vector<double> face_jump(static_cast<size_t>(nf1), 60.0);
    for (const FilledHole& h : holes)
      for (int f = h.first_face; f < h.first_face + h.face_count; ++f) face_jump[f] = h.jump_angle;
    for (Eigen::Index s = 0; s < nfs; ++s) jump_angle(s) = face_jump[sub_faces[s]];
  }
  NormalFilterWeights nw;
  nw.face_alpha.resize(nfs);
  for (Eigen::Index s = 0; s < nfs; ++s) nw.face_alpha(s) = sub_new[s] ? o.inside_alpha : o.outside_alpha;
  VertexUpdateWeights vw;
  vw.vertex_omega3.resize(nvs);
  for (Eigen::Index i = 0; i < nvs; ++i) {
    const int g = global[i];
    vw.vertex_omega3(i) = g >= nv0 && is_free[g] ? o.inside_omega3 : (is_free[g] ? o.ring_omega3 : o.pinned_omega3);
  }

  // Rounds of normal filtering + vertex update; crease flips after each, and up to two extra
  // rounds while the last one still flipped (the vertices must follow the new connectivity).
  std::vector<int> free_index(static_cast<size_t>(nvs), -1);
  std::vector<bool> anchored(static_cast<size_t>(nvs), false);
  {
    int next = 0;
    for (Eigen::Index i = 0; i < nvs; ++i)
      if (is_free[global[i]]) {
        free_index[i] = next++;
        anchored[i] = global[i] < nv0;  // freed input vertices stay near where they were
      }
  }
  for (int round = 0, flipped = 0; round < o.rounds || (flipped > 0 && round < o.rounds + 2); ++round) {
    const Topology topo = build_topology(Fs, nvs);  // the flips below change it between rounds
    nw.edge_beta = Eigen::VectorXd::Ones(topo.num_edges());
    for (Eigen::Index s = 0; s < nfs; ++s)
      if (sub_new[s])
        for (int k = 0; k < 3; ++k) nw.edge_beta(topo.face_edges(s, k)) = o.inside_beta;
    res.normal_report = filter_normals(Vs, Fs, o.normals, nw, progress);
    if (o.smooth_normals)
      res.normal_report.normals = piecewise_smooth_normals(Vs, Fs, sub_new, res.normal_report.normals, jump_angle);
    if (o.orthogonal_placement) {
      // Lengths in mean-edge units keep μ and the anchor weight scale-free.
      const double len = mean_edge_length(Vs, Fs);
      Eigen::MatrixXd Vn = Vs / len;
      if (place_by_orthogonality(Vn, Fs, free_index, anchored, res.normal_report.normals, o.placement_smoothing, 1.0))
        for (Eigen::Index i = 0; i < nvs; ++i)
          if (free_index[i] >= 0) Vs.row(i) = Vn.row(i) * len;
    }
    res.vertex_report = update_vertices(Vs, Fs, res.normal_report.normals, res.normal_report.v, o.vertices, vw, progress);
    // Only free vertices take the update; pinned ones keep their exact positions.
    for (Eigen::Index i = 0; i < nvs; ++i)
      if (is_free[global[i]]) Vs.row(i) = res.vertex_report.V.row(i);
    flipped = o.crease_flips ? flip_towards_targets(Vs, Fs, sub_new, res.normal_report.normals) : 0;
    res.crease_flips += flipped;
  }
  for (Eigen::Index i = 0; i < nvs; ++i)
    if (is_free[global[i]]) V1.row(global[i]) = Vs.row(i);
  for (Eigen::Index s = 0; s < nfs; ++s)
    if (sub_new[s])
      for (int k = 0; k < 3; ++k) F1(sub_faces[s], k) = global[Fs(s, k)];
}

}  // namespace

InpaintResult inpaint(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const InpaintOptions& o,
                      const ProgressCallback& progress) {
  o.validate();
  validate_mesh(V, F, "inpainting");
  InpaintResult res;
  res.V = V;
  res.F = F;
  res.new_faces.assign(static_cast<size_t>(F.rows()), false);
  res.new_vertices.assign(static_cast<size_t>(V.rows()), false);
  res.holes = find_holes(V, F);
  const auto nh = static_cast<int>(res.holes.size());
  for (int i : o.holes)
    if (i >= nh) {
      std::ostringstream os;
      os << "inpainting: hole index " << i << " does not exist (the mesh has " << nh << " holes)";
      throw InvalidInput(os.str());
    }
  res.reports.resize(res.holes.size());
  std::vector<int> selected;  // indices of holes handed to CGAL
  std::vector<bool> listed(res.holes.size(), o.holes.empty());
  for (int i : o.holes) listed[i] = true;
  for (int i = 0; i < nh; ++i) {
    const Hole& hole = res.holes[i];
    HoleReport& r = res.reports[i];
    r.index = i;
    r.action = HoleAction::Skipped;
    if (!listed[i]) {
      r.reason = "not in the list of holes to fill";
    } else if (!hole.simple) {
      r.reason = "its boundary touches itself at vertex " + std::to_string(hole.touching_vertex) +
                 " (not a simple loop)";
    } else if (o.holes.empty() && hole.outer_boundary && !o.fill_outer_boundary) {
      r.reason = "outer boundary of an open surface (diameter " + num(hole.diameter) +
                 " mean edge lengths, at least half its component's bounding-box diagonal)";
    } else if (o.holes.empty() && o.max_hole_edges > 0 && hole.edges > o.max_hole_edges) {
      r.reason = std::to_string(hole.edges) + " boundary edges > max_hole_edges " + std::to_string(o.max_hole_edges);
    } else if (o.holes.empty() && o.max_hole_diameter > 0 && hole.diameter > o.max_hole_diameter) {
      r.reason = "diameter " + num(hole.diameter) + " mean edge lengths > max_hole_diameter " + num(o.max_hole_diameter);
    } else {
      selected.push_back(i);
    }
  }

  const auto t0 = std::chrono::steady_clock::now();
  std::vector<FilledHole> filled;
  if (!selected.empty()) {
    std::vector<std::vector<int>> loops;
    for (int i : selected) loops.push_back(res.holes[i].loop);
    const double density = o.density > 0 ? o.density : (o.recover_features ? o.feature_density : std::sqrt(2.0));
    detail::CgalFillResult fill = detail::fill_holes_cgal(V, F, loops, density, true);
    for (size_t s = 0; s < selected.size(); ++s) {
      const detail::CgalHoleOutcome& out = fill.holes[s];
      HoleReport& r = res.reports[selected[s]];
      if (out.filled) {
        r.action = HoleAction::Filled;
        r.new_faces = out.face_count;
        r.new_vertices = out.vertex_count;
        r.faired = out.faired;
        FilledHole fh;
        fh.index = selected[s];
        fh.loop = &res.holes[selected[s]].loop;
        fh.first_face = out.first_face;
        fh.face_count = out.face_count;
        fh.first_vertex = out.first_vertex;
        fh.vertex_count = out.vertex_count;
        filled.push_back(fh);
      } else {
        r.action = HoleAction::Failed;
        r.reason = out.error;
      }
    }
    res.V = std::move(fill.V);
    res.F = std::move(fill.F);
    res.new_faces.assign(static_cast<size_t>(res.F.rows()), false);
    res.new_vertices.assign(static_cast<size_t>(res.V.rows()), false);
    for (Eigen::Index f = F.rows(); f < res.F.rows(); ++f) res.new_faces[f] = true;
    for (Eigen::Index i = V.rows(); i < res.V.rows(); ++i) res.new_vertices[i] = true;
  }
  for (const HoleReport& r : res.reports) {
    if (r.action == HoleAction::Filled) ++res.filled;
    else if (r.action == HoleAction::Skipped) ++res.skipped;
    else ++res.failed;
  }
  const auto t1 = std::chrono::steady_clock::now();
  res.seconds_fill = std::chrono::duration<double>(t1 - t0).count();

  if (o.recover_features && !filled.empty()) {
    // Which holes have a crease running into them (the others keep CGAL's smooth fair patch,
    // which is what a smooth surface wants: docs/inpainting.md).
    const Topology topo = build_topology(F, V.rows());
    const Eigen::VectorXd dihedral = dihedral_angles(V, F, topo);
    std::vector<std::vector<int>> vertex_edges(static_cast<size_t>(V.rows()));
    for (Eigen::Index e = 0; e < topo.num_edges(); ++e) {
      vertex_edges[topo.edges(e, 0)].push_back(static_cast<int>(e));
      vertex_edges[topo.edges(e, 1)].push_back(static_cast<int>(e));
    }
    std::vector<FilledHole> featured;
    for (FilledHole& h : filled) {
      HoleReport& r = res.reports[h.index];
      double weakest = 180;
      const bool yes = crease_enters(*h.loop, topo, dihedral, vertex_edges, o, r.features_reason, weakest);
      h.jump_angle = o.smooth_jump_angle > 0 ? o.smooth_jump_angle : std::clamp(0.75 * weakest, 20.0, 60.0);
      r.features = o.all_holes_featured || yes;
      if (o.all_holes_featured && !yes) r.features_reason += " (forced)";
      // A patch without new vertices can still gain from the crease flips.
      if (r.features) featured.push_back(h);
    }
    res.featured = static_cast<int>(featured.size());
    if (!featured.empty()) recover_features(res.V, res.F, V.rows(), F.rows(), featured, o, progress, res);
  }
  res.seconds_features = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  return res;
}

// ---------------------------------------------------------------------------------------
// Error figures
// ---------------------------------------------------------------------------------------

InpaintErrors inpaint_errors(const Eigen::MatrixXd& V_input, const Eigen::MatrixXi& F_input,
                             const Eigen::MatrixXd& V_result, const Eigen::MatrixXi& F_result,
                             const std::vector<bool>& new_faces, const Eigen::MatrixXd& V_truth,
                             const Eigen::MatrixXi& F_truth) {
  validate_mesh(V_input, F_input, "inpainting errors: input");
  validate_mesh(V_result, F_result, "inpainting errors: result");
  validate_mesh(V_truth, F_truth, "inpainting errors: truth");
  if (F_truth.rows() == 0 || F_result.rows() == 0)
    throw InvalidInput("inpainting errors: the result and the truth need faces");
  if (!new_faces.empty() && new_faces.size() != static_cast<size_t>(F_result.rows()))
    throw InvalidInput("inpainting errors: new_faces must have one flag per result face");
  const std::vector<int> truth_rows = referenced_rows(F_truth, V_truth.rows());
  Eigen::MatrixXd truth_pts(static_cast<Eigen::Index>(truth_rows.size()), 3);
  for (size_t i = 0; i < truth_rows.size(); ++i) truth_pts.row(static_cast<Eigen::Index>(i)) = V_truth.row(truth_rows[i]);
  const double diag = bounding_box_diagonal(truth_pts);
  if (!(diag > 0)) throw InvalidInput("inpainting errors: the truth has a zero-size bounding box");

  double h = F_input.rows() ? mean_edge_length(V_input, F_input) : 0;
  if (!(h > 0)) h = mean_edge_length(V_truth, F_truth);
  const double t = 0.1 * h;
  const std::vector<int> input_rows = referenced_rows(F_input, V_input.rows());
  const PointGrid grid(V_input, input_rows, t);

  auto far_points = [&](const Eigen::MatrixXd& P, const std::vector<int>& rows) {
    std::vector<int> keep;
    for (int i : rows)
      if (!grid.any_within(P.row(i), t)) keep.push_back(i);
    Eigen::MatrixXd Q(static_cast<Eigen::Index>(keep.size()), 3);
    for (size_t k = 0; k < keep.size(); ++k) Q.row(static_cast<Eigen::Index>(k)) = P.row(keep[k]);
    return Q;
  };
  const Eigen::MatrixXd missing = far_points(V_truth, truth_rows);
  const Eigen::MatrixXd added = far_points(V_result, referenced_rows(F_result, V_result.rows()));
  std::vector<double> d;
  if (missing.rows()) {
    const Eigen::VectorXd a = SurfaceDistance(V_result, F_result).distances(missing);
    d.insert(d.end(), a.data(), a.data() + a.size());
  }
  const SurfaceDistance truth_surface(V_truth, F_truth);
  if (added.rows()) {
    const Eigen::VectorXd b = truth_surface.distances(added);
    d.insert(d.end(), b.data(), b.data() + b.size());
  }
  InpaintErrors e;
  e.points = static_cast<Eigen::Index>(d.size());
  double sum = 0, sum2 = 0;
  for (double x : d) {
    e.max = std::max(e.max, x / diag);
    sum += x / diag;
    sum2 += (x / diag) * (x / diag);
  }
  if (!d.empty()) {
    e.mean = sum / double(d.size());
    e.rms = std::sqrt(sum2 / double(d.size()));
  }

  std::vector<int> nf;
  for (Eigen::Index f = 0; f < F_result.rows(); ++f)
    if (new_faces.empty() ? f >= F_input.rows() : new_faces[f]) nf.push_back(static_cast<int>(f));
  e.new_faces = static_cast<Eigen::Index>(nf.size());
  if (!nf.empty()) {
    Eigen::MatrixXi Fn(e.new_faces, 3);
    for (size_t k = 0; k < nf.size(); ++k) Fn.row(static_cast<Eigen::Index>(k)) = F_result.row(nf[k]);
    const Eigen::MatrixXd Nn = face_normals(V_result, Fn);
    const Eigen::MatrixXd B = face_barycenters(V_result, Fn);
    const Eigen::VectorXi cf = detail::closest_faces(V_truth, F_truth, B);
    const Eigen::MatrixXd Nt = face_normals(V_truth, F_truth);
    double s = 0;
    for (Eigen::Index k = 0; k < e.new_faces; ++k) {
      const Eigen::RowVector3d a = Nn.row(k), b = Nt.row(cf(k));
      s += (a.squaredNorm() == 0 || b.squaredNorm() == 0) ? 90.0
                                                          : std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * 180.0 / kPi;
    }
    e.mean_normal_error_deg = s / double(e.new_faces);
  }
  return e;
}

// ---------------------------------------------------------------------------------------
// Hole puncher
// ---------------------------------------------------------------------------------------

PunchResult punch_holes(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, int count, double radius,
                        std::uint64_t seed, bool on_features) {
  validate_mesh(V, F, "punch holes");
  if (count < 0) throw InvalidInput("punch holes: count = " + std::to_string(count) + " must be >= 0");
  if (!(std::isfinite(radius) && radius > 0)) throw InvalidInput("punch holes: radius = " + num(radius) + " must be > 0");
  const Eigen::Index nv = V.rows(), nf = F.rows();
  const Topology topo = build_topology(F, nv);
  const Adjacency adj = vertex_adjacency(V, topo);
  const double h = nf ? mean_edge_length(V, F) : 0;

  // Faces around each vertex.
  std::vector<std::vector<int>> vf(static_cast<size_t>(nv));
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) vf[F(f, k)].push_back(static_cast<int>(f));
  std::vector<bool> face_removed(static_cast<size_t>(nf), false), removed(static_cast<size_t>(nv), false);

  // Vertices near an existing boundary or non-manifold edge are off limits.
  std::vector<int> irregular;
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e)
    if (!topo.edge_is_interior[e]) {
      irregular.push_back(topo.edges(e, 0));
      irregular.push_back(topo.edges(e, 1));
    }
  std::vector<bool> blocked(static_cast<size_t>(nv), false);
  {
    const std::vector<double> d = dijkstra(adj, irregular, 3 * h);
    for (Eigen::Index i = 0; i < nv; ++i) blocked[i] = std::isfinite(d[i]) || vf[i].empty();
  }

  std::vector<int> candidates;
  if (on_features) {
    const Eigen::VectorXd dihedral = dihedral_angles(V, F, topo);
    std::vector<bool> sharp(static_cast<size_t>(nv), false);
    for (Eigen::Index e = 0; e < topo.num_edges(); ++e)
      if (dihedral(e) > kPi / 3) sharp[topo.edges(e, 0)] = sharp[topo.edges(e, 1)] = true;
    for (Eigen::Index i = 0; i < nv; ++i)
      if (sharp[i]) candidates.push_back(static_cast<int>(i));
  } else {
    for (Eigen::Index i = 0; i < nv; ++i)
      if (!vf[i].empty()) candidates.push_back(static_cast<int>(i));
  }
  std::mt19937_64 rng(seed);
  for (size_t i = candidates.size(); i > 1; --i) std::swap(candidates[i - 1], candidates[rng() % i]);

  // Boundary degree of u once the faces touching `disk` are gone as well: the number of its
  // edges with exactly one remaining face; 0 remaining faces means u would be cut off.
  auto boundary_degree = [&](int u, const std::vector<bool>& in_disk, int* remaining) {
    std::unordered_map<int, int> edge_count;
    *remaining = 0;
    for (int f : vf[u]) {
      if (face_removed[f]) continue;
      bool gone = false;
      for (int k = 0; k < 3; ++k) gone = gone || in_disk[F(f, k)];
      if (gone) continue;
      ++*remaining;
      for (int k = 0; k < 3; ++k)
        if (F(f, k) != u) ++edge_count[F(f, k)];
    }
    int deg = 0;
    for (const auto& [w, c] : edge_count) {
      (void)w;
      if (c == 1) ++deg;
    }
    return deg;
  };

  PunchResult res;
  std::vector<bool> in_disk(static_cast<size_t>(nv), false);
  for (int c : candidates) {
    if (res.punched >= count) break;
    if (blocked[c] || removed[c]) continue;
    const std::vector<double> d = dijkstra(adj, {c}, radius * h);
    std::vector<int> disk;
    bool ok = true;
    for (Eigen::Index i = 0; i < nv && ok; ++i)
      if (std::isfinite(d[i])) {
        if (blocked[i]) ok = false;
        disk.push_back(static_cast<int>(i));
      }
    if (!ok) continue;
    for (int i : disk) in_disk[i] = true;
    // Grow the disk until every vertex on its rim has one gap in its fan (a simple loop).
    const size_t initial = disk.size();
    for (bool changed = true; changed && ok;) {
      changed = false;
      std::vector<int> rim;
      for (int i : disk)
        for (const auto& [w, len] : adj.nbr[i]) {
          (void)len;
          if (!in_disk[w]) rim.push_back(w);
        }
      std::sort(rim.begin(), rim.end());
      rim.erase(std::unique(rim.begin(), rim.end()), rim.end());
      for (int u : rim) {
        int remaining = 0;
        const int deg = boundary_degree(u, in_disk, &remaining);
        if (remaining == 0 || deg > 2) {
          if (blocked[u]) ok = false;
          in_disk[u] = true;
          disk.push_back(u);
          changed = true;
        }
      }
      if (disk.size() > 4 * initial + 16) ok = false;
    }
    if (!ok) {
      for (int i : disk) in_disk[i] = false;
      continue;
    }
    for (int i : disk) {
      removed[i] = true;
      for (int f : vf[i]) face_removed[f] = true;
    }
    for (int i : disk) in_disk[i] = false;
    // Keep later holes three mean edge lengths away from this one.
    const std::vector<double> near = dijkstra(adj, disk, 3 * h);
    for (Eigen::Index i = 0; i < nv; ++i)
      if (std::isfinite(near[i])) blocked[i] = true;
    res.centers.push_back(c);
    ++res.punched;
  }

  // Compact: keep remaining faces in order, drop unreferenced vertices.
  std::vector<bool> used(static_cast<size_t>(nv), false);
  Eigen::Index kept = 0;
  for (Eigen::Index f = 0; f < nf; ++f)
    if (!face_removed[f]) {
      ++kept;
      for (int k = 0; k < 3; ++k) used[F(f, k)] = true;
    }
  res.old_to_new = Eigen::VectorXi::Constant(nv, -1);
  std::vector<int> map;
  for (Eigen::Index i = 0; i < nv; ++i)
    if (used[i]) {
      res.old_to_new(i) = static_cast<int>(map.size());
      map.push_back(static_cast<int>(i));
    }
  res.vertex_map = Eigen::Map<const Eigen::VectorXi>(map.data(), static_cast<Eigen::Index>(map.size()));
  res.V.resize(static_cast<Eigen::Index>(map.size()), 3);
  for (size_t i = 0; i < map.size(); ++i) res.V.row(static_cast<Eigen::Index>(i)) = V.row(map[i]);
  res.F.resize(kept, 3);
  Eigen::Index r = 0;
  for (Eigen::Index f = 0; f < nf; ++f)
    if (!face_removed[f]) {
      for (int k = 0; k < 3; ++k) res.F(r, k) = res.old_to_new(F(f, k));
      ++r;
    }
  return res;
}

}  // namespace msmesh
