// msmesh repair: fixes what can be fixed in a messy mesh and says what it did
// (docs/robustness.md).
#include <iostream>
#include <memory>

#include "command.h"
#include "data_notes.h"
#include "json.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "msmesh/repair.h"
#include "number_option.h"
#include "output_plan.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::string input, output;
  double weld = 0.0;
  bool keep_duplicates = false, keep_degenerate = false, keep_duplicate_faces = false, no_orient = false;
  bool split = false, remove_unreferenced = false;
  bool json = false, in_place = false, ascii = false, dry_run = false, quiet = false;
};

void run(const Args& a) {
  RepairOptions o;
  o.merge_duplicate_vertices = !a.keep_duplicates;
  o.weld_tolerance = a.weld;
  o.remove_degenerate_faces = !a.keep_degenerate;
  o.remove_duplicate_faces = !a.keep_duplicate_faces;
  o.orient = !a.no_orient;
  o.split_non_manifold = a.split;
  o.remove_unreferenced = a.remove_unreferenced;
  o.validate();
  if (a.output.empty() && !a.dry_run) throw InvalidInput("repair: give an output file (-o) or --dry-run");
  OutputPlan plan;  // every file of the run, checked before any work; outputs committed together
  plan.input(a.input).in_place(a.in_place).output(a.dry_run ? std::string() : a.output, OutputKind::Mesh, "-o");
  plan.begin();

  ReadNotes read_notes;
  Mesh mesh = read_mesh(a.input, read_notes);
  const Eigen::Index dropped = read_notes.dropped_degenerate;
  const RepairReport r = repair_mesh(mesh, o);
  if (r.faces_after == 0)
    throw InvalidInput(a.input + ": repair removed every face (all " + std::to_string(r.faces_before) +
                       " are degenerate or duplicates); nothing written");
  if (!a.dry_run) {
    WriteOptions wo;
    wo.binary = !a.ascii;
    write_mesh(a.output, mesh, wo);
  }
  plan.commit();
  const std::vector<std::string> notes =
      data_notes(a.input, read_notes, r.attribute_notes, mesh, a.dry_run ? std::string() : a.output);

  if (a.json) {
    Json j;
    j.add("input", a.input)
        .add("output", a.dry_run ? std::string() : a.output)
        .add("changed", r.changed() || dropped > 0);
    j.add("vertices_before", static_cast<long long>(r.vertices_before))
        .add("faces_before", static_cast<long long>(r.faces_before))
        .add("vertices_after", static_cast<long long>(r.vertices_after))
        .add("faces_after", static_cast<long long>(r.faces_after))
        .add("dropped_on_reading", static_cast<long long>(dropped))
        .add("merged_vertices", static_cast<long long>(r.merged_vertices))
        .add("degenerate_faces_removed", static_cast<long long>(r.degenerate_faces_removed))
        .add("zero_area_faces_removed", static_cast<long long>(r.zero_area_faces_removed))
        .add("duplicate_faces_removed", static_cast<long long>(r.duplicate_faces_removed))
        .add("flipped_faces", static_cast<long long>(r.flipped_faces))
        .add("split_vertices", static_cast<long long>(r.split_vertices))
        .add("unreferenced_vertices_removed", static_cast<long long>(r.unreferenced_vertices_removed))
        .add("components", static_cast<long long>(r.components))
        .add("non_orientable_components", static_cast<long long>(r.non_orientable_components))
        .add("non_manifold_edges", static_cast<long long>(r.non_manifold_edges))
        .add("non_manifold_vertices", static_cast<long long>(r.non_manifold_vertices))
        .add("unreferenced_vertices", static_cast<long long>(r.unreferenced_vertices));
    add_notes(j, notes);
    if (!a.quiet) std::cout << j.str() << "\n";
    return;
  }
  print_notes(notes);
  if (a.quiet) return;
  std::cout << "repaired " << a.input << " -> " << (a.dry_run ? std::string("(dry run, nothing written)") : a.output)
            << " (" << r.vertices_before << " -> " << r.vertices_after << " vertices, " << r.faces_before << " -> "
            << r.faces_after << " faces)\n";
  if (dropped > 0) std::cout << "  dropped on reading, faces repeating a vertex: " << dropped << "\n";
  const auto actions = r.actions();
  for (const std::string& line : actions) std::cout << "  " << line << "\n";
  if (actions.empty() && dropped == 0) std::cout << "  nothing to repair\n";
  std::cout << "  remaining: " << r.components << " components, " << r.non_manifold_edges << " non-manifold edges, "
            << r.non_manifold_vertices << " non-manifold vertices, " << r.unreferenced_vertices
            << " unreferenced vertices";
  if (r.non_orientable_components > 0) std::cout << ", " << r.non_orientable_components << " non-orientable components";
  std::cout << "\n";
  if (r.non_manifold_edges + r.non_manifold_vertices > 0 && !a.split)
    std::cout << "  (--split-non-manifold separates non-manifold parts)\n";
  if (r.unreferenced_vertices > 0 && !a.remove_unreferenced)
    std::cout << "  (--remove-unreferenced drops unreferenced vertices; this renumbers the vertices)\n";
}

const Registrar kRegistration("repair", 45, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c = app.add_subcommand(
      "repair",
      "Fix duplicate vertices, degenerate and duplicate faces, orientation (and optionally non-manifold parts and "
      "unreferenced vertices); vertex order is kept unless --remove-unreferenced");
  c->add_option("input", a->input, "Input mesh (obj, off, ply, stl, gltf, glb; also .gz)")->required();
  c->add_option("-o,--output", a->output, "Output mesh; format from the extension");
  add_number_option(c, "--weld", a->weld, repair_parameters()[0].info,
                    "Merge vertices closer than this (0: exact duplicates only)");
  c->add_flag("--keep-duplicate-vertices", a->keep_duplicates, "Do not merge duplicate vertices");
  c->add_flag("--keep-degenerate", a->keep_degenerate, "Do not remove zero-area faces");
  c->add_flag("--keep-duplicate-faces", a->keep_duplicate_faces, "Do not remove duplicate faces");
  c->add_flag("--no-orient", a->no_orient, "Do not orient faces consistently");
  c->add_flag("--split-non-manifold", a->split, "Give each fan around a non-manifold vertex or edge its own vertex");
  c->add_flag("--remove-unreferenced", a->remove_unreferenced,
              "Remove vertices no face refers to (renumbers the vertices)");
  c->add_flag("--dry-run", a->dry_run, "Only report what would be done; write nothing");
  c->add_flag("--json", a->json, "Print one JSON object instead of the summary");
  add_quiet_flag(c, a->quiet);
  c->add_flag("--ascii", a->ascii, "Write PLY/STL as ascii instead of binary");
  c->add_flag("--in-place", a->in_place, "Allow the output to overwrite the input file");
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
