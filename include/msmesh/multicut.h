// Minimum-cost multicut (correlation clustering) of a weighted graph: greedy additive edge
// contraction (GAEC) followed by Kernighan–Lin-style local moves (Keuper et al. 2015, the
// solver the paper uses for segmentation, §6.3 and DESIGN.md §"Applications").
//
// Sign convention: every edge e = {i, j} has a cost c_e that is paid when the edge is CUT,
// i.e. when i and j end up in different clusters. The solver minimises
//     objective(labels) = Σ_{e cut} c_e.
// So c_e > 0 means "prefer i and j joined" (cutting costs c_e), c_e < 0 means "prefer them
// apart" (cutting gains |c_e|). Joining everything has objective 0; the optimum is ≤ 0.
// A labelling is a valid multicut when every cluster is connected in the graph; the solver
// always returns one (any partition can be refined into one with the same objective).
#pragma once
#include <Eigen/Core>

#include "msmesh/parameters.h"
#include "msmesh/progress.h"

namespace msmesh {

struct MulticutOptions {
  /// Run the local search after GAEC (single-node moves, Kernighan–Lin moves between pairs of
  /// neighbouring clusters, and re-contraction). Default true.
  bool local_search = true;
  /// Maximum rounds of the local search (each round: node moves, pairwise KL, contraction);
  /// it stops earlier when a round does not improve the objective. Default 50, ≥ 0.
  int max_local_rounds = 50;
  /// A move is applied only when it lowers the objective by more than this (≥ 0). Default 1e-9.
  double tolerance = 1e-9;
  /// Throws InvalidInput naming the parameter, its value and the valid range.
  void validate() const;
};

/// max-local-rounds (>= 0) and tolerance (>= 0) with their ranges (parameters.h), used by validate().
const ParameterTable<MulticutOptions>& multicut_parameters();

struct MulticutResult {
  /// #nodes cluster labels in [0, count), numbered in order of their first node; every
  /// cluster is connected in the graph.
  Eigen::VectorXi labels;
  int count = 0;                ///< number of clusters
  double objective = 0;         ///< Σ costs of cut edges (of the final labels)
  double objective_greedy = 0;  ///< the same after GAEC alone
  int contractions = 0;         ///< edges contracted by GAEC
  int local_rounds = 0;         ///< local-search rounds run
  int local_moves = 0;          ///< improving moves applied by the local search
};

/// Solves the minimum-cost multicut of the graph with `num_nodes` nodes, `edges` (#E by 2 node
/// indices; parallel edges are summed, self-loops are never cut and are ignored) and `costs`
/// (#E, cost paid when the edge is cut; see the convention above). Throws InvalidInput for an
/// index out of range, a non-finite cost or bad options, Cancelled when `progress` returns
/// false. Progress stages: "multicut greedy", "multicut local".
MulticutResult solve_multicut(Eigen::Index num_nodes, const Eigen::MatrixXi& edges, const Eigen::VectorXd& costs,
                              const MulticutOptions& options = {}, const ProgressCallback& progress = {});

/// The objective Σ_{e : labels(i) ≠ labels(j)} costs(e) of a labelling (#nodes) of the graph.
double multicut_objective(const Eigen::MatrixXi& edges, const Eigen::VectorXd& costs, const Eigen::VectorXi& labels);

/// True when every label's nodes form a connected subgraph (so the cut edges are exactly the
/// edges between different labels of a multicut); labels must be ≥ 0.
bool is_valid_multicut(Eigen::Index num_nodes, const Eigen::MatrixXi& edges, const Eigen::VectorXi& labels);

}  // namespace msmesh
