// Bindings of the HTML report (msmesh/report_page.h): report(), one self-contained page with
// the 3D viewer, tables, parameters, convergence plots and notes, as the CLI's --report.
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bindings.h"
#include "msmesh/errors.h"
#include "msmesh/report_page.h"

namespace py = pybind11;

namespace msmesh::python {

namespace {

/// A viewer mesh from a dict: name, V, F and optionally face_error_deg, edge_field,
/// face_labels, highlighted_faces (already checked by msmesh/__init__.py).
ReportMesh report_mesh(const py::dict& d) {
  ReportMesh m;
  m.name = d["name"].cast<std::string>();
  m.V = d["V"].cast<Eigen::MatrixXd>();
  m.F = d["F"].cast<Eigen::MatrixXi>();
  if (d.contains("face_error_deg")) m.face_error_deg = d["face_error_deg"].cast<Eigen::VectorXd>();
  if (d.contains("edge_field")) m.edge_field = d["edge_field"].cast<Eigen::VectorXd>();
  if (d.contains("face_labels")) m.face_labels = d["face_labels"].cast<Eigen::VectorXi>();
  if (d.contains("highlighted_faces")) m.highlighted_faces = d["highlighted_faces"].cast<std::vector<bool>>();
  return m;
}

using Table = std::tuple<std::string, std::vector<std::string>, std::vector<std::vector<std::string>>>;
using Plot = std::tuple<std::string, std::string, bool, std::vector<std::pair<std::string, std::vector<double>>>>;

ReportData report_data(const std::vector<py::dict>& meshes, const std::string& title, const std::string& subtitle,
                       int initial_mesh, const std::string& initial_color,
                       const std::vector<std::pair<std::string, std::string>>& parameters,
                       const std::vector<Table>& tables, const std::vector<Plot>& plots,
                       const std::vector<std::string>& notes) {
  ReportData d;
  for (const py::dict& m : meshes) d.meshes.push_back(report_mesh(m));
  d.title = title;
  d.subtitle = subtitle;
  d.initial_mesh = initial_mesh;
  d.initial_color = initial_color;
  d.parameters = parameters;
  for (const auto& [heading, header, rows] : tables) d.tables.push_back({heading, ReportTable{header, rows}});
  for (const auto& [plot_title, y_label, log_y, series] : plots)
    d.plots.push_back({plot_title, y_label, log_y, series});
  d.notes = notes;
  return d;
}

void write_report_binding(const std::string& path, const std::vector<py::dict>& meshes, const std::string& title,
                          const std::string& subtitle, int initial_mesh, const std::string& initial_color,
                          const std::vector<std::pair<std::string, std::string>>& parameters,
                          const std::vector<Table>& tables, const std::vector<Plot>& plots,
                          const std::vector<std::string>& notes) {
  const ReportData d =
      report_data(meshes, title, subtitle, initial_mesh, initial_color, parameters, tables, plots, notes);
  run_without_gil(py::none(), [&](const ProgressCallback&) {
    write_report(path, d);
    return 0;
  });
}

std::string report_html_binding(const std::vector<py::dict>& meshes, const std::string& title,
                                const std::string& subtitle, int initial_mesh, const std::string& initial_color,
                                const std::vector<std::pair<std::string, std::string>>& parameters,
                                const std::vector<Table>& tables, const std::vector<Plot>& plots,
                                const std::vector<std::string>& notes) {
  const ReportData d =
      report_data(meshes, title, subtitle, initial_mesh, initial_color, parameters, tables, plots, notes);
  return run_without_gil(py::none(), [&](const ProgressCallback&) { return report_html(d); });
}

}  // namespace

void bind_report(py::module_& m) {
  m.def("write_report", &write_report_binding, py::arg("path"), py::arg("meshes"), py::arg("title"),
        py::arg("subtitle"), py::arg("initial_mesh"), py::arg("initial_color"), py::arg("parameters"),
        py::arg("tables"), py::arg("plots"), py::arg("notes"));
  m.def("report_html", &report_html_binding, py::arg("meshes"), py::arg("title"), py::arg("subtitle"),
        py::arg("initial_mesh"), py::arg("initial_color"), py::arg("parameters"), py::arg("tables"), py::arg("plots"),
        py::arg("notes"));
}

}  // namespace msmesh::python
