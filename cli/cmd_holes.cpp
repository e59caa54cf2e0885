// msmesh holes: punch holes (geodesic disks) into a mesh, for inpainting tests and benchmarks.
#include <iostream>
#include <memory>
#include <sstream>

#include "command.h"
#include "data_notes.h"
#include "json.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "msmesh/mesh_attributes.h"
#include "msmesh/punch_holes.h"
#include "number_option.h"
#include "output_plan.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::string input, output, map;
  int count = 3;
  double radius = 3;
  long long seed = 1;
  bool on_features = false, json = false, ascii = false, in_place = false, quiet = false;
};

void run(const Args& a) {
  if (a.seed < 0) throw InvalidInput("holes: --seed must be >= 0");
  OutputPlan plan;  // every file of the run, checked before any work; outputs committed together
  plan.input(a.input).in_place(a.in_place);
  plan.output(a.output, OutputKind::Mesh, "-o").output(a.map, OutputKind::Text, "--map");
  plan.begin();
  ReadNotes read_notes;
  const Mesh mesh = read_mesh(a.input, read_notes);
  const PunchResult r =
      punch_holes(mesh.V, mesh.F, a.count, a.radius, static_cast<std::uint64_t>(a.seed), a.on_features);
  if (r.F.rows() == 0)
    throw InvalidInput("holes: the holes (radius " + fmt(a.radius) +
                       " mean edge lengths) would remove every face of '" + a.input +
                       "'; nothing written (use a smaller --radius or --count)");
  Mesh out;
  out.V = r.V;
  out.F = r.F;
  const std::vector<std::string> carried = carry_attributes(mesh, out, r.vertex_map, r.face_map);
  WriteOptions wo;
  wo.binary = !a.ascii;
  write_mesh(a.output, out, wo);
  const std::vector<std::string> notes = data_notes(a.input, read_notes, carried, out, a.output);
  if (!a.map.empty()) {
    std::ostringstream os;
    os << "# input vertex index of each output vertex (one per line)\n";
    for (Eigen::Index i = 0; i < r.vertex_map.size(); ++i) os << r.vertex_map(i) << "\n";
    write_text_file(a.map, os.str());
  }
  plan.commit();
  if (a.json) {
    Json j;
    j.add("input", a.input)
        .add("output", a.output)
        .add("requested", a.count)
        .add("punched", r.punched)
        .add("radius", a.radius)
        .add("seed", a.seed)
        .add("on_features", a.on_features)
        .add("removed_faces", static_cast<long long>(mesh.F.rows() - r.F.rows()))
        .add("removed_vertices", static_cast<long long>(mesh.V.rows() - r.V.rows()));
    std::vector<double> centers(r.centers.begin(), r.centers.end());
    j.add("centers", centers);
    add_notes(j, notes);
    std::cout << j.str() << "\n";
    return;
  }
  print_notes(notes);
  if (a.quiet) return;
  std::cout << "punched " << r.punched << " of " << a.count << " holes (radius " << fmt(a.radius)
            << " mean edge lengths" << (a.on_features ? ", on sharp features" : "") << ", seed " << a.seed
            << "): " << a.input << " -> " << a.output << "\n";
  std::cout << "  removed " << (mesh.F.rows() - r.F.rows()) << " faces and " << (mesh.V.rows() - r.V.rows())
            << " vertices";
  if (!a.map.empty()) std::cout << "; vertex index map written to " << a.map;
  std::cout << "\n";
  if (r.punched < a.count)
    std::cout << "  note: no room for more holes (they are kept apart from each other and from boundaries)\n";
}

const Registrar kRegistration("holes", 85, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c = app.add_subcommand("holes", "Punch holes (geodesic disks) into a mesh, for inpainting tests");
  c->add_option("input", a->input, "Input mesh (obj, off, ply, stl, gltf, glb; also .gz)")->required();
  c->add_option("-o,--output", a->output, "Output mesh with holes")->required();
  using T = ParameterType;
  add_number_option(c, "--count", a->count, cli_number("holes", "count", T::Integer, {1, 100000}), "Number of holes");
  add_number_option(c, "--radius", a->radius,
                    cli_number("holes", "radius", T::Real, {0, 1e6, true, false}, "mean edge lengths"),
                    "Hole radius (geodesic, along edges)");
  add_number_option(c, "--seed", a->seed, cli_number("holes", "seed", T::Integer, {0, kLargestExactInteger}),
                    "Random seed (same seed, same holes)");
  c->add_flag("--on-features", a->on_features, "Centre the holes on sharp edges and corners (dihedral > 60 deg)");
  c->add_option("--map", a->map, "Write the input index of each output vertex to this text file (-: standard output)");
  c->add_flag("--json", a->json, "Print one JSON object instead of the summary");
  add_quiet_flag(c, a->quiet);
  c->add_flag("--ascii", a->ascii, "Write PLY/STL as ascii instead of binary");
  c->add_flag("--in-place", a->in_place, "Allow the output to overwrite the input file");
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
