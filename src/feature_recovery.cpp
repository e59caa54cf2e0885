// Feature recovery of inpainting (feature_recovery.h): which holes a crease runs into, and the
// rounds of normal filtering and vertex updating on the new faces, with the piecewise-smooth
// completion of the normals, the orthogonal placement and the crease flips between them.
#include "feature_recovery.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>
#include <utility>

#include "format_number.h"
#include "msmesh/geometry.h"
#include "msmesh/normal_filter.h"
#include "msmesh/vertex_update.h"
#include "sub_mesh.h"

namespace msmesh::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;

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
Eigen::MatrixXd piecewise_smooth_normals(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                         const std::vector<bool>& is_new, const Eigen::MatrixXd& N,
                                         const Eigen::VectorXd& jump_angle_deg) {
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

}  // namespace

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
    if (dihedral(e) > sharp_rad)
      ++sharp;
    else
      other.push_back(dihedral(e) * 180.0 / kPi);
  }
  double median = 0;
  if (!other.empty()) {
    std::nth_element(other.begin(), other.begin() + static_cast<long>(other.size() / 2), other.end());
    median = other[other.size() / 2];
  }
  const bool yes = sharp >= 2 && median < o.smooth_angle;
  why = std::to_string(sharp) + " sharp edges (> " + num(o.feature_angle) +
        " deg) at its boundary, median of the others " + num(median) + " deg";
  return yes;
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
  std::vector<int> local(static_cast<size_t>(nv1), -1);
  SubMesh sub = sub_mesh(V1, F1, sub_faces, local);
  const std::vector<int>& global = sub.global;
  Eigen::MatrixXi& Fs = sub.F;
  Eigen::MatrixXd& Vs = sub.V;
  const auto nvs = static_cast<Eigen::Index>(global.size());
  const auto nfs = static_cast<Eigen::Index>(sub_faces.size());

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
    res.vertex_report =
        update_vertices(Vs, Fs, res.normal_report.normals, res.normal_report.v, o.vertices, vw, progress);
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

}  // namespace msmesh::detail
