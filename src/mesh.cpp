#include "msmesh/mesh.h"

#include <cmath>
#include <sstream>

#include "msmesh/errors.h"

namespace msmesh {

void validate_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::string& what) {
  if (V.cols() != 3 && !(V.rows() == 0)) {
    std::ostringstream os;
    os << what << ": vertex array must be #V by 3, got " << V.rows() << " by " << V.cols();
    throw InvalidInput(os.str());
  }
  if (F.cols() != 3 && !(F.rows() == 0)) {
    std::ostringstream os;
    os << what << ": face array must be #F by 3, got " << F.rows() << " by " << F.cols();
    throw InvalidInput(os.str());
  }
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    for (Eigen::Index c = 0; c < V.cols(); ++c) {
      if (!std::isfinite(V(i, c))) {
        std::ostringstream os;
        os << what << ": vertex " << i << " has a non-finite coordinate (" << V(i, c) << ")";
        throw InvalidInput(os.str());
      }
    }
  }
  // Squared lengths and areas of coordinates this far apart overflow to infinity, and the
  // errors computed from them to NaN: refused rather than processed into a NaN result.
  constexpr double kMaxSpan = 1e150;
  for (Eigen::Index c = 0; c < V.cols() && V.rows() > 0; ++c) {
    const double span = V.col(c).maxCoeff() - V.col(c).minCoeff();
    if (!(span <= kMaxSpan)) {
      std::ostringstream os;
      os << what << ": the vertex coordinates span " << span << " along axis "
         << "xyz"[c] << ", more than 1e150: their squared distances overflow; scale the mesh down";
      throw InvalidInput(os.str());
    }
  }
  const Eigen::Index n = V.rows();
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      if (F(f, k) < 0 || F(f, k) >= n) {
        std::ostringstream os;
        os << what << ": face " << f << " refers to vertex " << F(f, k) << ", out of range [0, " << n << ")";
        throw InvalidInput(os.str());
      }
    }
    if (F(f, 0) == F(f, 1) || F(f, 1) == F(f, 2) || F(f, 0) == F(f, 2)) {
      std::ostringstream os;
      os << what << ": face " << f << " repeats a vertex (" << F(f, 0) << ", " << F(f, 1) << ", " << F(f, 2) << ")";
      throw InvalidInput(os.str());
    }
  }
}

}  // namespace msmesh
