// Inpainting (paper §6.2, DESIGN.md §"Applications"): find the holes of a mesh, fill their
// topology with CGAL's triangulate_refine_and_fair_hole (Liepa 2003), then recover the
// missing features with NMSTV normal filtering and vertex updating, with large fidelity
// (α, ω₃) outside the filled region, almost none inside, and β/10 inside — plus three steps
// beyond the paper (piecewise-smooth completion of the normals, a convex vertex placement,
// crease-aligning edge flips); docs/inpainting.md says why and what each is worth.
//
// Hole finding is in holes.h, the error figures of an inpainting result against a ground truth
// in metrics.h (inpaint_errors), the hole puncher for tests and benchmarks in punch_holes.h.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "msmesh/holes.h"
#include "msmesh/normal_filter.h"
#include "msmesh/progress.h"
#include "msmesh/vertex_update.h"

namespace msmesh {

struct InpaintOptions {
  // --- which holes ---
  int max_hole_edges = 0;        ///< skip holes with more boundary edges (0: no limit)
  double max_hole_diameter = 0;  ///< skip holes wider than this many mean edge lengths (0: no limit)
  /// Fill exactly these holes (indices into find_holes()), outer boundaries included and
  /// regardless of the limits above. Empty: every hole within the limits except outer boundaries.
  std::vector<int> holes;
  bool fill_outer_boundary = false;  ///< also fill outer boundaries (within the limits)

  // --- fill ---
  /// CGAL's density_control_factor of the patch refinement (larger: denser). 0: automatic —
  /// CGAL's default √2 without feature recovery, `feature_density` with it (a crease can only be
  /// rebuilt where the patch has vertices to put on it).
  double density = 0;
  double feature_density = 2.0;

  // --- feature recovery ---
  bool recover_features = true;  ///< false: CGAL's fill-and-fair only
  /// Feature recovery runs on the holes a crease runs into: at least two input edges at the
  /// hole's boundary vertices sharper than feature_angle (degrees), and the median dihedral
  /// angle of the other edges there below smooth_angle (the sharp edges separate smooth
  /// patches). Other holes keep CGAL's fair patch, the better answer on smooth surfaces.
  double feature_angle = 60;
  double smooth_angle = 5;
  bool all_holes_featured = false;  ///< recover features in every filled hole regardless
  /// Rings of input vertices around each filled hole that may move (0: every input vertex stays
  /// exactly where it was). Ring 1 is the hole's boundary, ring k the vertices k−1 edges from it.
  int free_ring = 0;
  /// Normal filtering parameters (Algorithm 1) used around the holes. Defaults, tuned on
  /// bench/inpaint: α = 2, β = 0.02, γ = 0.5, ρ = 0.1, projection after every N-step
  /// (docs/inpainting.md).
  NormalFilterOptions normals = default_normal_options();
  /// Vertex update parameters (Algorithm 2) used around the holes. Defaults: ω₁ = 1, ω₂ = 0,
  /// ω₃ = 0.1, 60 iterations.
  VertexUpdateOptions vertices = default_vertex_options();
  double outside_alpha = 100;   ///< α multiplier on input faces (the fidelity that keeps them)
  double inside_alpha = 1e-6;   ///< α multiplier on new faces (their initial normals mean nothing)
  double inside_beta = 0.1;     ///< β multiplier on edges of new faces (paper: β/10 inside)
  double inside_omega3 = 1e-4;  ///< ω₃ multiplier on new vertices ("very small")
  double ring_omega3 = 1;       ///< ω₃ multiplier on freed input vertices (free_ring > 0)
  /// ω₃ multiplier on pinned input vertices: makes them (numerically) fixed in the solve; their
  /// exact input positions are copied back afterwards.
  double pinned_omega3 = 1e8;
  /// Rings of input faces around each hole included in the solves (the rest of the mesh is
  /// pinned and far away, so it cannot change the result; this keeps the cost per hole).
  int context_rings = 6;
  /// Mumford–Shah smoothing of the filtered normals of the new faces: keep NMSTV's edge set
  /// (neighbouring normals more than the jump angle apart) and interpolate the normals
  /// harmonically elsewhere, so curved surfaces are not flattened into facets.
  bool smooth_normals = true;
  /// Jump angle in degrees; 0: per hole, 0.75 × the gentlest crease (dihedral > 30°) at its
  /// boundary, kept within [20°, 60°] — a crease of the input survives, the small steps of
  /// NMSTV's staircase on a curved surface do not.
  double smooth_jump_angle = 0;
  /// Before each vertex update, place the free vertices by one convex solve that makes the
  /// edges of their faces orthogonal to the filtered normals (plus a small membrane term of
  /// weight placement_smoothing, mean-edge units); Algorithm 2 then starts from there.
  bool orthogonal_placement = true;
  double placement_smoothing = 1e-3;
  /// After each round, flip edges between new faces where the flipped pair matches the
  /// filtered normals clearly better (a crease can only be rebuilt along edges; the fill's
  /// triangulation may have faces spanning it). Only new faces change.
  bool crease_flips = true;
  /// Alternate normal filtering and vertex update this many times (the normals of the new
  /// faces are recomputed from the updated positions before the next round).
  int rounds = 2;

  static NormalFilterOptions default_normal_options();
  static VertexUpdateOptions default_vertex_options();
  /// Throws InvalidInput naming the bad parameter.
  void validate() const;
};

enum class HoleAction {
  Filled,   ///< filled (and its features recovered when asked)
  Skipped,  ///< not selected: outer boundary, over a limit, not listed, or self-touching
  Failed,   ///< selected but CGAL could not fill it; left open
};

/// "filled", "skipped" or "failed" (as the CLI's summary, JSON and Python report say it).
const char* hole_action_name(HoleAction action);

/// What was done with one hole of find_holes().
struct HoleReport {
  int index = 0;  ///< index into InpaintResult::holes
  HoleAction action = HoleAction::Skipped;
  std::string reason;  ///< why it was skipped or failed; empty when filled
  int new_faces = 0, new_vertices = 0;
  bool faired = false;          ///< CGAL's fairing succeeded (a filled but unfaired patch is kept)
  bool features = false;        ///< the feature recovery ran on this hole
  std::string features_reason;  ///< what the crease test saw (filled holes, recover_features)
};

struct InpaintResult {
  /// #V' by 3: the input vertices first (identical bit for bit unless free_ring > 0 freed
  /// some), then the new vertices.
  Eigen::MatrixXd V;
  /// #F' by 3: the input faces first, in order, then the new faces.
  Eigen::MatrixXi F;
  std::vector<bool> new_faces;      ///< #F' flags: face added by the fill
  std::vector<bool> new_vertices;   ///< #V' flags: vertex added by the fill
  std::vector<Hole> holes;          ///< every hole found, as find_holes() returns them
  std::vector<HoleReport> reports;  ///< one per hole, same order
  int filled = 0, skipped = 0, failed = 0;
  int featured = 0;              ///< filled holes the feature recovery ran on
  int moved_input_vertices = 0;  ///< input vertices freed by free_ring
  int crease_flips = 0;          ///< edge flips made by the feature recovery
  /// Reports of the last round, on the working region around the recovered holes (their own
  /// face and edge numbering; empty when nothing was solved).
  NormalFilterResult normal_report;
  VertexUpdateResult vertex_report;
  double seconds_fill = 0, seconds_features = 0;
};

/// The refinement density the fill uses: `density`, or when 0 the automatic choice.
double fill_density(const InpaintOptions& options);

/// Bytes the fill of `holes` needs at the options' density, deliberately low (the new faces
/// grow with density² × the holes' spanned area); inpaint() checks it with check_memory
/// (msmesh/memory.h) before any hole is filled.
double inpaint_memory_estimate(const std::vector<Hole>& holes, const InpaintOptions& options = {});

/// Inpaints (V, F) (#V by 3, #F by 3). A mesh without holes comes back unchanged. Failures of
/// single holes are reported, not thrown. Throws InvalidInput (bad mesh or options),
/// SolverError, or Cancelled when `progress` returns false.
InpaintResult inpaint(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const InpaintOptions& options = {},
                      const ProgressCallback& progress = {});

}  // namespace msmesh
