// The HTML report: one self-contained page with an interactive three.js viewer (the bundle in
// report/dist/viewer.js, embedded at build time), the parameters, the error figures and the
// convergence plots. The report library (msmesh_report, report/) makes the pages of the CLI's
// --report options and of msmesh.report() in Python.
#pragma once
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace msmesh {

/// One mesh of the report's 3D viewer.
struct ReportMesh {
  std::string name;                     ///< button label, e.g. "input", "result", "truth"
  Eigen::MatrixXd V;                    ///< #V by 3
  Eigen::MatrixXi F;                    ///< #F by 3
  Eigen::VectorXd face_error_deg;       ///< empty or #F: angle to the truth's face normal
  Eigen::VectorXd edge_field;           ///< empty or #E: v[e] on Topology::edges.row(e) of F
  Eigen::VectorXi face_labels;          ///< empty or #F: segment labels
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
  std::string title;                                            ///< e.g. "msmesh denoise: noisy.obj"
  std::string subtitle;                                         ///< e.g. the command line or a one-line summary
  std::vector<ReportMesh> meshes;                               ///< the viewer's meshes, the first shown first
  int initial_mesh = 0;                                         ///< index into meshes shown when the page opens
  std::string initial_color = "shaded";                         ///< "shaded", "error", "field" or "labels"
  std::vector<std::pair<std::string, std::string>> parameters;  ///< name, value
  /// Tables under the viewer, each with a heading (error figures, run statistics, ...).
  std::vector<std::pair<std::string, ReportTable>> tables;
  std::vector<ReportPlot> plots;   ///< convergence plots (empty: section left out)
  std::vector<std::string> notes;  ///< paragraphs under the figures
};

/// The whole HTML page of `data` (self-contained: viewer script, data and styles inline; no
/// network access when viewed).
std::string report_html(const ReportData& data);

/// Writes report_html(data) to `path` atomically. Throws IoError naming the file.
void write_report(const std::string& path, const ReportData& data);

/// The viewer's JavaScript bundle (report/dist/viewer.js) as embedded in the library.
/// Throws IoError when the build did not embed it and it cannot be read from the source tree.
const std::string& report_viewer_script();

}  // namespace msmesh
