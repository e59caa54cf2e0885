// Bilateral normal filtering (Zheng et al. 2011, local iterative scheme) and the classic
// vertex update (Sun et al. 2007): the widely used reference denoiser users compare against.
#include "msmesh/bilateral.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "bilateral_pairs.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/mesh.h"
#include "msmesh/parameters.h"
#include "normalize.h"
#include "parallel.h"
#include "wide_rows.h"

namespace msmesh {

void BilateralOptions::validate() const { check_parameters(bilateral_parameters(), *this); }

namespace {

// Faces sharing at least one vertex with each face (CSR), the face itself excluded, each list in
// the order a serial scan finds them (vertex by vertex, each vertex's faces in face order).
// Blocks of faces are listed in parallel, each thread marking with its own array, and then
// copied into place: the same lists whatever the number of threads.
void face_vertex_neighbours(const Eigen::MatrixXi& F, Eigen::Index nv, std::vector<int>& start, std::vector<int>& nbr) {
  const Eigen::Index nf = F.rows();
  std::vector<int> vstart(static_cast<size_t>(nv) + 1, 0);
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) ++vstart[F(f, k) + 1];
  for (Eigen::Index i = 0; i < nv; ++i) vstart[i + 1] += vstart[i];
  std::vector<int> vfaces(vstart.back()), fill(vstart.begin(), vstart.end() - 1);
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) vfaces[fill[F(f, k)]++] = static_cast<int>(f);
  start.assign(static_cast<size_t>(nf) + 1, 0);
  const Eigen::Index nb = (nf + detail::kBlock - 1) / detail::kBlock;
  std::vector<std::vector<int>> lists(static_cast<size_t>(nb));
  const auto list_block = [&](Eigen::Index b, std::vector<int>& mark) {
    std::vector<int>& list = lists[static_cast<size_t>(b)];
    list.reserve(static_cast<size_t>(detail::kBlock) * 13);
    for (Eigen::Index f = b * detail::kBlock; f < std::min(nf, (b + 1) * detail::kBlock); ++f) {
      mark[f] = static_cast<int>(f);
      for (int k = 0; k < 3; ++k) {
        const int v = F(f, k);
        for (int i = vstart[v]; i < vstart[v + 1]; ++i) {
          const int g = vfaces[i];
          if (mark[g] != f) {
            mark[g] = static_cast<int>(f);
            list.push_back(g);
          }
        }
      }
      start[f + 1] = static_cast<int>(list.size());  // within the block, made absolute below
    }
  };
  if (nb < 4) {  // (no parallel construct for small meshes: parallel.h says why)
    std::vector<int> mark(static_cast<size_t>(nf), -1);
    for (Eigen::Index b = 0; b < nb; ++b) list_block(b, mark);
  } else {
#pragma omp parallel
    {
      std::vector<int> mark(static_cast<size_t>(nf), -1);
#pragma omp for schedule(static)
      for (Eigen::Index b = 0; b < nb; ++b) list_block(b, mark);
    }
  }
  std::vector<std::size_t> offset(static_cast<size_t>(nb) + 1, 0);
  for (Eigen::Index b = 0; b < nb; ++b) offset[b + 1] = offset[b] + lists[b].size();
  nbr.resize(offset.back());
  detail::parallel_for_blocks(nf, [&](Eigen::Index begin, Eigen::Index end) {
    const std::size_t b = static_cast<std::size_t>(begin / detail::kBlock);
    std::copy(lists[b].begin(), lists[b].end(), nbr.begin() + static_cast<std::ptrdiff_t>(offset[b]));
    for (Eigen::Index f = begin; f < end; ++f) start[f + 1] += static_cast<int>(offset[b]);
  });
}

/// out = s / |s|, or the face's own normal `own` where the weighted sum vanishes.
inline void store_unit(double s0, double s1, double s2, const double* own, double* out) {
  const double len = std::sqrt(s0 * s0 + s1 * s1 + s2 * s2);
  if (len > 0) {
    out[0] = s0 / len;
    out[1] = s1 / len;
    out[2] = s2 / len;
  } else {
    std::copy(own, own + 3, out);
  }
}

}  // namespace

Eigen::MatrixXd bilateral_filter_normals(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const BilateralOptions& o,
                                         const ProgressCallback& progress) {
  o.validate();
  validate_mesh(V, F, "bilateral filtering");
  const detail::Normalization norm = detail::normalization_for(V, F);
  const Eigen::MatrixXd Vn = norm.apply(V);
  const Eigen::Index nf = F.rows();
  const Eigen::MatrixXd C = face_barycenters(Vn, F);
  const Eigen::VectorXd A = face_areas(Vn, F);
  std::vector<int> start, nbr;
  face_vertex_neighbours(F, V.rows(), start, nbr);
  double sigma_s = o.sigma_s;
  if (sigma_s <= 0) {
    double sum = 0;
    for (Eigen::Index f = 0; f < nf; ++f)
      for (int i = start[f]; i < start[f + 1]; ++i) sum += (C.row(f) - C.row(nbr[i])).norm();
    sigma_s = nbr.empty() ? 1.0 : sum / double(nbr.size());
  }
  const double is2 = 1.0 / (2 * sigma_s * sigma_s), ir2 = 1.0 / (2 * o.sigma_r * o.sigma_r);
  // Row-major copies (one face's three coordinates side by side) for the neighbour loop; the
  // arithmetic is Eigen's, term for term, so the result is the same to the last bit.
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
  const Rows Cr = C;
  Rows N = face_normals(Vn, F), Nn(nf, 3);
  for (int it = 0; it < o.normal_iterations; ++it) {
#pragma omp parallel for schedule(static) if (nf >= 8192)
    for (Eigen::Index f = 0; f < nf; ++f) {
      const double* cf = Cr.data() + 3 * f;
      const double* nf3 = N.data() + 3 * f;
      double s0 = A(f) * nf3[0], s1 = A(f) * nf3[1], s2 = A(f) * nf3[2];
      for (int i = start[f]; i < start[f + 1]; ++i) {
        const Eigen::Index g = nbr[i];
        const double* cg = Cr.data() + 3 * g;
        const double* ng = N.data() + 3 * g;
        const double c0 = cf[0] - cg[0], c1 = cf[1] - cg[1], c2 = cf[2] - cg[2];
        const double n0 = nf3[0] - ng[0], n1 = nf3[1] - ng[1], n2 = nf3[2] - ng[2];
        const double ds = c0 * c0 + c1 * c1 + c2 * c2;
        const double dr = n0 * n0 + n1 * n1 + n2 * n2;
        const double w = A(g) * std::exp(-ds * is2 - dr * ir2);
        s0 += w * ng[0];
        s1 += w * ng[1];
        s2 += w * ng[2];
      }
      store_unit(s0, s1, s2, nf3, Nn.data() + 3 * f);
    }
    N.swap(Nn);
    if (progress && !progress({"bilateral normals", it + 1, o.normal_iterations, std::nan("")}))
      throw Cancelled("bilateral filtering cancelled");
  }
  return Eigen::MatrixXd(N);
}

Eigen::MatrixXd detail::bilateral_normals_by_pairs(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, int passes,
                                                   double sigma_r) {
  const detail::Normalization norm = detail::normalization_for(V, F);
  const Eigen::MatrixXd Vn = norm.apply(V);
  const Eigen::Index nf = F.rows();
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
  const Rows C = face_barycenters(Vn, F);
  const Eigen::VectorXd A = face_areas(Vn, F);
  std::vector<int> start, nbr;
  face_vertex_neighbours(F, V.rows(), start, nbr);
  // Each unordered pair {f, g} once (f < g), numbered in the order of f and of g in f's list,
  // and for every entry of the neighbour lists the pair it belongs to: f's entry for g is found
  // in the lists of f and, from the other side, of g (a dozen entries each).
  const std::size_t entries = nbr.size();
  std::vector<int> pair_start(static_cast<std::size_t>(nf) + 1, 0);
  detail::parallel_for(nf, [&](Eigen::Index f) {
    int later = 0;
    for (int i = start[f]; i < start[f + 1]; ++i) later += nbr[i] > f;
    pair_start[f + 1] = later;
  });
  for (Eigen::Index f = 0; f < nf; ++f) pair_start[f + 1] += pair_start[f];
  const Eigen::Index np = pair_start[nf];
  std::vector<int> pair_of(entries), first(static_cast<std::size_t>(np)), second(static_cast<std::size_t>(np));
  detail::parallel_for(
      nf,
      [&](Eigen::Index f) {
        int p = pair_start[f];
        for (int i = start[f]; i < start[f + 1]; ++i) {
          const int g = nbr[i];
          if (g < f) continue;
          first[p] = static_cast<int>(f);
          second[p] = g;
          pair_of[i] = p;
          for (int j = start[g]; j < start[g + 1]; ++j)
            if (nbr[j] == f) {
              pair_of[j] = p;
              break;
            }
          ++p;
        }
      },
      12);
  std::vector<double> spatial(static_cast<std::size_t>(np)), range(static_cast<std::size_t>(np));
  // The range weights of a pass in single precision, by Eigen's vectorised exponential: the
  // weights only steer the shape rule's thresholds (a relative error ~1e-7 moves no class), and
  // glibc's exp, one call per pair and pass, was a third of this function's time. Padded to
  // whole packets, in blocks at multiples of kBlock: every weight takes the same vector path,
  // whatever the thread count.
  const Eigen::Index np4 = (np + 3) / 4 * 4;
  std::vector<float> range_f(static_cast<std::size_t>(np4), 0.0f);
  detail::parallel_for(np, [&](Eigen::Index p) {
    const double* a = C.data() + 3 * first[p];
    const double* b = C.data() + 3 * second[p];
    const double c0 = a[0] - b[0], c1 = a[1] - b[1], c2 = a[2] - b[2];
    spatial[p] = c0 * c0 + c1 * c1 + c2 * c2;
    range[p] = std::sqrt(spatial[p]);  // scratch: the distances, added in pair order below
  });
  double sum = 0;  // sigma_s 0: the mean distance between neighbouring face centres
  for (Eigen::Index p = 0; p < np; ++p) sum += range[p];
  const double sigma_s = np > 0 ? sum / double(np) : 1.0;
  const double is2 = 1.0 / (2 * sigma_s * sigma_s), ir2 = 1.0 / (2 * sigma_r * sigma_r);
  detail::parallel_for(
      np, [&](Eigen::Index p) { spatial[p] = std::exp(-spatial[p] * is2); }, 4);
  // Entry weights without the range part: the neighbour's area times the pair's spatial weight.
  std::vector<double> weight(entries);
  detail::parallel_for(
      nf,
      [&](Eigen::Index f) {
        for (int i = start[f]; i < start[f + 1]; ++i) weight[i] = A(nbr[i]) * spatial[pair_of[i]];
      },
      12);
  // The normals as rows of four (the fourth 0), for the wide rows (wide_rows.h) of the sums.
  std::vector<double> N(static_cast<std::size_t>(4 * nf)), Nn(static_cast<std::size_t>(4 * nf));
  {
    const Rows N0 = face_normals(Vn, F);
    detail::parallel_for(nf, [&](Eigen::Index f) {
      for (int c = 0; c < 3; ++c) N[static_cast<std::size_t>(4 * f + c)] = N0(f, c);
      N[static_cast<std::size_t>(4 * f + 3)] = Nn[static_cast<std::size_t>(4 * f + 3)] = 0;
    });
  }
  const bool wide = detail::wide_rows();
  constexpr Eigen::Index kFaces = 256;  // faces per block of sums
  const Eigen::Index face_blocks = (nf + kFaces - 1) / kFaces;
  for (int it = 0; it < passes; ++it) {
    detail::parallel_for_blocks(np4, [&](Eigen::Index p0, Eigen::Index p1) {
      for (Eigen::Index p = p0; p < std::min(p1, np); ++p) {
        const double* a = N.data() + 4 * first[p];
        const double* b = N.data() + 4 * second[p];
        const double n0 = a[0] - b[0], n1 = a[1] - b[1], n2 = a[2] - b[2];
        range_f[p] = static_cast<float>(-(n0 * n0 + n1 * n1 + n2 * n2) * ir2);
      }
      Eigen::Map<Eigen::ArrayXf, Eigen::Aligned16> r(range_f.data() + p0, p1 - p0);
      r = r.exp();
    });
#pragma omp parallel for schedule(static) if (nf >= 8192)
    for (Eigen::Index b = 0; b < face_blocks; ++b) {
      const Eigen::Index f0 = b * kFaces, f1 = std::min(nf, f0 + kFaces);
      double sums[4 * kFaces];
      if (wide) {
        detail::weighted_sums_wide(f0, f1, start.data(), nbr.data(), A.data(), weight.data(), range_f.data(),
                                   pair_of.data(), N.data(), sums);
      } else {
        for (Eigen::Index f = f0; f < f1; ++f) {
          const double* nf3 = N.data() + 4 * f;
          double s0 = A(f) * nf3[0], s1 = A(f) * nf3[1], s2 = A(f) * nf3[2];
          for (int i = start[f]; i < start[f + 1]; ++i) {
            const double* ng = N.data() + 4 * nbr[i];
            const double w = weight[i] * double(range_f[pair_of[i]]);
            s0 += w * ng[0];
            s1 += w * ng[1];
            s2 += w * ng[2];
          }
          double* s = sums + 4 * (f - f0);
          s[0] = s0;
          s[1] = s1;
          s[2] = s2;
        }
      }
      for (Eigen::Index f = f0; f < f1; ++f) {
        const double* s = sums + 4 * (f - f0);
        store_unit(s[0], s[1], s[2], N.data() + 4 * f, Nn.data() + 4 * f);
      }
    }
    N.swap(Nn);
  }
  Eigen::MatrixXd out(nf, 3);
  detail::parallel_for(nf, [&](Eigen::Index f) {
    for (int c = 0; c < 3; ++c) out(f, c) = N[static_cast<std::size_t>(4 * f + c)];
  });
  return out;
}

Eigen::MatrixXd classic_vertex_update(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& N,
                                      int iterations, const ProgressCallback& progress) {
  validate_mesh(V, F, "vertex update");
  if (N.rows() != F.rows() || N.cols() != 3) throw InvalidInput("vertex update: target normals must be #F by 3");
  const Eigen::Index nv = V.rows(), nf = F.rows();
  Eigen::MatrixXd X = V;
  Eigen::VectorXi count = Eigen::VectorXi::Zero(nv);
  for (Eigen::Index f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) ++count(F(f, k));
  for (int it = 0; it < iterations; ++it) {
    const Eigen::MatrixXd C = face_barycenters(X, F);
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(nv, 3);
    for (Eigen::Index f = 0; f < nf; ++f)
      for (int k = 0; k < 3; ++k) {
        const int i = F(f, k);
        D.row(i) += N.row(f) * N.row(f).dot(C.row(f) - X.row(i));
      }
    for (Eigen::Index i = 0; i < nv; ++i)
      if (count(i) > 0) X.row(i) += D.row(i) / double(count(i));
    if (progress && !progress({"vertex update", it + 1, iterations, std::nan("")}))
      throw Cancelled("vertex update cancelled");
  }
  return X;
}

}  // namespace msmesh
