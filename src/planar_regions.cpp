// Planar regions of the filtered normals (docs/presets.md, "Planar regions"). Algorithm 1 leaves
// a flat part of a CAD model as plateaus of a few dozen faces, each tilted by the mean of its own
// faces' noise (the meshtgv fandisk: 2.8° RMS on its flat faces, 0.07° between neighbours);
// the plane through all of the part's vertices averages the noise over the whole part instead.
#include "planar_regions.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "msmesh/geometry.h"
#include "union_find.h"

namespace msmesh::detail {

PlanarRegions snap_planar_regions(const PreparedMesh& mesh, Eigen::MatrixXd& N, int min_faces) {
  PlanarRegions out;
  const Eigen::Index nf = mesh.num_faces();
  if (min_faces <= 0) return out;
  out.snapped.assign(static_cast<std::size_t>(nf), false);
  if (nf < min_faces) return out;
  const Topology& t = mesh.topology();
  const Eigen::MatrixXi& F = mesh.faces();
  const Eigen::MatrixXd& X = mesh.positions();
  const double cos_neighbour = std::cos(kPlaneNeighbourDeg * M_PI / 180);
  const double cos_spread = std::cos(kPlaneSpreadDeg * M_PI / 180);

  UnionFind sets(static_cast<std::size_t>(nf));
  for (Eigen::Index e = 0; e < t.num_edges(); ++e) {
    if (!t.edge_is_interior[static_cast<std::size_t>(e)]) continue;
    const int f = t.edge_faces(e, 0), g = t.edge_faces(e, 1);
    if (N.row(f).dot(N.row(g)) > cos_neighbour) sets.unite(f, g);
  }
  // The faces of each region, in face order (a counting sort by root).
  std::vector<int> root(static_cast<std::size_t>(nf)), start(static_cast<std::size_t>(nf) + 1, 0);
  for (Eigen::Index f = 0; f < nf; ++f) {
    root[f] = sets.find(static_cast<int>(f));
    ++start[root[f] + 1];
  }
  for (Eigen::Index f = 0; f < nf; ++f) start[f + 1] += start[f];
  std::vector<int> faces(static_cast<std::size_t>(nf)), fill(start.begin(), start.end() - 1);
  for (Eigen::Index f = 0; f < nf; ++f) faces[fill[root[f]]++] = static_cast<int>(f);

  const Eigen::VectorXd area = face_areas(X, F);
  std::vector<int> seen(static_cast<std::size_t>(X.rows()), -1), vertices;
  for (Eigen::Index r = 0; r < nf; ++r) {
    const int* begin = faces.data() + start[r];
    const int* end = faces.data() + start[r + 1];
    if (end - begin < min_faces) continue;
    Eigen::RowVector3d mean = Eigen::RowVector3d::Zero();
    for (const int* f = begin; f != end; ++f) mean += area(*f) * N.row(*f);
    if (!(mean.norm() > 0)) continue;
    mean.normalize();
    if (std::any_of(begin, end, [&](int f) { return N.row(f).dot(mean) < cos_spread; })) continue;
    vertices.clear();
    for (const int* f = begin; f != end; ++f)
      for (int k = 0; k < 3; ++k) {
        const int v = F(*f, k);
        if (seen[v] == r) continue;
        seen[v] = static_cast<int>(r);
        vertices.push_back(v);
      }
    Eigen::RowVector3d centre = Eigen::RowVector3d::Zero();
    for (const int v : vertices) centre += X.row(v);
    centre /= static_cast<double>(vertices.size());
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const int v : vertices) {
      const Eigen::RowVector3d d = X.row(v) - centre;
      scatter += d.transpose() * d;
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);
    if (eig.info() != Eigen::Success) continue;
    Eigen::RowVector3d plane = eig.eigenvectors().col(0).transpose();  // the smallest eigenvalue's
    if (plane.dot(mean) < 0) plane = -plane;
    for (const int* f = begin; f != end; ++f) {
      N.row(*f) = plane;
      out.snapped[static_cast<std::size_t>(*f)] = true;
    }
    ++out.regions;
    out.faces += end - begin;
  }
  return out;
}

}  // namespace msmesh::detail
