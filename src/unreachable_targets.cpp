// Targets a first vertex update could not reach (docs/presets.md, "Unreachable targets").
#include "unreachable_targets.h"

#include <cmath>
#include <cstddef>

#include "msmesh/geometry.h"
#include "parallel.h"

namespace msmesh::detail {

UnreachableTargets unreachable_targets(const Eigen::MatrixXd& X, const Eigen::MatrixXi& F, const Eigen::MatrixXd& N,
                                       double angle_deg) {
  const Eigen::Index nf = F.rows();
  UnreachableTargets r;
  r.marked.assign(static_cast<std::size_t>(nf), 0);
  if (!(angle_deg > 0)) return r;
  const Eigen::MatrixXd reached = face_normals(X, F);
  const double cos_max = std::cos(angle_deg * M_PI / 180);
  parallel_for(nf, [&](Eigen::Index f) {
    const double c = reached.row(f).dot(N.row(f));
    r.marked[static_cast<std::size_t>(f)] = reached.row(f).squaredNorm() > 0 && c < cos_max ? 1 : 0;
  });
  for (const char m : r.marked) r.faces += m;
  return r;
}

void drop_targets(const std::vector<char>& marked, Eigen::MatrixXd& N) {
  for (Eigen::Index f = 0; f < N.rows(); ++f)
    if (marked[static_cast<std::size_t>(f)]) N.row(f).setZero();
}

}  // namespace msmesh::detail
