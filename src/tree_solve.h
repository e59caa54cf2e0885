// Internal: the triangular solves with a CHOLMOD simplicial LLᵀ factor, for three right-hand
// sides stored row by row, split over two threads along the elimination tree.
//
// Columns of L in two disjoint subtrees of the elimination tree never meet until their
// common ancestors, so the forward solve L y = b runs two sets of subtrees at once (their
// contributions to the ancestor rows go to a buffer per set) and then the remaining top of
// the tree; the backward solve Lᵀ x = y runs the top first, then the two sets at once.
// The split is a property of the factor, not of the thread count: one thread runs the two
// sets one after the other and gets the same bits.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "pcg.h"

struct cholmod_factor_struct;

namespace msmesh::detail {

/// Two sets of disjoint subtrees of an elimination tree, to be worked on at once, and the
/// remaining top of the tree (the ancestors), to be worked on after (forward) or before
/// (backward). The tree must be postordered (each subtree a range of columns); `cost` is
/// the work of each column. Below `min_total` total work, or when the split would not save
/// a fifth, everything is top (serial).
struct TreeSplit {
  struct Range {
    int begin, end;  // columns [begin, end): one subtree
  };
  std::vector<Range> sets[2];  // ascending
  std::vector<int> top;        // columns outside the sets, ascending
  double parallel_share = 0;   // share of the cost in the two sets
};
TreeSplit split_elimination_tree(const std::vector<int>& parent, const std::vector<double>& cost, double min_total);

/// Threads for the two sets: two, unless the user asked for one (OMP_NUM_THREADS=1).
int tree_threads();

class TreeSolve {
 public:
  /// Reads a simplicial LLᵀ factor (int indices, real), which must outlive this object.
  /// valid() is false for any other kind of factor.
  explicit TreeSolve(const cholmod_factor_struct* L);
  bool valid() const { return valid_; }
  /// Solves A X = B for the A that was factored; B and X are #rows by 3, row-major (X may be B).
  /// Uses work space of this object: not for two solves at once on the same object.
  void solve(const RowMatrixX3& B, RowMatrixX3& X) const;
  /// Share of L's entries in the two parallel sets (0 when the solve is serial).
  double parallel_share() const { return parallel_share_; }

 private:
  void forward(double* y) const;
  void backward(double* y) const;

  bool valid_ = false;
  int n_ = 0;
  const int *Lp_ = nullptr, *Li_ = nullptr, *Lnz_ = nullptr, *perm_ = nullptr;
  const double* Lx_ = nullptr;
  using Range = TreeSplit::Range;
  std::vector<Range> sets_[2];  // ascending
  std::vector<int> top_;        // columns outside the sets, ascending
  std::vector<int> top_slot_;   // column → index in top_, or −1
  mutable std::vector<double> buffer_[2];
  mutable std::vector<double> work_;
  double parallel_share_ = 0;
};

}  // namespace msmesh::detail
