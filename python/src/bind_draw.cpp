// Bindings of pictures: RenderOptions, render() (one mesh, coloured as `msmesh render`
// colours it), compare() (the sheet of `msmesh compare`) and PNG files.
#include <cstdint>
#include <string>
#include <vector>

#include "bindings.h"
#include "msmesh/atomic_file.h"
#include "msmesh/compare_sheet.h"
#include "msmesh/errors.h"
#include "msmesh/mesh.h"
#include "msmesh/mesh_coloring.h"
#include "msmesh/metrics.h"
#include "msmesh/png.h"
#include "msmesh/render.h"
#include "msmesh/topology.h"

namespace py = pybind11;

namespace msmesh::python {

namespace {

py::array_t<std::uint8_t> image_to_numpy(const Image& im) {
  py::array_t<std::uint8_t> a(
      {static_cast<py::ssize_t>(im.height), static_cast<py::ssize_t>(im.width), static_cast<py::ssize_t>(3)});
  std::copy(im.rgb.begin(), im.rgb.end(), a.mutable_data());
  return a;
}

Image image_from_numpy(const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>& a) {
  if (a.ndim() != 3 || a.shape(2) != 3) throw InvalidInput("image: shape must be (height, width, 3)");
  Image im;
  im.height = static_cast<int>(a.shape(0));
  im.width = static_cast<int>(a.shape(1));
  im.rgb.assign(a.data(), a.data() + a.size());
  return im;
}

/// The colouring of `msmesh render --color`: auto, none, file, error, field or labels.
Coloring coloring(const std::string& color, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                  const Eigen::MatrixXd& vertex_colors, const Eigen::MatrixXd& V_truth, const Eigen::MatrixXi& F_truth,
                  const Eigen::VectorXd& v, const Eigen::VectorXi& labels, double error_max) {
  std::string c = color;
  if (c == "auto") c = vertex_colors.size() ? "file" : "none";
  if (c == "none") return {};
  if (c == "file") {
    if (vertex_colors.size() == 0) throw InvalidInput("render: color='file' needs vertex_colors");
    return vertex_coloring(vertex_colors, V.rows());
  }
  if (c == "error") {
    if (V_truth.size() == 0) throw InvalidInput("render: color='error' needs truth=(V, F)");
    const NormalErrors e = normal_errors(V, F, V_truth, F_truth);
    return error_coloring(e.angle_rad * (180.0 / M_PI), error_max);
  }
  if (c == "field") return field_coloring(F, V.rows(), v);
  if (c == "labels") return label_coloring(F, V.rows(), labels);
  throw InvalidInput("render: unknown color '" + color + "'; valid: auto, none, file, error, field, labels");
}

py::tuple render_binding(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const RenderOptions& options,
                         const std::string& color, const Eigen::MatrixXd& vertex_colors, const Eigen::MatrixXd& V_truth,
                         const Eigen::MatrixXi& F_truth, const Eigen::VectorXd& v, const Eigen::VectorXi& labels,
                         double feature_angle, double error_max) {
  check_parameter("render", "feature_edges", feature_angle, {0, 180, false, true});
  check_parameter("render", "error_max", error_max, {0, 180});
  std::string summary;
  const Image image = run_without_gil(py::none(), [&](const ProgressCallback&) {
    options.validate();
    validate_mesh(V, F, "render");
    Coloring c = coloring(color, V, F, vertex_colors, V_truth, F_truth, v, labels, error_max);
    if (feature_angle > 0 && c.style.lines.rows() == 0) {
      c.style.lines = sharp_edges(V, F, feature_angle);
      c.style.line_colors = Eigen::RowVector3d(0.1, 0.1, 0.1);
    }
    summary = c.summary;
    return add_color_bar(render_mesh(V, F, c.style, options), c);
  });
  return py::make_tuple(image_to_numpy(image), summary);
}

py::dict compare_binding(const std::vector<ComparePanel>& panels, const Eigen::MatrixXd& V_truth,
                         const Eigen::MatrixXi& F_truth, const CompareOptions& options) {
  const CompareSheet s = run_without_gil(
      py::none(), [&](const ProgressCallback&) { return compare_sheet(panels, V_truth, F_truth, options); });
  py::dict d;
  d["image"] = image_to_numpy(s.image);
  py::list figures;
  for (const Evaluation& e : s.evaluations) {
    py::dict f;
    f["same_connectivity"] = e.same_connectivity;
    f["msae_e3"] = e.same_connectivity ? py::cast(e.normals.msae * 1e3) : py::none();
    f["mean_angle_deg"] = e.same_connectivity ? py::cast(e.normals.mean_angle_deg) : py::none();
    f["flipped"] = e.same_connectivity ? py::cast(static_cast<long long>(e.normals.flipped)) : py::none();
    f["distance_rms"] = e.distances.rms;
    figures.append(f);
  }
  d["panels"] = figures;
  d["error_top"] = s.error_top;
  d["noisy_panel"] = s.noisy_panel >= 0 ? py::cast(s.noisy_panel) : py::none();
  d["saturated"] = s.saturated;
  d["scale_note"] = s.scale_note;
  return d;
}

void write_png_binding(const std::string& path,
                       const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>& a) {
  const Image im = image_from_numpy(a);
  run_without_gil(py::none(), [&](const ProgressCallback&) {
    const std::vector<std::uint8_t> bytes = encode_png(im);
    write_file_atomically(path, [&](std::ostream& os) {
      os.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    });
    return 0;
  });
}

}  // namespace

void bind_draw(py::module_& m) {
  py::class_<RenderOptions>(m, "RenderOptions", "Options of render() (see render.h).")
      .def(py::init<>())
      .def_property(
          "view", [](const RenderOptions& o) { return view_names()[static_cast<size_t>(o.view)]; },
          [](RenderOptions& o, const std::string& name) { o.view = view_from_name(name); })
      .def_property(
          "up", [](const RenderOptions& o) { return up_axis_name(o.up); },
          [](RenderOptions& o, const std::string& name) { o.up = up_axis_from_name(name); })
      .def_property(
          "perspective", [](const RenderOptions& o) { return o.projection == Projection::Perspective; },
          [](RenderOptions& o, bool p) { o.projection = p ? Projection::Perspective : Projection::Orthographic; })
      .def_readwrite("background", &RenderOptions::background)
      .def_readwrite("base_color", &RenderOptions::base_color)
      .def("validate", &RenderOptions::validate);
  m.def("view_names", &view_names);
  m.def("up_axis_names", &up_axis_names);
  m.def("sheet_color_names", &sheet_color_names);
  m.def("render", &render_binding, py::arg("V"), py::arg("F"), py::arg("options"), py::arg("color"),
        py::arg("vertex_colors"), py::arg("V_truth"), py::arg("F_truth"), py::arg("v"), py::arg("labels"),
        py::arg("feature_angle"), py::arg("error_max"));

  py::class_<ComparePanel>(m, "ComparePanel", "One mesh of compare() (see compare_sheet.h).")
      .def(py::init([](const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const Eigen::MatrixXd& colors,
                       const std::string& caption) {
             return ComparePanel{V, F, colors, caption};
           }),
           py::arg("V"), py::arg("F"), py::arg("vertex_colors"), py::arg("caption"));
  py::class_<CompareOptions>(m, "CompareOptions", "Options of compare() (see compare_sheet.h).")
      .def(py::init<>())
      .def_readwrite("render", &CompareOptions::render)
      .def_property(
          "color", [](const CompareOptions& o) { return sheet_color_names()[static_cast<size_t>(o.color)]; },
          [](CompareOptions& o, const std::string& name) { o.color = sheet_color_from_name(name); })
      .def_readwrite("feature_angle", &CompareOptions::feature_angle)
      .def_readwrite("error_max", &CompareOptions::error_max)
      .def_readwrite("noisy_panel", &CompareOptions::noisy_panel)
      .def_readwrite("title", &CompareOptions::title)
      .def("validate", &CompareOptions::validate);
  m.attr("NOISY_PANEL_AUTO") = kNoisyPanelAuto;
  m.attr("NO_NOISY_PANEL") = kNoNoisyPanel;
  m.def("compare", &compare_binding, py::arg("panels"), py::arg("V_truth"), py::arg("F_truth"), py::arg("options"));
  m.def("write_png", &write_png_binding, py::arg("path"), py::arg("image"));
}

}  // namespace msmesh::python
