// Pictures and reports of results, for people (issue 7):
//  - figure helpers shared by `msmesh render` and `msmesh compare`: PNG files, the edge-field
//    and label files, colouring a mesh by edge field, angle error or labels;
//  - write_report(): one self-contained HTML file with an interactive three.js viewer (the
//    bundle in report/dist/viewer.js, embedded into the program at build time), the
//    parameters, the error figures and the convergence plots;
//  - write_denoise_report() / write_segment_report() / write_inpaint_report(): the report of
//    one run of those subcommands (their --report option).
#pragma once
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "msmesh/color_bar.h"
#include "msmesh/color_map.h"
#include "msmesh/denoise.h"
#include "msmesh/image.h"
#include "msmesh/inpaint.h"
#include "msmesh/mesh.h"
#include "msmesh/render.h"
#include "msmesh/segment.h"
#include "msmesh/topology.h"

namespace msmesh::cli {

// ---------------------------------------------------------------------------------------
// Figures
// ---------------------------------------------------------------------------------------

/// Writes `image` as a PNG file (atomically). Throws IoError naming the file.
void write_png(const std::string& path, const Image& image);

/// Parses "WxH" (e.g. "800x600") into width and height; throws InvalidInput otherwise.
std::pair<int, int> parse_size(const std::string& text);

/// Reads an edge field written by `msmesh denoise --save-field`: the text format (one edge a
/// line, "i j v"; '#' starts a comment) or the ascii PLY (vertices, then "i j v r g b" edges).
/// Returns #E values in the edge order of `topo`; every edge of `topo` must be listed.
/// Throws IoError naming the file and line, or InvalidInput for a pair that is not an edge.
Eigen::VectorXd read_edge_field(const std::string& path, const Topology& topo);

/// Reads one integer label ≥ 0 per face (whitespace separated, '#' comments), exactly
/// `faces` of them. Throws IoError naming the file.
Eigen::VectorXi read_face_labels(const std::string& path, Eigen::Index faces);

/// The colours and legend of one rendered mesh.
struct Coloring {
  MeshStyle style;
  bool has_bar = false;
  ColorBar bar;
  std::string summary;  ///< one line for the terminal, e.g. "angle error 0-12.5 deg"
};

/// Faces coloured by angle error (degrees, #F) on [0, max_deg] with heat_color();
/// max_deg ≤ 0: automatic (error_scale of the values).
Coloring error_coloring(const Eigen::VectorXd& angle_deg, double max_deg);
/// A round upper end for an error colour scale: the 98th percentile of the values rounded up
/// to 1, 2 or 5 × 10^k (so one wild face does not wash the picture out), at least 1e-3.
double error_scale(const Eigen::VectorXd& values);
/// The edge field v (#E, edges of build_topology(F)) as lines coloured with field_color() of
/// the normalised field (features dark red); smooth edges are left undrawn.
Coloring field_coloring(const Eigen::MatrixXi& F, Eigen::Index num_vertices, const Eigen::VectorXd& v);
/// Faces coloured by label (label_color), with dark lines where the label changes.
Coloring label_coloring(const Eigen::MatrixXi& F, Eigen::Index num_vertices, const Eigen::VectorXi& labels);

/// `picture` with a strip below it holding the colour bar of `c` (when it has one).
Image add_color_bar(const Image& picture, const Coloring& c);

// ---------------------------------------------------------------------------------------
// HTML report
// ---------------------------------------------------------------------------------------

/// One mesh of the report's 3D viewer.
struct ReportMesh {
  std::string name;    ///< button label, e.g. "input", "result", "truth"
  Eigen::MatrixXd V;   ///< #V by 3
  Eigen::MatrixXi F;   ///< #F by 3
  Eigen::VectorXd face_error_deg;  ///< empty or #F: angle to the truth's face normal
  Eigen::VectorXd edge_field;      ///< empty or #E: v on the edges of build_topology(F)
  Eigen::VectorXi face_labels;     ///< empty or #F: segment labels
  std::vector<bool> highlighted_faces;  ///< empty or #F: drawn tinted (e.g. faces added by inpainting)
};

/// One convergence plot: several series of values per iteration on a shared y axis.
struct ReportPlot {
  std::string title, y_label;
  bool log_y = true;
  std::vector<std::pair<std::string, std::vector<double>>> series;  ///< name, value per iteration
};

/// A table: a header row and rows of cells (plain text, escaped on output).
struct ReportTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

struct ReportData {
  std::string title;     ///< e.g. "msmesh denoise: noisy.obj"
  std::string subtitle;  ///< e.g. the command line or a one-line summary
  std::vector<ReportMesh> meshes;  ///< the viewer's meshes, the first shown first
  int initial_mesh = 0;            ///< index into meshes shown when the page opens
  std::string initial_color = "shaded";  ///< "shaded", "error", "field" or "labels"
  std::vector<std::pair<std::string, std::string>> parameters;  ///< name, value
  /// Tables under the viewer, each with a heading (error figures, run statistics, ...).
  std::vector<std::pair<std::string, ReportTable>> tables;
  std::vector<ReportPlot> plots;    ///< convergence plots (empty: section left out)
  std::vector<std::string> notes;   ///< paragraphs under the figures
};

/// The whole HTML page of `data` (self-contained: viewer script, data and styles inline; no
/// network access when viewed).
std::string report_html(const ReportData& data);

/// Writes report_html(data) to `path` atomically. Throws IoError naming the file.
void write_report(const std::string& path, const ReportData& data);

/// The viewer's JavaScript bundle (report/dist/viewer.js) as embedded in this program.
/// Throws IoError when the build did not embed it and it cannot be read from the source tree.
const std::string& report_viewer_script();

/// The report of `msmesh denoise`: input / result / truth meshes (error and edge field colour
/// modes), parameters, figures (MSAE, mean angle, flips, distances) and the residual plots.
void write_denoise_report(const std::string& path, const std::string& input_path, const Mesh& input,
                          const Eigen::MatrixXd& result_V, const Mesh* truth, const std::string& method,
                          const std::string& preset, const DenoiseOptions& options, const DenoiseResult& result);

/// The report of `msmesh segment`: the mesh coloured by segment, its edge field, segment
/// table and the normal filtering plots.
void write_segment_report(const std::string& path, const std::string& input_path, const Mesh& mesh,
                          const SegmentOptions& options, const SegmentResult& result);

/// The report of `msmesh inpaint`: input and result (new faces tinted), truth when given,
/// the hole table and the plots of the last feature-recovery round.
void write_inpaint_report(const std::string& path, const std::string& input_path, const Mesh& input,
                          const InpaintResult& result, const Mesh* truth, const InpaintOptions& options);

}  // namespace msmesh::cli
