// msmesh inpaint: fill the holes of a mesh (CGAL fill-and-fair) and recover their sharp
// features with NMSTV normal filtering + vertex updating (paper §6.2).
#include <iostream>
#include <memory>
#include <sstream>

#include "command.h"
#include "data_notes.h"
#include "field_files.h"
#include "figures.h"
#include "json.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/inpaint.h"
#include "msmesh/io.h"
#include "msmesh/mesh_attributes.h"
#include "msmesh/metrics.h"
#include "msmesh/parameters.h"
#include "number_option.h"
#include "output_plan.h"
#include "parameter_options.h"
#include "run_reports.h"
#include "usage_error.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::string input, output, truth;
  std::vector<int> holes;
  bool list = false, json = false, quiet = false, in_place = false, ascii = false;
  std::string report;                                            // --report: HTML report (cli/run_reports.h)
  std::unique_ptr<ParameterOptions<InpaintOptions>> parameters;  // every InpaintOptions number (parameters.h)
};

std::string hole_note(const Hole& h) {
  if (!h.simple) return "boundary touches itself at vertex " + std::to_string(h.touching_vertex);
  if (h.outer_boundary) return "outer boundary (not filled unless listed)";
  return "";
}

Json hole_json(int i, const Hole& h) {
  Json j;
  j.add("index", i)
      .add("edges", h.edges)
      .add("diameter", h.diameter)
      .add("length", h.length)
      .add("component", h.component)
      .add("outer_boundary", h.outer_boundary)
      .add("simple", h.simple);
  if (!h.simple) j.add("touching_vertex", h.touching_vertex);
  return j;
}

void list_holes(const Args& a) {
  const Mesh mesh = read_mesh(a.input);
  const std::vector<Hole> holes = find_holes(mesh.V, mesh.F);
  if (a.json) {
    std::vector<Json> hs;
    for (size_t i = 0; i < holes.size(); ++i) hs.push_back(hole_json(static_cast<int>(i), holes[i]));
    Json j;
    j.add("input", a.input).add("holes", hs);
    std::cout << j.str() << "\n";
    return;
  }
  if (holes.empty()) {
    std::cout << a.input << ": no holes (no boundary edges)\n";
    return;
  }
  std::cout << a.input << ": " << holes.size() << " boundary loop" << (holes.size() == 1 ? "" : "s")
            << " (diameter in mean edge lengths)\n";
  std::cout << "  index  edges  diameter  note\n";
  for (size_t i = 0; i < holes.size(); ++i) {
    char line[96];
    std::snprintf(line, sizeof line, "  %5zu  %5d  %8.2f  ", i, holes[i].edges, holes[i].diameter);
    std::cout << line << hole_note(holes[i]) << "\n";
  }
}

Json errors_json(const InpaintErrors& e) {
  Json k;
  k.add("points", static_cast<long long>(e.points))
      .add("max_e3", e.max * 1e3)
      .add("mean_e3", e.mean * 1e3)
      .add("rms_e3", e.rms * 1e3)
      .add("new_faces", static_cast<long long>(e.new_faces))
      .add("new_face_normal_error_deg", e.mean_normal_error_deg);
  return k;
}

void run(const Args& a) {
  if (a.list) {
    list_holes(a);
    return;
  }
  if (a.output.empty()) throw UsageError("inpaint: --output is required (or --list to only list the holes)");
  InpaintOptions o;
  o.holes = a.holes;
  try {
    a.parameters->apply(o);
    o.validate();
  } catch (const UsageError&) {
    throw;
  } catch (const InvalidInput& e) {
    throw UsageError(e.what());  // a combination of options out of range: still a usage error
  }
  OutputPlan plan;  // every file of the run, checked before any work; outputs committed together
  plan.input(a.input).input(a.truth, "--truth").in_place(a.in_place);
  plan.output(a.output, OutputKind::Mesh, "-o").output(a.report, OutputKind::Text, "--report");
  plan.begin();
  ReadNotes read_notes;
  const Mesh mesh = read_mesh(a.input, read_notes);
  Mesh truth;
  if (!a.truth.empty()) truth = read_mesh(a.truth);

  const InpaintResult r = inpaint(mesh.V, mesh.F, o, make_progress_bar(a.quiet || a.json));
  finish_progress_line();

  Mesh out;
  out.V = r.V;
  out.F = r.F;
  const Eigen::Index added = r.V.rows() - mesh.V.rows();
  // Input vertices and faces keep their rows (inpaint.h); the new ones take the values of their
  // nearest input neighbours, and new faces get no texture coordinates (said in a note).
  Eigen::VectorXi vertex_origin = Eigen::VectorXi::Constant(r.V.rows(), -1);
  Eigen::VectorXi face_origin = Eigen::VectorXi::Constant(r.F.rows(), -1);
  vertex_origin.head(mesh.V.rows()).setLinSpaced(mesh.V.rows(), 0, static_cast<int>(mesh.V.rows()) - 1);
  face_origin.head(mesh.F.rows()).setLinSpaced(mesh.F.rows(), 0, static_cast<int>(mesh.F.rows()) - 1);
  const std::vector<std::string> carried = carry_attributes(mesh, out, vertex_origin, face_origin);
  if (mesh.vertex_normals.size() > 0) out.vertex_normals = vertex_normals(out.V, out.F);
  WriteOptions wo;
  wo.binary = !a.ascii;
  write_mesh(a.output, out, wo);
  const std::vector<std::string> notes = data_notes(a.input, read_notes, carried, out, a.output);

  InpaintErrors err;
  if (!a.truth.empty()) err = inpaint_errors(mesh.V, mesh.F, r.V, r.F, r.new_faces, truth.V, truth.F);
  if (!a.report.empty()) write_inpaint_report(a.report, a.input, mesh, r, a.truth.empty() ? nullptr : &truth, o);
  plan.commit();

  if (a.json) {
    Json j;
    j.add("input", a.input).add("output", a.output).add("features", o.recover_features);
    j.add("vertices", static_cast<long long>(mesh.V.rows())).add("faces", static_cast<long long>(mesh.F.rows()));
    j.add("holes_found", static_cast<int>(r.holes.size()))
        .add("filled", r.filled)
        .add("skipped", r.skipped)
        .add("failed", r.failed)
        .add("featured", r.featured);
    j.add("new_vertices", static_cast<long long>(added))
        .add("new_faces", static_cast<long long>(r.F.rows() - mesh.F.rows()))
        .add("moved_input_vertices", r.moved_input_vertices)
        .add("crease_flips", r.crease_flips);
    std::vector<Json> hs;
    for (size_t i = 0; i < r.holes.size(); ++i) {
      Json h = hole_json(static_cast<int>(i), r.holes[i]);
      const HoleReport& rep = r.reports[i];
      h.add("action", hole_action_name(rep.action));
      if (!rep.reason.empty()) h.add("reason", rep.reason);
      if (rep.action == HoleAction::Filled)
        h.add("new_faces", rep.new_faces)
            .add("new_vertices", rep.new_vertices)
            .add("faired", rep.faired)
            .add("features", rep.features)
            .add("crease_test", rep.features_reason);
      hs.push_back(h);
    }
    j.add("holes", hs);
    add_notes(j, notes);
    j.add("parameters", parameters_json(inpaint_parameters(), o));
    j.add("seconds_fill", r.seconds_fill).add("seconds_features", r.seconds_features);
    if (!a.truth.empty()) j.add("truth", a.truth).add("errors", errors_json(err));
    std::cout << j.str() << "\n";
    return;
  }

  print_notes(notes);
  if (a.quiet) return;
  if (r.holes.empty()) {
    std::cout << a.input << " has no holes: " << a.output << " is the input mesh unchanged (" << mesh.V.rows()
              << " vertices, " << mesh.F.rows() << " faces)\n";
    return;
  }
  {
    for (size_t i = 0; i < r.holes.size(); ++i) {
      const Hole& h = r.holes[i];
      const HoleReport& rep = r.reports[i];
      std::cout << "  hole " << i << " (" << h.edges << " edges, diameter " << fmt(h.diameter, 3)
                << "): " << hole_action_name(rep.action);
      if (rep.action == HoleAction::Filled) {
        std::cout << ", " << rep.new_faces << " faces, " << rep.new_vertices << " vertices";
        if (!rep.faired) std::cout << " (CGAL fairing failed: patch kept unfaired)";
        if (o.recover_features)
          std::cout << (rep.features ? "; features recovered (" : "; smooth, CGAL's fair patch kept (")
                    << rep.features_reason << ")";
      } else {
        std::cout << ": " << rep.reason;
      }
      std::cout << "\n";
    }
  }
  std::cout << "inpainted " << a.input << " -> " << a.output << ": " << r.filled << " of " << r.holes.size()
            << " holes filled";
  if (r.skipped) std::cout << ", " << r.skipped << " skipped";
  if (r.failed) std::cout << ", " << r.failed << " failed";
  std::cout << "; " << added << " vertices and " << (r.F.rows() - mesh.F.rows()) << " faces added\n";
  std::cout << "  fill " << fmt(r.seconds_fill, 3) << " s";
  if (o.recover_features && r.featured > 0)
    std::cout << ", feature recovery " << fmt(r.seconds_features, 3) << " s (" << r.featured << " of " << r.filled
              << " filled holes, " << r.crease_flips << " crease flips, "
              << (o.free_ring ? std::to_string(r.moved_input_vertices) + " input vertices freed"
                              : std::string("input vertices unchanged"))
              << ")";
  else if (o.recover_features && r.filled > 0)
    std::cout << " (no crease runs into any filled hole: CGAL's fair patches kept)";
  else if (!o.recover_features)
    std::cout << " (CGAL fill-and-fair only)";
  std::cout << "\n";
  if (!a.truth.empty())
    std::cout << "  filled region vs truth: max/mean/RMS " << fmt(err.max * 1e3) << "/" << fmt(err.mean * 1e3) << "/"
              << fmt(err.rms * 1e3) << " e-3 of bbox diagonal (" << err.points << " points), new-face normal error "
              << fmt(err.mean_normal_error_deg) << " deg\n";
  if (!a.report.empty()) std::cout << "  report written to " << a.report << "\n";
}

const Registrar kRegistration("inpaint", 80, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c = app.add_subcommand(
      "inpaint", "Fill holes (CGAL fill-and-fair) and recover their sharp features with NMSTV (paper 6.2)");
  c->add_option("input", a->input, "Input mesh with holes (obj, off, ply, stl, gltf, glb; also .gz)")->required();
  c->add_option("-o,--output", a->output, "Output mesh; format from the extension");
  const ParameterInfo hole = cli_number("inpaint", "holes", ParameterType::Integer, {0, 2147483647});
  c->add_option_function<std::vector<std::string>>(
       "--holes",
       [a, hole](const std::vector<std::string>& texts) {
         for (const std::string& t : texts) {
           try {
             a->holes.push_back(static_cast<int>(parse_parameter(hole, t, "--holes")));
           } catch (const InvalidInput& e) {
             throw UsageError(e.what());
           }
         }
       },
       "Fill exactly these holes (indices from --list), e.g. 0,2,5")
      ->delimiter(',')
      ->type_name("I,J,...");
  c->add_flag("--list", a->list, "Print the holes (index, edges, diameter) and exit");
  c->add_option("--truth", a->truth, "Ground-truth mesh: print the filled region's distance errors");
  c->add_option("--report", a->report, "Write an HTML report: 3D viewer (new faces tinted), hole table, plots");
  a->parameters = std::make_unique<ParameterOptions<InpaintOptions>>(
      c, inpaint_parameters(), std::vector<std::pair<std::string, InpaintOptions>>{{"", InpaintOptions{}}},
      "(docs/inpainting.md)");
  c->add_flag("--json", a->json, "Print one JSON object instead of the summary");
  add_quiet_flag(c, a->quiet);
  c->add_flag("--ascii", a->ascii, "Write PLY/STL as ascii instead of binary");
  c->add_flag("--in-place", a->in_place, "Allow the output to overwrite the input file");
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
