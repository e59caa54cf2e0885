#include "mesh_components.h"

#include "union_find.h"

namespace msmesh::detail {

std::vector<int> face_component_labels(const Eigen::MatrixXi& F, Eigen::Index num_vertices, int& count) {
  UnionFind uf(static_cast<std::size_t>(num_vertices));
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    uf.unite(F(f, 0), F(f, 1));
    uf.unite(F(f, 1), F(f, 2));
  }
  std::vector<int> id(static_cast<std::size_t>(num_vertices), -1), label(static_cast<std::size_t>(F.rows()));
  count = 0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    int& c = id[static_cast<std::size_t>(uf.find(F(f, 0)))];
    if (c < 0) c = count++;
    label[static_cast<std::size_t>(f)] = c;
  }
  return label;
}

ComponentSplit split_small_components(const std::vector<int>& label, int count, int min_faces) {
  std::vector<Eigen::Index> size(static_cast<std::size_t>(count), 0);
  for (int c : label) ++size[static_cast<std::size_t>(c)];
  ComponentSplit s;
  for (Eigen::Index n : size)
    if (n < min_faces) {
      ++s.small_components;
      s.small_faces += n;
    }
  s.large_faces.reserve(label.size() - static_cast<std::size_t>(s.small_faces));
  for (std::size_t f = 0; f < label.size(); ++f)
    if (size[static_cast<std::size_t>(label[f])] >= min_faces) s.large_faces.push_back(static_cast<Eigen::Index>(f));
  return s;
}

}  // namespace msmesh::detail
