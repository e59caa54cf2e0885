#include "patch_sample.h"

#include <algorithm>
#include <cstdint>

namespace msmesh::detail {

namespace {

/// The faces around each vertex (CSR).
struct VertexFaces {
  std::vector<int> start, faces;
  VertexFaces(const Eigen::MatrixXi& F, Eigen::Index nv) : start(static_cast<std::size_t>(nv) + 1, 0) {
    for (Eigen::Index i = 0; i < F.size(); ++i) ++start[static_cast<std::size_t>(F.data()[i]) + 1];
    for (std::size_t i = 0; i + 1 < start.size(); ++i) start[i + 1] += start[i];
    faces.resize(static_cast<std::size_t>(F.size()));
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (Eigen::Index f = 0; f < F.rows(); ++f)
      for (int k = 0; k < 3; ++k) faces[static_cast<std::size_t>(fill[F(f, k)]++)] = static_cast<int>(f);
  }
  template <class Visit>
  void for_each_neighbour(const Eigen::MatrixXi& F, int f, Visit&& visit) const {
    for (int k = 0; k < 3; ++k) {
      const int v = F(f, k);
      for (int i = start[v]; i < start[v + 1]; ++i) visit(faces[i]);
    }
  }
};

}  // namespace

PatchSample sample_patches(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, Eigen::Index patches,
                           Eigen::Index patch_faces, int margin) {
  const Eigen::Index nf = F.rows();
  PatchSample s;
  std::vector<int> chosen;
  if (nf <= patches * patch_faces) {
    chosen.resize(static_cast<std::size_t>(nf));
    for (Eigen::Index f = 0; f < nf; ++f) chosen[static_cast<std::size_t>(f)] = static_cast<int>(f);
    std::vector<int> local(static_cast<std::size_t>(V.rows()), -1);
    s.mesh = sub_mesh(V, F, chosen, local);
    s.core_face.assign(static_cast<std::size_t>(nf), 1);
    s.core_vertex.assign(s.mesh.global.size(), 1);
    s.patches = 1;
    s.core_faces = nf;
    return s;
  }
  const VertexFaces vf(F, V.rows());
  // -1: not in the sample; otherwise the rings to the nearest cut (set below).
  std::vector<std::int32_t> in(static_cast<std::size_t>(nf), -1);
  for (Eigen::Index p = 0; p < patches; ++p) {
    // The seed: the first face not yet taken from an even spacing over the face order.
    Eigen::Index seed = (2 * p + 1) * nf / (2 * patches);
    while (seed < nf && in[static_cast<std::size_t>(seed)] >= 0) ++seed;
    if (seed >= nf) break;
    const std::size_t first = chosen.size();
    in[static_cast<std::size_t>(seed)] = 0;
    chosen.push_back(static_cast<int>(seed));
    for (std::size_t head = first;
         head < chosen.size() && chosen.size() - first < static_cast<std::size_t>(patch_faces); ++head)
      vf.for_each_neighbour(F, chosen[head], [&](int g) {
        if (in[static_cast<std::size_t>(g)] < 0 && chosen.size() - first < static_cast<std::size_t>(patch_faces)) {
          in[static_cast<std::size_t>(g)] = 0;
          chosen.push_back(g);
        }
      });
    ++s.patches;
  }
  // Rings to the nearest cut: breadth first from the sample's faces that touch a face outside it.
  constexpr std::int32_t kFar = 1 << 30;
  std::vector<int> queue;
  for (const int f : chosen) {
    bool cut = false;
    vf.for_each_neighbour(F, f, [&](int g) { cut = cut || in[static_cast<std::size_t>(g)] < 0; });
    in[static_cast<std::size_t>(f)] = cut ? 0 : kFar;
    if (cut) queue.push_back(f);
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int f = queue[head];
    const std::int32_t d = in[static_cast<std::size_t>(f)];
    if (d + 1 >= margin) continue;
    vf.for_each_neighbour(F, f, [&](int g) {
      std::int32_t& dg = in[static_cast<std::size_t>(g)];
      if (dg > d + 1) {
        dg = d + 1;
        queue.push_back(g);
      }
    });
  }
  std::sort(chosen.begin(), chosen.end());  // the sample in the mesh's own face order
  std::vector<int> local(static_cast<std::size_t>(V.rows()), -1);
  s.mesh = sub_mesh(V, F, chosen, local);
  s.core_face.resize(chosen.size());
  s.core_vertex.assign(s.mesh.global.size(), 0);
  for (std::size_t i = 0; i < chosen.size(); ++i) {
    const bool core = in[static_cast<std::size_t>(chosen[i])] >= margin;
    s.core_face[i] = core;
    s.core_faces += core;
    if (core)
      for (int k = 0; k < 3; ++k)
        s.core_vertex[static_cast<std::size_t>(s.mesh.F(static_cast<Eigen::Index>(i), k))] = 1;
  }
  return s;
}

}  // namespace msmesh::detail
