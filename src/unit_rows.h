// Internal: unit normals row by row, for the normal filter's iterates and the polish's result.
#pragma once
#include <cmath>

#include "parallel.h"
#include "pcg.h"

namespace msmesh::detail {

/// Scales every row of N to unit length; a zero or non-finite row takes the row of `fallback`.
inline void normalize_rows(RowMatrixX3& N, const RowMatrixX3& fallback) {
  parallel_for(N.rows(), [&](Eigen::Index f) {
    const double l = N.row(f).norm();
    if (l > 0 && std::isfinite(l))
      N.row(f) /= l;
    else
      N.row(f) = fallback.row(f);
  });
}

}  // namespace msmesh::detail
