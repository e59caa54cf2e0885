// The discrete operators of the paper (§3, eq. 6–13) as sparse matrices plus diagonal
// weights, exactly as DESIGN.md §"Spaces and operators" reads them.
//
// Spaces: U = per face (weight face area s), V = per edge (weight len), W = per corner line
// from a face's barycentre to its corner (weight length of the line, index l = 3 f + k).
#pragma once
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "msmesh/topology.h"

namespace msmesh {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// Operators of one mesh; build once, reuse.
struct Operators {
  /// #E by #F gradient ∇_M (eq. 6): row e holds sgn(e,τ) for the two faces of an interior
  /// manifold edge; boundary and non-manifold edges have an empty row. Pointwise jump.
  SparseMatrix G;
  /// 3#F by #E gradient ∇_E on edge functions (eq. 9–10): (Dv)_l = v_{e+} − v_{e−}, e+ the
  /// edge of τ entering corner k counter-clockwise, e− the edge leaving it.
  SparseMatrix D;
  Eigen::VectorXd face_areas;    ///< #F, S = diag(face_areas)
  Eigen::VectorXd edge_lengths;  ///< #E, L = diag(edge_lengths)
  Eigen::VectorXd line_lengths;  ///< 3#F, L_W = diag(line_lengths)
};

/// Builds G, D and the weights for V (#V by 3), F (#F by 3) and its topology. With
/// `matrices` false, only the weights (G and D left empty: the normal filter assembles its
/// systems from the topology and needs them only to record the energy).
Operators build_operators(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Topology& topo,
                          bool matrices = true);

/// Builds only G (#E by #F), which needs no geometry.
SparseMatrix build_face_gradient(const Topology& topo);

/// Builds only D (3#F by #E), which needs no geometry.
SparseMatrix build_edge_gradient(const Topology& topo);

/// div_M p = −S⁻¹ Gᵀ L p (eq. 7): edge field (#E by k) to face field (#F by k), the adjoint of
/// −∇_M in the U and V inner products. Faces of zero area get 0.
Eigen::MatrixXd divergence_faces(const Operators& ops, const Eigen::MatrixXd& p);

/// Δ_M u = div_M ∇_M u (eq. 8), face field #F by k to face field.
Eigen::MatrixXd laplacian_faces(const Operators& ops, const Eigen::MatrixXd& u);

/// div_E q = −L⁻¹ Dᵀ L_W q (eq. 12): line field (3#F by k) to edge field (#E by k).
Eigen::MatrixXd divergence_edges(const Operators& ops, const Eigen::MatrixXd& q);

/// Δ_E v = div_E ∇_E v (eq. 13), edge field to edge field.
Eigen::MatrixXd laplacian_edges(const Operators& ops, const Eigen::MatrixXd& v);

/// Weighted inner product Σ_i w_i <a_i, b_i> of two fields with one row per element.
double inner_product(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::VectorXd& w);

}  // namespace msmesh
