// FixedCholesky (sparse_solve.h): CHOLMOD's analysis and simplicial LLᵀ row factorisation,
// with the rows of two sets of disjoint elimination subtrees computed at once.
#include <cholmod.h>

#include <algorithm>

#include "sparse_solve.h"
#include "tree_solve.h"

namespace msmesh::detail {

namespace {

// Below this much factorisation work (Σ column count², about the flops) the second thread
// is not worth waking: Fandisk's N-step (13K faces) has 2.6e6, its vertex update 1.4e7.
constexpr double kMinParallelWork = 4e6;

// One cholmod_common, started and finished with its owner.
struct Common {
  cholmod_common c;
  Common() {
    cholmod_start(&c);
    c.supernodal = CHOLMOD_SIMPLICIAL;  // (see the file comment of sparse_solve.h)
    c.final_ll = 1;
    c.final_asis = 0;
  }
  ~Common() { cholmod_finish(&c); }
  Common(const Common&) = delete;
  Common& operator=(const Common&) = delete;
};

}  // namespace

struct FixedCholesky::Impl {
  Common common;
  cholmod_factor* L = nullptr;
  std::unique_ptr<TreeSolve> tree;
  double factor_share = 0;
  ~Impl() {
    if (L) cholmod_free_factor(&L, &common.c);
  }
};

FixedCholesky::FixedCholesky(const SparseMatrix& A, const std::string& what) : impl_(std::make_unique<Impl>()) {
  cholmod_common& c = impl_->common.c;
  const auto failed = [&](const char* why) {
    return SolverError(what + ": Cholesky factorisation failed (" + why + ")");
  };
  // A view of A's lower triangle (A is stored whole and symmetric).
  cholmod_sparse view{};
  view.nrow = view.ncol = static_cast<size_t>(A.rows());
  view.nzmax = static_cast<size_t>(A.nonZeros());
  view.p = const_cast<int*>(A.outerIndexPtr());
  view.i = const_cast<int*>(A.innerIndexPtr());
  view.x = const_cast<double*>(A.valuePtr());
  view.stype = -1;
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  if (!A.isCompressed()) throw failed("matrix not compressed");

  cholmod_factor* L = cholmod_analyze(&view, &c);
  if (!L) throw failed("analysis: out of memory");
  impl_->L = L;
  const size_t n = L->n;

  // S = triu(P A Pᵀ) in column form, what cholmod_rowfac reads (as cholmod_factorize does).
  cholmod_sparse* S = cholmod_ptranspose(&view, 2, static_cast<int*>(L->Perm), nullptr, 0, &c);
  if (!S) throw failed("out of memory");
  struct FreeS {
    cholmod_sparse*& s;
    cholmod_common& c;
    ~FreeS() { cholmod_free_sparse(&s, &c); }
  } free_s{S, c};

  // The elimination tree of S, postordered by the analysis. The split weighs column k by its
  // count squared (the flops it takes part in); the row-by-row factorisation charges part of
  // that to the top rows, so the sets' real share is lower (docs/performance.md).
  std::vector<int> parent(n);
  if (!cholmod_etree(S, parent.data(), &c)) throw failed("elimination tree");
  std::vector<double> work(n);
  const int* col_count = static_cast<const int*>(L->ColCount);
  for (size_t j = 0; j < n; ++j) work[j] = static_cast<double>(col_count[j]) * col_count[j];
  const TreeSplit split = split_elimination_tree(parent, work, kMinParallelWork);
  impl_->factor_share = split.parallel_share;

  double beta[2] = {0, 0};
  L->is_ll = 1;
  const int grow2 = c.grow2;
  c.grow2 = 0;  // space for exactly the symbolic pattern (as cholmod_factorize does)
  const auto rows = [&](size_t k0, size_t k1) {
    if (!cholmod_rowfac(S, nullptr, beta, k0, k1, L, &c)) throw failed("CHOLMOD row factorisation (out of memory?)");
  };
  bool split_rows = !split.sets[0].empty() || !split.sets[1].empty();
  if (split_rows) {
    // Rows 0..−1: turns the symbolic factor into a numeric one with room for every column.
    rows(0, 0);
    if (L->xtype == CHOLMOD_PATTERN) throw failed("out of memory");
    // The rows of the sets run concurrently only if no column will need to grow (which would
    // move L's arrays): each must have room for its symbolic count, as CHOLMOD allocates it.
    const int* Lp = static_cast<const int*>(L->p);
    const int* Lnext = static_cast<const int*>(L->next);
    for (size_t j = 0; j < n && split_rows; ++j)
      if (Lp[Lnext[j]] - Lp[j] < std::min<int>(std::max(col_count[j], 1), static_cast<int>(n - j))) split_rows = false;
  }
  if (!split_rows) {
    impl_->factor_share = 0;
    rows(0, n);
  } else {
    // Row k of L needs only rows of k's descendants and writes only into their columns, so
    // the rows of the two sets (disjoint subtrees) are computed at once, then the top rows.
    // Each set has its own workspace and its own copy of L's header (the arrays are shared;
    // L->minor, written when a pivot fails, is then not written by two threads).
    Common set_common[2];
    cholmod_factor part[2] = {*L, *L};
    bool ok[2] = {true, true};
#pragma omp parallel for num_threads(tree_threads()) schedule(static, 1)
    for (int s = 0; s < 2; ++s)
      for (const TreeSplit::Range& r : split.sets[s])
        if (ok[s] && !cholmod_rowfac(S, nullptr, beta, static_cast<size_t>(r.begin), static_cast<size_t>(r.end),
                                     &part[s], &set_common[s].c))
          ok[s] = false;
    if (!ok[0] || !ok[1] || part[0].i != L->i || part[1].i != L->i || part[0].x != L->x || part[1].x != L->x)
      throw failed("CHOLMOD row factorisation (out of memory?)");
    L->minor = std::min({L->minor, part[0].minor, part[1].minor});
    for (size_t t = 0; t < split.top.size();) {  // runs of consecutive top rows
      size_t e = t + 1;
      while (e < split.top.size() && split.top[e] == split.top[e - 1] + 1) ++e;
      rows(static_cast<size_t>(split.top[t]), static_cast<size_t>(split.top[e - 1]) + 1);
      t = e;
    }
  }
  c.grow2 = grow2;
  if (L->minor < n) throw SolverError(what + ": Cholesky factorisation failed (matrix not positive definite)");
  if (c.status < CHOLMOD_OK) throw failed("CHOLMOD error");
  // Final form: packed, columns in order (cholmod_factorize's final step).
  if (!cholmod_change_factor(L->xtype, L->is_ll, 0, c.final_pack, c.final_monotonic, L, &c))
    throw failed("out of memory");
  impl_->tree = std::make_unique<TreeSolve>(L);
  if (!impl_->tree->valid()) throw failed("unexpected factor type");
}

FixedCholesky::~FixedCholesky() = default;

double FixedCholesky::parallel_share() const { return impl_->tree->parallel_share(); }

double FixedCholesky::parallel_factor_share() const { return impl_->factor_share; }

void FixedCholesky::solve(const RowMatrixX3& B, RowMatrixX3& X, const std::string& what) const {
  impl_->tree->solve(B, X);
  if (!X.allFinite()) throw SolverError(what + ": solve failed (non-finite result)");
}

}  // namespace msmesh::detail
