#include "run_reports.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "msmesh/metrics.h"
#include "msmesh/parameters.h"

namespace msmesh::cli {

namespace {

std::string num(double x, int precision = 4) {
  if (!std::isfinite(x)) return "-";
  char b[48];
  std::snprintf(b, sizeof b, "%.*g", precision, x);
  return b;
}

std::string file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

/// The rows of the report's parameter table, from the parameter table (parameters.h): every
/// parameter whose group is in `groups` (empty: all).
template <class Options>
void add_parameters(ReportData& d, const ParameterTable<Options>& table, const Options& o,
                    const std::vector<std::string>& groups = {}) {
  for (const Parameter<Options>& p : table) {
    const ParameterInfo& i = p.info;
    if (!groups.empty() && std::find(groups.begin(), groups.end(), i.group) == groups.end()) continue;
    std::string value = i.type == ParameterType::Boolean ? (p.get(o) != 0 ? "yes" : "no") : i.format(p.get(o));
    if (!i.unit.empty()) value += " " + i.unit;
    d.parameters.push_back({i.name + (i.symbol.empty() ? "" : " (" + i.symbol + ")") + ": " + i.help, value});
  }
}

void add_plots(ReportData& d, const NormalFilterStats& n, const VertexUpdateStats* v) {
  if (!n.residual_history.empty() || !n.change_history.empty()) {
    ReportPlot p;
    p.title = "Normal filtering (Algorithm 1)";
    p.y_label = "mean-edge units";
    p.series.push_back({"residual |p - grad N|_V", n.residual_history});
    p.series.push_back({"change |N(k+1) - N(k)|_U", n.change_history});
    d.plots.push_back(p);
  }
  if (!n.energy_history.empty()) {
    ReportPlot p;
    p.title = "Energy (15) per iteration";
    p.y_label = "energy";
    p.log_y = false;
    p.series.push_back({"energy", n.energy_history});
    d.plots.push_back(p);
  }
  if (v && !v->change_history.empty()) {
    ReportPlot p;
    p.title = "Vertex update (Algorithm 2)";
    p.y_label = "RMS vertex move";
    p.series.push_back({"RMS vertex move (mean edges)", v->change_history});
    d.plots.push_back(p);
  }
}

}  // namespace

void write_denoise_report(const std::string& path, const std::string& input_path, const Mesh& input,
                          const Eigen::MatrixXd& result_V, const Mesh* truth, const std::string& method,
                          const std::string& preset, const DenoiseOptions& o, const DenoiseResult& r,
                          const Evaluation& ev_in, const Evaluation& ev_out) {
  ReportData d;
  d.title = "msmesh denoise: " + file_name(input_path);
  d.subtitle = std::to_string(input.V.rows()) + " vertices, " + std::to_string(input.F.rows()) + " faces; method " +
               method + (o.method == DenoiseMethod::Bilateral ? "" : ", preset " + preset);
  ReportMesh in{"input", input.V, input.F, {}, {}, {}, {}};
  ReportMesh out{"result", result_V, input.F, {}, r.v, {}, {}};
  if (truth) {
    if (ev_in.same_connectivity) in.face_error_deg = ev_in.normals.angle_rad * (180.0 / M_PI);
    if (ev_out.same_connectivity) out.face_error_deg = ev_out.normals.angle_rad * (180.0 / M_PI);
  }
  d.meshes.push_back(in);
  d.meshes.push_back(out);
  if (truth) d.meshes.push_back({"truth", truth->V, truth->F, {}, {}, {}, {}});
  d.initial_mesh = 1;
  d.initial_color = out.face_error_deg.size() ? "error" : (r.v.size() ? "field" : "shaded");

  d.parameters.push_back({"input", input_path});
  d.parameters.push_back({"method", method});
  if (o.method != DenoiseMethod::Bilateral) {
    d.parameters.push_back({"preset", preset});
    d.parameters.push_back({"IRLA reweighting", o.method == DenoiseMethod::NMSTV ? "on (NMSTV)" : "off (MSTV)"});
    add_parameters(d, denoise_parameters(), o, {"normal filtering", "vertex update", "solver"});
  } else {
    add_parameters(d, denoise_parameters(), o, {"bilateral filtering"});
  }

  if (truth) {
    ReportTable t;
    t.header = {"mesh",
                "MSAE (x1e-3)",
                "mean angle (deg)",
                "flipped faces",
                "dist. mean (x1e-3)",
                "dist. RMS (x1e-3)",
                "dist. max (x1e-3)"};
    auto row = [&](const std::string& name, const Evaluation& e) {
      const bool s = e.same_connectivity;
      t.rows.push_back({name, s ? num(e.normals.msae * 1e3) : "-", s ? num(e.normals.mean_angle_deg) : "-",
                        s ? std::to_string(e.normals.flipped) : "-", num(e.distances.mean * 1e3),
                        num(e.distances.rms * 1e3), num(e.distances.max * 1e3)});
    };
    row("input", ev_in);
    row("result", ev_out);
    d.tables.push_back({"Error against the ground truth", t});
    d.notes.push_back(
        "MSAE: mean over faces of the squared angle (radians) between result and truth face normals, "
        "printed x1e-3 as in the paper; mean angle: the plain mean angle in degrees. Distances: "
        "vertex to truth surface over the truth's bounding-box diagonal.");
  }
  ReportTable run;
  run.header = {"stage", "iterations", "converged", "seconds", "final value"};
  if (o.method != DenoiseMethod::Bilateral) {
    const auto& n = r.normal_report;
    run.rows.push_back({"normal filtering", std::to_string(n.iterations), n.converged ? "yes" : "no",
                        num(r.seconds_normals, 3),
                        n.residual_history.empty() ? "-" : "residual " + num(n.residual_history.back())});
  } else {
    run.rows.push_back(
        {"bilateral normals", std::to_string(o.bilateral.normal_iterations), "-", num(r.seconds_normals, 3), "-"});
  }
  const auto& v = r.vertex_report;
  run.rows.push_back({"vertex update", std::to_string(v.iterations), v.converged ? "yes" : "no",
                      num(r.seconds_vertices, 3),
                      v.change_history.empty() ? "-" : "RMS move " + num(v.change_history.back())});
  d.tables.push_back({"Run", run});
  add_plots(d, r.normal_report, &r.vertex_report);
  write_report(path, d);
}

void write_segment_report(const std::string& path, const std::string& input_path, const Mesh& mesh,
                          const SegmentOptions& o, const SegmentResult& r) {
  ReportData d;
  d.title = "msmesh segment: " + file_name(input_path);
  d.subtitle = std::to_string(mesh.F.rows()) + " faces, " + std::to_string(r.count) + " segments";
  d.meshes.push_back({"mesh", mesh.V, mesh.F, {}, r.v, r.labels, {}});
  d.initial_color = "labels";
  d.parameters.push_back({"input", input_path});
  add_parameters(d, segment_parameters(), o);
  ReportTable t;
  t.header = {"segment", "faces", "area", "area (%)"};
  std::vector<long> faces(r.count, 0);
  for (Eigen::Index f = 0; f < r.labels.size(); ++f) ++faces[r.labels(f)];
  const double total = r.areas.sum();
  for (int s = 0; s < r.count; ++s)
    t.rows.push_back({std::to_string(s), std::to_string(faces[s]), num(r.areas(s)),
                      num(total > 0 ? 100 * r.areas(s) / total : 0.0, 3)});
  d.tables.push_back({"Segments", t});
  d.notes.push_back("Multicut found " + std::to_string(r.multicut_count) + " segments (objective " + num(r.objective) +
                    "); segments below the minimum area were merged into a neighbour.");
  add_plots(d, r.normal_report, nullptr);
  write_report(path, d);
}

void write_inpaint_report(const std::string& path, const std::string& input_path, const Mesh& input,
                          const InpaintResult& r, const Mesh* truth, const InpaintOptions& o) {
  ReportData d;
  d.title = "msmesh inpaint: " + file_name(input_path);
  d.subtitle = std::to_string(r.filled) + " of " + std::to_string(r.holes.size()) + " holes filled; " +
               std::to_string(r.F.rows() - input.F.rows()) + " faces added";
  d.meshes.push_back({"input", input.V, input.F, {}, {}, {}, {}});
  ReportMesh out{"result", r.V, r.F, {}, {}, {}, r.new_faces};
  d.meshes.push_back(out);
  if (truth) d.meshes.push_back({"truth", truth->V, truth->F, {}, {}, {}, {}});
  d.initial_mesh = 1;
  d.parameters.push_back({"input", input_path});
  add_parameters(d, inpaint_parameters(), o);
  ReportTable t;
  t.header = {"hole", "edges", "diameter", "action", "new faces", "features"};
  for (size_t i = 0; i < r.holes.size(); ++i) {
    const HoleReport& rep = r.reports[i];
    const char* action = hole_action_name(rep.action);
    t.rows.push_back({std::to_string(i), std::to_string(r.holes[i].edges), num(r.holes[i].diameter, 3),
                      std::string(action) + (rep.reason.empty() ? "" : " (" + rep.reason + ")"),
                      std::to_string(rep.new_faces),
                      rep.action == HoleAction::Filled ? (rep.features ? "recovered" : "fair patch") : "-"});
  }
  d.tables.push_back({"Holes", t});
  if (truth) {
    const InpaintErrors e = inpaint_errors(input.V, input.F, r.V, r.F, r.new_faces, truth->V, truth->F);
    ReportTable f;
    f.header = {"points", "max (x1e-3)", "mean (x1e-3)", "RMS (x1e-3)", "new-face normal error (deg)"};
    f.rows.push_back({std::to_string(e.points), num(e.max * 1e3), num(e.mean * 1e3), num(e.rms * 1e3),
                      num(e.mean_normal_error_deg)});
    d.tables.push_back({"Filled region against the ground truth", f});
  }
  d.notes.push_back(
      "New faces are tinted in the viewer's shaded mode. Plots: the last feature-recovery round, on the region around "
      "the recovered holes.");
  add_plots(d, r.normal_report, &r.vertex_report);
  write_report(path, d);
}

}  // namespace msmesh::cli
