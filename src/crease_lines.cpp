#include "crease_lines.h"

#include <limits>

#include "union_find.h"

namespace msmesh::detail {

double crease_line_length(const Topology& t, const Eigen::VectorXd& len, const std::vector<char>& crease,
                          Eigen::Index num_vertices, double min_length, const std::vector<char>* open) {
  UnionFind lines(static_cast<std::size_t>(num_vertices));
  for (Eigen::Index e = 0; e < t.num_edges(); ++e)
    if (crease[static_cast<std::size_t>(e)]) lines.unite(t.edges(e, 0), t.edges(e, 1));
  std::vector<double> line_length(static_cast<std::size_t>(num_vertices), 0.0);
  for (Eigen::Index e = 0; e < t.num_edges(); ++e)
    if (crease[static_cast<std::size_t>(e)]) line_length[static_cast<std::size_t>(lines.find(t.edges(e, 0)))] += len(e);
  if (open)  // a line that leaves the measured part counts as long
    for (Eigen::Index e = 0; e < t.num_edges(); ++e)
      for (int k = 0; k < 2 && crease[static_cast<std::size_t>(e)]; ++k)
        if ((*open)[static_cast<std::size_t>(t.edges(e, k))])
          line_length[static_cast<std::size_t>(lines.find(t.edges(e, k)))] = std::numeric_limits<double>::infinity();
  double on_lines = 0;
  for (Eigen::Index e = 0; e < t.num_edges(); ++e)
    if (crease[static_cast<std::size_t>(e)] &&
        line_length[static_cast<std::size_t>(lines.find(t.edges(e, 0)))] >= min_length)
      on_lines += len(e);
  return on_lines;
}

}  // namespace msmesh::detail
