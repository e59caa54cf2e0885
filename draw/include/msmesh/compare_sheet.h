// Comparison sheets: several meshes rendered from the same camera side by side, with captions
// and (given a ground truth) their error figures under each panel, like Fig. 11 of the paper.
// `msmesh compare` and msmesh.compare() draw their sheets with compare_sheet().
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "msmesh/image.h"
#include "msmesh/metrics.h"
#include "msmesh/render.h"

namespace msmesh {

/// One mesh of a sheet.
struct ComparePanel {
  Eigen::MatrixXd V;              ///< #V by 3
  Eigen::MatrixXi F;              ///< #F by 3
  Eigen::MatrixXd vertex_colors;  ///< empty, or #V by 3 RGB in [0,1] (the file's colours)
  std::string caption;
};

/// How the panels are coloured.
enum class SheetColor {
  Auto,   ///< File for the panels with vertex colours, None for the others
  None,   ///< grey
  File,   ///< the panels' vertex colours (grey where a panel has none)
  Error,  ///< angle to the truth's face normal per face, one scale for all panels
};

/// "auto", "none", "file", "error".
std::vector<std::string> sheet_color_names();
/// The colouring of a name of sheet_color_names(); throws InvalidInput otherwise.
SheetColor sheet_color_from_name(const std::string& name);

/// RenderOptions of a size × size picture, the other options at their defaults.
inline RenderOptions square_render_options(int size) {
  RenderOptions o;
  o.width = o.height = size;
  return o;
}

/// CompareOptions::noisy_panel: chosen from the errors; no panel is the noisy input.
constexpr int kNoisyPanelAuto = -1;
constexpr int kNoNoisyPanel = -2;

/// The size of each panel by default (pixels): `msmesh compare --size` and msmesh.compare().
constexpr int kComparePanelSize = 400;

struct CompareOptions {
  /// Each panel's picture (size, view, up axis, camera, ...); kComparePanelSize square by
  /// default. Empty frame_points: all the panels' vertices, so that every panel shows the same
  /// view at the same scale.
  RenderOptions render = square_render_options(kComparePanelSize);
  SheetColor color = SheetColor::Auto;
  double feature_angle = 0;  ///< draw edges sharper than this (degrees, [0, 180)) dark; 0: off
  double error_max = 0;      ///< top of the error scale in degrees ([0, 180]); 0: from the results
  /// The panel (0-based) holding the noisy input, which the automatic error scale leaves out
  /// so that the results are not washed out (its larger errors saturate, and the legend says
  /// so). kNoisyPanelAuto: the panel whose mean angle error is at least twice every other
  /// panel's, if there is one; kNoNoisyPanel: none.
  int noisy_panel = kNoisyPanelAuto;
  std::string title;  ///< a line above the panels; empty: none
  /// Throws InvalidInput naming the bad value.
  void validate() const;
};

/// A drawn sheet and what it shows.
struct CompareSheet {
  Image image;
  /// Per panel, against the truth (when one was given): normal errors only where the panel has
  /// the truth's faces (Evaluation::same_connectivity).
  std::vector<Evaluation> evaluations;
  double error_top = 0;    ///< top of the error colour scale (degrees); 0 without error colours
  int noisy_panel = -1;    ///< the panel taken as the noisy input, or -1
  bool saturated = false;  ///< some faces' errors exceed error_top (they share the top colour)
  /// The legend's words on the scale, e.g. "scale from the results; the noisy input saturates".
  std::string scale_note;
};

/// The error colour scale of a sheet: error_max when > 0, else error_scale() (mesh_coloring.h)
/// of the angles (degrees) of the panels other than `noisy_panel` whose errors are not all
/// zero (a truth panel would lower it); all panels when no other is left.
double sheet_error_scale(const std::vector<Eigen::VectorXd>& angle_deg, int noisy_panel, double error_max);

/// The panel that kNoisyPanelAuto picks from the mean angle errors of the panels (negative
/// for a panel without errors): the largest, if it is at least twice every other one and
/// there are two or more panels; -1 otherwise.
int auto_noisy_panel(const std::vector<double>& mean_angle_deg);

/// Draws the sheet. V_truth/F_truth: the ground truth, or empty matrices for none (the error
/// colouring needs one, and panels with its faces). Throws InvalidInput for no panels, an
/// invalid mesh, options or colours, error colours without a truth or for a panel whose faces
/// differ from the truth's, or a noisy_panel out of range.
CompareSheet compare_sheet(const std::vector<ComparePanel>& panels, const Eigen::MatrixXd& V_truth,
                           const Eigen::MatrixXi& F_truth, const CompareOptions& options);

}  // namespace msmesh
