// Segmentation into piecewise-smooth parts and feature lines from the edge field v
// (paper §6.3, DESIGN.md §"Applications").
//
// segment(): Algorithm 1 (filter_normals) gives regularised face normals N and the edge field
// v; v is normalised to [0, 1]; the two faces of an interior edge e are split with
// probability p_e = 1 − v_e, except that p_e = clamp_probability where their regularised
// normals are within smooth_angle_deg (smooth regions never split); p is clamped to
// [clamp_probability, 1 − clamp_probability] and the minimum-cost multicut of the face
// adjacency graph with cost log((1 − p_e)/p_e) per edge (positive = join; multicut.h) gives
// the segments.
#pragma once
#include <Eigen/Core>
#include <vector>

#include "msmesh/multicut.h"
#include "msmesh/normal_filter.h"
#include "msmesh/presets.h"
#include "msmesh/progress.h"

namespace msmesh {

struct SegmentOptions {
  /// Algorithm 1 parameters for the regularised normals and v. Default: preset "cad"
  /// (segment_normal_options(), presets.h).
  NormalFilterOptions normals = segment_normal_options();
  /// Faces whose regularised normals are within this angle (degrees, in (0, 180)) are never
  /// split: their split probability is clamp_probability (§6.3). Default 15.
  double smooth_angle_deg = 15.0;
  /// Split probabilities are clamped to [clamp_probability, 1 − clamp_probability]; in
  /// (0, 0.5). Default 0.001 (the paper's 0.1%). It bounds the edge costs to ±log(1/c − 1).
  double clamp_probability = 0.001;
  /// Beyond the paper: after the multicut, segments whose area is below this fraction of the
  /// total area are merged, smallest first, into the neighbouring segment with which they
  /// share the longest boundary. In [0, 1); 0 turns it off. Default 0.005: it removes the
  /// slivers (0.02–0.4% of the area) that heavy noise leaves along creases, and keeps every
  /// true patch of the test shapes and of the public Fandisk (smallest 0.7%); see
  /// docs/segmentation.md.
  double min_area_fraction = 0.005;
  /// Multicut solver options (GAEC + Kernighan–Lin moves by default).
  MulticutOptions multicut;
  /// Throws InvalidInput naming the parameter, its value and the valid range.
  void validate() const;
};

struct SegmentResult {
  /// #F segment labels in [0, count): segment 0 has the largest area, ties broken by the
  /// lowest face index. Every segment is edge-connected.
  Eigen::VectorXi labels;
  int count = 0;
  Eigen::VectorXd areas;  ///< count areas, in the mesh's units (areas(0) the largest)
  /// Multicut objective Σ_{cut edges} log((1 − p)/p) of `labels` (after the small-segment merge).
  double objective = 0;
  int multicut_count = 0;             ///< segments the multicut found, before the small-segment merge
  Eigen::MatrixXd normals;            ///< #F by 3 regularised normals from Algorithm 1
  Eigen::VectorXd v;                  ///< #E edge field from Algorithm 1: v[e] belongs to Topology::edges.row(e) of F
  Eigen::VectorXd v_normalized;       ///< #E, v rescaled to [0, 1] (min → 0, max → 1)
  Eigen::VectorXd split_probability;  ///< #E p_e; 0 for boundary and non-manifold edges
  Eigen::MatrixXi edges;              ///< #E by 2: v[e], v_normalized[e], split_probability[e] belong to edges.row(e)
  NormalFilterStats normal_report;    ///< iterations and histories of Algorithm 1
  MulticutResult multicut_report;     ///< statistics of the multicut solve (its own labels)
};

/// Segments (V, F) (#V by 3, #F by 3) into piecewise-smooth parts. Results do not depend on
/// the mesh's scale, position or orientation. Faces that share only a boundary or a
/// non-manifold edge are not adjacent in the face graph. Throws InvalidInput, SolverError or
/// Cancelled (progress stages of filter_normals, then "multicut greedy", "multicut local").
SegmentResult segment(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const SegmentOptions& options = {},
                      const ProgressCallback& progress = {});

/// The steps of segment() after Algorithm 1, for given regularised normals N (#F by 3) and
/// edge field v (#E: v[e] belongs to Topology::edges.row(e) of F, the NormalFilterResult::edges
/// of filter_normals). Fills every field of the result except normal_report.
SegmentResult segment_with_field(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& N,
                                 const Eigen::VectorXd& v, const SegmentOptions& options = {},
                                 const ProgressCallback& progress = {});

/// #E: v rescaled to [0, 1] (min → 0, max → 1); all ones when v is constant.
Eigen::VectorXd normalize_edge_field(const Eigen::VectorXd& v);

/// Feature lines: the edges whose normalised field (normalize_edge_field(v) < threshold, v
/// #E with v[e] on Topology::edges.row(e) of F) form the feature graph; its edges are chained
/// through vertices of degree 2 and split at junctions and end points (degree ≠ 2). Each
/// polyline is a list of vertex indices (rows of V); a closed loop repeats its first vertex
/// at the end. Polylines with fewer than `min_edges` edges are dropped (default 1: keep all).
/// Order: by first vertex, deterministic. Throws InvalidInput for a v of the wrong size or a
/// threshold outside (0, 1].
std::vector<std::vector<int>> feature_lines(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                            const Eigen::VectorXd& v, double threshold, int min_edges = 1);

/// Rand index of two labellings of the same elements (labels ≥ 0): the fraction of element
/// pairs on which they agree (both together or both apart), in [0, 1]; 1 for identical
/// partitions up to renaming. O(n + k_a·k_b) through the contingency table (a sparse table
/// when k_a·k_b is large). Throws InvalidInput for different sizes or negative labels.
double rand_index(const Eigen::VectorXi& labels_a, const Eigen::VectorXi& labels_b);

}  // namespace msmesh
