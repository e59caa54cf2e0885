#include "wide_rows.h"

#include <atomic>
#include <cstdlib>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define MSMESH_WIDE_ROWS 1
#else
#define MSMESH_WIDE_ROWS 0
#endif

namespace msmesh::detail {

namespace {

std::atomic<bool> switched_off{false};

bool processor_has_avx() {
#if MSMESH_WIDE_ROWS
  // (libgcc's test includes the operating system's support of the AVX registers.)
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx") != 0;
  }();
  return has;
#else
  return false;
#endif
}

}  // namespace

bool wide_rows() { return !switched_off.load(std::memory_order_relaxed) && processor_has_avx(); }

void set_wide_rows(bool on) { switched_off.store(!on, std::memory_order_relaxed); }

#if MSMESH_WIDE_ROWS

namespace {

// Everything below is compiled for AVX alone (no FMA: a fused multiply-add rounds once where
// the scalar loops round twice), and reached only through wide_rows().
#define MSMESH_AVX __attribute__((target("avx")))

// Four entries of a row as doubles, and back (float rows rounded as static_cast<float> does).
MSMESH_AVX inline __m256d load4(const float* p) { return _mm256_cvtps_pd(_mm_loadu_ps(p)); }
MSMESH_AVX inline __m256d load4(const double* p) { return _mm256_loadu_pd(p); }
MSMESH_AVX inline void store4(float* p, __m256d v) { _mm_storeu_ps(p, _mm256_cvtpd_ps(v)); }
MSMESH_AVX inline void store4(double* p, __m256d v) { _mm256_storeu_pd(p, v); }
// v rounded to T and back, as a value stored in T and read again.
MSMESH_AVX inline __m256d round_to(float, __m256d v) { return _mm256_cvtps_pd(_mm256_cvtpd_ps(v)); }
MSMESH_AVX inline __m256d round_to(double, __m256d v) { return v; }
MSMESH_AVX inline __m256d splat(double x) { return _mm256_set1_pd(x); }
MSMESH_AVX inline __m256d add(__m256d a, __m256d b) { return _mm256_add_pd(a, b); }
MSMESH_AVX inline __m256d sub(__m256d a, __m256d b) { return _mm256_sub_pd(a, b); }
MSMESH_AVX inline __m256d mul(__m256d a, __m256d b) { return _mm256_mul_pd(a, b); }
// Adds the first three lanes of v to out.
MSMESH_AVX inline void add_lanes(__m256d v, double* out) {
  alignas(32) double s[4];
  _mm256_store_pd(s, v);
  for (int c = 0; c < 3; ++c) out[c] += s[c];
}
// x[0..2] += the first three lanes of v (a row of three doubles, the caller's x), by a pair and
// a single (AVX's masked stores are slow on some processors).
MSMESH_AVX inline void add_to_three(double* x, __m256d v) {
  _mm_storeu_pd(x, _mm_add_pd(_mm_loadu_pd(x), _mm256_castpd256_pd128(v)));
  _mm_store_sd(x + 2, _mm_add_sd(_mm_load_sd(x + 2), _mm256_extractf128_pd(v, 1)));
}

// diag y_i + Σ_k vals_k y_cols_k, in the scalar loop's order.
template <class T>
MSMESH_AVX inline __m256d fixed_width_row(Eigen::Index i, const T* diag, const T* vals, const int* cols, const T* y,
                                          __m256d yi) {
  __m256d a = mul(splat(double(diag[i])), yi);
  for (int k = 0; k < 3; ++k)
    a = add(a, mul(splat(double(vals[3 * i + k])), load4(y + 4 * static_cast<Eigen::Index>(cols[3 * i + k]))));
  return a;
}

template <class T>
MSMESH_AVX void sweep_avx(Eigen::Index i0, Eigen::Index i1, const T* diag, const T* vals, const int* cols,
                          const T* inv_d, const T* y, T* y_old, const T* r0, double c1, double c2, bool first,
                          double* rr) {
  __m256d sum = _mm256_setzero_pd();
  const __m256d vc1 = splat(c1);
  for (Eigen::Index i = i0; i < i1; ++i) {
    const __m256d yi = load4(y + 4 * i);
    const __m256d r = sub(load4(r0 + 4 * i), fixed_width_row(i, diag, vals, cols, y, yi));
    const __m256d previous = first ? _mm256_setzero_pd() : load4(y_old + 4 * i);
    // y + c₁ (y − y_old) + (c₂ d⁻¹) r, grouped as the scalar loop groups it.
    store4(y_old + 4 * i, add(add(yi, mul(vc1, sub(yi, previous))), mul(splat(c2 * double(inv_d[i])), r)));
    sum = add(sum, mul(r, r));
  }
  add_lanes(sum, rr);
}

MSMESH_AVX void compressed_product_avx(Eigen::Index i0, Eigen::Index i1, const int* outer, const int* inner,
                                       const double* val, const double* p, double* q, double* pq) {
  __m256d sum = _mm256_setzero_pd();
  for (Eigen::Index i = i0; i < i1; ++i) {
    __m256d a = _mm256_setzero_pd();
    for (int j = outer[i]; j < outer[i + 1]; ++j)
      a = add(a, mul(splat(val[j]), load4(p + 4 * static_cast<Eigen::Index>(inner[j]))));
    store4(q + 4 * i, a);
    sum = add(sum, mul(load4(p + 4 * i), a));
  }
  add_lanes(sum, pq);
}

template <class T>
MSMESH_AVX void fixed_width_product_avx(Eigen::Index i0, Eigen::Index i1, const T* diag, const T* vals, const int* cols,
                                        const T* p, T* q, double* pq) {
  __m256d sum = _mm256_setzero_pd();
  for (Eigen::Index i = i0; i < i1; ++i) {
    const __m256d pi = load4(p + 4 * i);
    const __m256d qi = round_to(T(), fixed_width_row(i, diag, vals, cols, p, pi));
    store4(q + 4 * i, qi);
    sum = add(sum, mul(pi, qi));
  }
  add_lanes(sum, pq);
}

template <class T>
MSMESH_AVX void residual_update_avx(Eigen::Index i0, Eigen::Index i1, T* r, const T* q, const T* inv_d,
                                    const double* alpha, double* rz, double* rr) {
  const __m256d va = _mm256_set_pd(0, alpha[2], alpha[1], alpha[0]);
  __m256d srz = _mm256_setzero_pd(), srr = _mm256_setzero_pd();
  for (Eigen::Index i = i0; i < i1; ++i) {
    const __m256d ri = round_to(T(), sub(load4(r + 4 * i), mul(va, load4(q + 4 * i))));
    store4(r + 4 * i, ri);
    const __m256d r2 = mul(ri, ri);
    srz = add(srz, mul(r2, splat(double(inv_d[i]))));
    srr = add(srr, r2);
  }
  add_lanes(srz, rz);
  add_lanes(srr, rr);
}

template <class T>
MSMESH_AVX void direction_update_avx(Eigen::Index i0, Eigen::Index i1, double* x, T* p, const T* r, const T* inv_d,
                                     const double* alpha, const double* keep, const double* beta) {
  const __m256d va = _mm256_set_pd(0, alpha[2], alpha[1], alpha[0]);
  const __m256d vk = _mm256_set_pd(0, keep[2], keep[1], keep[0]);
  const __m256d vb = _mm256_set_pd(0, beta[2], beta[1], beta[0]);
  for (Eigen::Index i = i0; i < i1; ++i) {
    const __m256d pi = load4(p + 4 * i);
    add_to_three(x + 3 * i, mul(va, pi));
    store4(p + 4 * i, mul(vk, add(mul(load4(r + 4 * i), splat(double(inv_d[i]))), mul(vb, pi))));
  }
}

MSMESH_AVX void weighted_sums_avx(Eigen::Index f0, Eigen::Index f1, const int* start, const int* nbr,
                                  const double* area, const double* weight, const float* range, const int* pair_of,
                                  const double* n, double* sums) {
  for (Eigen::Index f = f0; f < f1; ++f) {
    __m256d s = mul(splat(area[f]), load4(n + 4 * f));
    for (int i = start[f]; i < start[f + 1]; ++i)
      s = add(s, mul(splat(weight[i] * double(range[pair_of[i]])), load4(n + 4 * static_cast<Eigen::Index>(nbr[i]))));
    store4(sums + 4 * (f - f0), s);
  }
}

#undef MSMESH_AVX

}  // namespace

template <class T>
void chebyshev_sweep_wide(Eigen::Index i0, Eigen::Index i1, const T* diag, const T* vals, const int* cols,
                          const T* inv_d, const T* y, T* y_old, const T* r0, double c1, double c2, bool first,
                          double* rr) {
  sweep_avx(i0, i1, diag, vals, cols, inv_d, y, y_old, r0, c1, c2, first, rr);
}

void product_wide(Eigen::Index i0, Eigen::Index i1, const int* outer, const int* inner, const double* val,
                  const double* p, double* q, double* pq) {
  compressed_product_avx(i0, i1, outer, inner, val, p, q, pq);
}

template <class T>
void product_wide(Eigen::Index i0, Eigen::Index i1, const T* diag, const T* vals, const int* cols, const T* p, T* q,
                  double* pq) {
  fixed_width_product_avx(i0, i1, diag, vals, cols, p, q, pq);
}

template <class T>
void residual_update_wide(Eigen::Index i0, Eigen::Index i1, T* r, const T* q, const T* inv_d, const double* alpha,
                          double* rz, double* rr) {
  residual_update_avx(i0, i1, r, q, inv_d, alpha, rz, rr);
}

template <class T>
void direction_update_wide(Eigen::Index i0, Eigen::Index i1, double* x, T* p, const T* r, const T* inv_d,
                           const double* alpha, const double* keep, const double* beta) {
  direction_update_avx(i0, i1, x, p, r, inv_d, alpha, keep, beta);
}

void weighted_sums_wide(Eigen::Index f0, Eigen::Index f1, const int* start, const int* nbr, const double* area,
                        const double* weight, const float* range, const int* pair_of, const double* n, double* sums) {
  weighted_sums_avx(f0, f1, start, nbr, area, weight, range, pair_of, n, sums);
}

#else  // no wide rows on this processor family: wide_rows() is false, so none of these is called

template <class T>
void chebyshev_sweep_wide(Eigen::Index, Eigen::Index, const T*, const T*, const int*, const T*, const T*, T*, const T*,
                          double, double, bool, double*) {
  std::abort();
}
void product_wide(Eigen::Index, Eigen::Index, const int*, const int*, const double*, const double*, double*, double*) {
  std::abort();
}
template <class T>
void product_wide(Eigen::Index, Eigen::Index, const T*, const T*, const int*, const T*, T*, double*) {
  std::abort();
}
template <class T>
void residual_update_wide(Eigen::Index, Eigen::Index, T*, const T*, const T*, const double*, double*, double*) {
  std::abort();
}
void weighted_sums_wide(Eigen::Index, Eigen::Index, const int*, const int*, const double*, const double*, const float*,
                        const int*, const double*, double*) {
  std::abort();
}
template <class T>
void direction_update_wide(Eigen::Index, Eigen::Index, double*, T*, const T*, const T*, const double*, const double*,
                           const double*) {
  std::abort();
}

#endif

#define MSMESH_WIDE_ROWS_FOR(T)                                                                                      \
  template void chebyshev_sweep_wide<T>(Eigen::Index, Eigen::Index, const T*, const T*, const int*, const T*,        \
                                        const T*, T*, const T*, double, double, bool, double*);                      \
  template void product_wide<T>(Eigen::Index, Eigen::Index, const T*, const T*, const int*, const T*, T*, double*);  \
  template void residual_update_wide<T>(Eigen::Index, Eigen::Index, T*, const T*, const T*, const double*, double*,  \
                                        double*);                                                                    \
  template void direction_update_wide<T>(Eigen::Index, Eigen::Index, double*, T*, const T*, const T*, const double*, \
                                         const double*, const double*);
MSMESH_WIDE_ROWS_FOR(float)
MSMESH_WIDE_ROWS_FOR(double)
#undef MSMESH_WIDE_ROWS_FOR

}  // namespace msmesh::detail
