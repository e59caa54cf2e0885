// Internal: hot loops over rows of three numbers padded to four, four per 256-bit instruction
// where the processor has AVX: the three-column solves' (pcg.cpp) and the shape rule's
// bilateral sums (bilateral.cpp).
//
// Why: the N-step's Chebyshev sweeps and the vertex update's CG products are bound by the
// instructions per row, not by memory (a row of the N-step costs 7–8 ns on one thread
// whether the matrix fits the L2 cache or not, docs/performance.md): the scalar loops spend
// three loads, conversions, multiplications and additions per neighbour where one of each
// does. The build targets plain x86-64, so the AVX loops are compiled for that instruction set
// alone and chosen at run time (wide_rows()).
//
// The same operations in the same order as the scalar loops, lane by lane, and no fused
// multiply-add (AVX without FMA): the results are identical bit for bit, which tests check by
// switching the wide rows off (set_wide_rows).
#pragma once
#include <Eigen/Core>

namespace msmesh::detail {

/// True when the wide loops below run: the processor has AVX and set_wide_rows has not
/// switched them off.
bool wide_rows();
/// Tests: off, every caller takes its scalar loops (the solves on rows of three); on, the wide
/// loops run wherever the processor allows.
void set_wide_rows(bool on);

/// One Chebyshev sweep (pcg.cpp, solve_chebyshev) over rows [i0, i1) of a fixed-width matrix
/// (diagonal, three entries per row at cols/vals): r = r₀ − A y, y_old ←
/// y + c₁ (y − y_old) + c₂ D⁻¹ r (y_old read as 0 when `first`); adds ‖r‖² per column to rr.
/// y, y_old and r₀ have four entries per row (the fourth 0). For float and double rows.
template <class T>
void chebyshev_sweep_wide(Eigen::Index i0, Eigen::Index i1, const T* diag, const T* vals, const int* cols,
                          const T* inv_d, const T* y, T* y_old, const T* r0, double c1, double c2, bool first,
                          double* rr);

/// q = A p over rows [i0, i1) of a compressed double matrix (outer/inner/val, the diagonal
/// among the entries), four doubles per row in p and q; adds p·q per column to pq.
void product_wide(Eigen::Index i0, Eigen::Index i1, const int* outer, const int* inner, const double* val,
                  const double* p, double* q, double* pq);

/// The same for a fixed-width matrix (the N-step's CG solves): q rounded to T.
template <class T>
void product_wide(Eigen::Index i0, Eigen::Index i1, const T* diag, const T* vals, const int* cols, const T* p, T* q,
                  double* pq);

/// CG's residual update over rows [i0, i1): r ← r − α q (rounded to T); adds r·D⁻¹r and ‖r‖²
/// per column to rz and rr.
template <class T>
void residual_update_wide(Eigen::Index i0, Eigen::Index i1, T* r, const T* q, const T* inv_d, const double* alpha,
                          double* rz, double* rr);

/// CG's step and new direction over rows [i0, i1): x += α p (x: three doubles per row, the
/// caller's), then p ← keep (D⁻¹ r + β p).
template <class T>
void direction_update_wide(Eigen::Index i0, Eigen::Index i1, double* x, T* p, const T* r, const T* inv_d,
                           const double* alpha, const double* keep, const double* beta);

/// The shape rule's bilateral sums (bilateral.cpp, bilateral_normals_by_pairs) over faces
/// [f0, f1): s_f = a_f n_f + Σ_i weight_i · range[pair_of_i] · n_{nbr_i} for the entries i of f's
/// neighbour list (start/nbr), n in rows of four doubles; s_f written as the row f − f0 of four
/// into sums (the fourth entry unspecified).
void weighted_sums_wide(Eigen::Index f0, Eigen::Index f1, const int* start, const int* nbr, const double* area,
                        const double* weight, const float* range, const int* pair_of, const double* n, double* sums);

}  // namespace msmesh::detail
