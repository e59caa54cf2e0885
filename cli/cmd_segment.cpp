// msmesh segment: piecewise-smooth segmentation from the NMSTV edge field (paper §6.3).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "command.h"
#include "data_notes.h"
#include "field_files.h"
#include "figures.h"
#include "json.h"
#include "msmesh/color_map.h"
#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "msmesh/mesh_attributes.h"
#include "msmesh/parameters.h"
#include "msmesh/presets.h"
#include "msmesh/segment.h"
#include "output_plan.h"
#include "parameter_options.h"
#include "run_reports.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::string input, output, labels, parts, preset = "cad";
  bool denoise_first = false, json = false, quiet = false, ascii = false, in_place = false;
  std::string report;                                            // --report: HTML report (cli/run_reports.h)
  std::unique_ptr<ParameterOptions<SegmentOptions>> parameters;  // --angle, --alpha ... (parameters.h)
};

// The faces of one segment as a mesh of their own, vertices re-indexed in order of use.
Mesh extract_part(const Mesh& m, const Eigen::VectorXi& labels, int label) {
  std::vector<int> map(m.V.rows(), -1), used;
  std::vector<int> faces;
  for (Eigen::Index f = 0; f < m.F.rows(); ++f)
    if (labels(f) == label) faces.push_back(static_cast<int>(f));
  Mesh part;
  part.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t k = 0; k < faces.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      int& to = map[m.F(faces[k], c)];
      if (to < 0) {
        to = static_cast<int>(used.size());
        used.push_back(m.F(faces[k], c));
      }
      part.F(k, c) = to;
    }
  part.V.resize(static_cast<Eigen::Index>(used.size()), 3);
  for (size_t i = 0; i < used.size(); ++i) part.V.row(i) = m.V.row(used[i]);
  // Every attribute follows its vertices and faces (materials, groups, texture coordinates...).
  carry_attributes(m, part, Eigen::Map<const Eigen::VectorXi>(used.data(), static_cast<Eigen::Index>(used.size())),
                   Eigen::Map<const Eigen::VectorXi>(faces.data(), static_cast<Eigen::Index>(faces.size())));
  return part;
}

void run(const Args& a) {
  const DenoiseOptions preset = preset_options(a.preset);
  SegmentOptions o;
  o.normals = preset.normals;
  a.parameters->apply(o);
  o.validate();
  OutputPlan plan;  // every file of the run, checked before any work; outputs committed together
  plan.input(a.input).in_place(a.in_place);
  plan.output(a.output, OutputKind::PlyMesh, "-o")
      .output(a.labels, OutputKind::Text, "--labels")
      .output(a.report, OutputKind::Text, "--report")
      .parts_folder(a.parts, "--parts");
  plan.begin();
  const auto t0 = std::chrono::steady_clock::now();
  ReadNotes read_notes;
  Mesh mesh = read_mesh(a.input, read_notes);

  const ProgressCallback progress = make_progress_bar(a.quiet || a.json);
  double seconds_denoise = 0;
  if (a.denoise_first) {
    const auto td = std::chrono::steady_clock::now();
    mesh.V = denoise(mesh.V, mesh.F, preset, progress).V;
    finish_progress_line();
    seconds_denoise = std::chrono::duration<double>(std::chrono::steady_clock::now() - td).count();
  }
  const auto ts = std::chrono::steady_clock::now();
  const SegmentResult r = segment(mesh.V, mesh.F, o, progress);
  finish_progress_line();
  const double seconds_segment = std::chrono::duration<double>(std::chrono::steady_clock::now() - ts).count();

  Eigen::MatrixXd colors(mesh.F.rows(), 3);
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) colors.row(f) = label_color(r.labels(f)).transpose();
  write_ply_face_colors(a.output, mesh, colors, !a.ascii);
  Mesh written = mesh;  // the input's own face colours are replaced by the segments' (said so)
  written.face_colors = colors;
  std::vector<std::string> notes = data_notes(a.input, read_notes, {}, written, a.output);
  if (mesh.face_colors.size() > 0)
    notes.push_back(a.output + ": the input's face colours are replaced by the segment colours");
  if (!a.report.empty()) write_segment_report(a.report, a.input, mesh, o, r);
  if (!a.labels.empty()) {
    std::ostringstream os;
    for (Eigen::Index f = 0; f < r.labels.size(); ++f) os << r.labels(f) << "\n";
    write_text_file(a.labels, os.str());
  }
  std::vector<Eigen::Index> face_count(r.count, 0);
  for (Eigen::Index f = 0; f < r.labels.size(); ++f) ++face_count[r.labels(f)];
  if (!a.parts.empty()) {
    create_output_folder(a.parts);  // removed again if the run fails
    for (int s = 0; s < r.count; ++s) {
      char name[32];
      std::snprintf(name, sizeof name, "part_%03d.obj", s);
      write_mesh((std::filesystem::path(a.parts) / name).string(), extract_part(mesh, r.labels, s));
    }
  }
  plan.commit();
  const double total_area = r.areas.sum();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  if (a.json) {
    Json j;
    j.add("input", a.input).add("output", a.output).add("preset", a.preset).add("denoised", a.denoise_first);
    j.add("faces", static_cast<long long>(mesh.F.rows()))
        .add("segments", r.count)
        .add("multicut_segments", r.multicut_count)
        .add("objective", r.objective);
    std::vector<Json> segs;
    for (int s = 0; s < r.count; ++s) {
      Json k;
      k.add("label", s)
          .add("faces", static_cast<long long>(face_count[s]))
          .add("area", r.areas(s))
          .add("area_fraction", total_area > 0 ? r.areas(s) / total_area : 0.0);
      segs.push_back(k);
    }
    j.add("segment_list", segs).add("parameters", parameters_json(segment_parameters(), o));
    j.add("normal_iterations", r.normal_report.iterations)
        .add("seconds_denoise", seconds_denoise)
        .add("seconds_segment", seconds_segment)
        .add("seconds_total", seconds);
    if (!a.labels.empty()) j.add("labels", a.labels);
    if (!a.parts.empty()) j.add("parts", a.parts);
    add_notes(j, notes);
    std::cout << j.str() << "\n";
    return;
  }
  print_notes(notes);
  if (a.quiet) return;
  std::cout << "segmented " << a.input << " -> " << a.output << " (" << mesh.F.rows() << " faces"
            << (a.denoise_first ? ", denoised first" : "") << ")\n";
  std::cout << "  " << r.count << " segments";
  if (r.multicut_count != r.count) std::cout << " (multicut " << r.multicut_count << ", small ones merged)";
  std::cout << ", preset " << a.preset << ", " << fmt(seconds_segment, 3) << " s\n";
  for (int s = 0; s < r.count; ++s)
    std::cout << "  segment " << s << ": " << face_count[s] << " faces, area " << fmt(r.areas(s)) << " ("
              << fmt(total_area > 0 ? 100 * r.areas(s) / total_area : 0.0, 3) << "%)\n";
  if (!a.labels.empty()) std::cout << "  labels written to " << a.labels << "\n";
  if (!a.report.empty()) std::cout << "  report written to " << a.report << "\n";
  if (!a.parts.empty()) std::cout << "  " << r.count << " parts written to " << a.parts << "/part_NNN.obj\n";
}

const Registrar kRegistration("segment", 70, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c =
      app.add_subcommand("segment", "Segment a mesh into piecewise-smooth parts (NMSTV edge field + multicut)");
  c->add_option("input", a->input, "Input mesh (obj, off, ply, stl, gltf, glb; also .gz)")->required();
  c->add_option("-o,--output", a->output, "Output .ply with one colour per segment on its faces")->required();
  c->add_option("--labels", a->labels,
                "Write the segment label of each face (one per line, input order; -: standard output)");
  c->add_option("--parts", a->parts, "Write each segment as a mesh DIR/part_NNN.obj (re-indexed)");
  c->add_option("--report", a->report, "Write an HTML report: 3D viewer of the segments and edge field, segment table");
  c->add_flag("--denoise", a->denoise_first, "Denoise first (msmesh denoise with the same preset), then segment");
  c->add_option("--preset", a->preset, "Normal filter parameters: cad (sharp features) or smooth (organic)")
      ->check(CLI::IsMember(preset_names()))
      ->capture_default_str();
  std::vector<std::pair<std::string, SegmentOptions>> defaults;
  for (const std::string& name : preset_names()) {
    defaults.emplace_back(name, SegmentOptions{});
    defaults.back().second.normals = preset_options(name).normals;
  }
  a->parameters = std::make_unique<ParameterOptions<SegmentOptions>>(c, segment_parameters(), defaults, "");
  c->add_flag("--json", a->json, "Print one JSON object instead of the summary");
  add_quiet_flag(c, a->quiet);
  c->add_flag("--ascii", a->ascii, "Write the PLY as ascii instead of binary");
  c->add_flag("--in-place", a->in_place, "Allow the output to overwrite the input file");
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
