// A mesh made ready for the solvers once: checked, normalised and connected.
//
// Normal filtering and the vertex update both need the mesh validated, centred and scaled to
// mean edge length 1 (DESIGN.md §"Scale") and its connectivity (topology.h). PreparedMesh
// does this once, so a pipeline of several stages (denoise: Algorithm 1 then Algorithm 2)
// shares it instead of repeating it per stage. Immutable after construction.
#pragma once
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "msmesh/topology.h"

namespace msmesh {

class PreparedMesh {
 public:
  /// Checks (V, F) with validate_mesh (messages prefixed by `what`), builds the topology of F
  /// and, when F has faces, the normalisation: centre on the vertex mean, divide by the mean
  /// edge length. Throws InvalidInput for an invalid mesh or when no edge has positive length.
  PreparedMesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::string& what = "mesh");

  /// #V by 3 normalised positions (mean edge length 1, vertex mean at the origin); the input
  /// positions when F has no faces.
  const Eigen::MatrixXd& positions() const { return positions_; }
  /// #F by 3 vertex indices, as given.
  const Eigen::MatrixXi& faces() const { return faces_; }
  /// Connectivity of faces(); its edge order is the one of every edge field (#E) computed on
  /// this mesh.
  const Topology& topology() const { return topology_; }
  /// #E by 2 edges (topology().edges): edge field entry e belongs to edges().row(e).
  const Eigen::MatrixXi& edges() const { return topology_.edges; }
  /// The vertex mean of the input (0 without faces).
  const Eigen::RowVector3d& center() const { return center_; }
  /// The mean edge length of the input: one normalised unit (1 without faces).
  double scale() const { return scale_; }
  /// Maps normalised positions (#V by 3) back to the input's units and position.
  Eigen::MatrixXd to_input_units(const Eigen::MatrixXd& positions) const;

  /// The faces in reverse Cuthill–McKee order of their adjacency across interior edges
  /// (position i holds face face_order()[i]): the order the iterative solvers of the normal
  /// filter, the polish and the vertex update work in, so that neighbours are close in memory.
  /// Computed on first use (thread-safe; copies of this object share it).
  const std::vector<int>& face_order() const;
  Eigen::Index num_vertices() const { return positions_.rows(); }
  Eigen::Index num_faces() const { return faces_.rows(); }
  Eigen::Index num_edges() const { return topology_.num_edges(); }

 private:
  Eigen::MatrixXd positions_;
  Eigen::MatrixXi faces_;
  Topology topology_;
  Eigen::RowVector3d center_ = Eigen::RowVector3d::Zero();
  double scale_ = 1.0;
  struct Orders;
  std::shared_ptr<Orders> orders_;  // face_order(), computed on first use
};

}  // namespace msmesh
