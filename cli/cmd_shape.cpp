// msmesh shape: writes a built-in procedural test shape (shapes.h).
#include <iostream>
#include <memory>
#include <string>

#include "command.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "msmesh/shapes.h"
#include "number_option.h"
#include "output_plan.h"

namespace msmesh::cli {
namespace {

constexpr double kMaxShapeResolution = 1000;  // 6 million faces for a cube-like shape

struct Args {
  std::string name, output;
  int resolution = 16;
  bool list = false, ascii = false, quiet = false;
};

std::string patches(int count) { return std::to_string(count) + (count == 1 ? " smooth patch" : " smooth patches"); }

void print_names(std::ostream& os) {
  for (const std::string& name : shape_names()) os << name << " (" << patches(shape_patch_count(name)) << ")\n";
}

void run(const Args& a) {
  if (a.list) {
    print_names(std::cout);
    return;
  }
  if (a.name.empty()) throw InvalidInput("shape: give a NAME (msmesh shape --list shows them)");
  const int patch_count = shape_patch_count(a.name);  // an unknown name throws, listing the valid ones
  if (a.output.empty()) throw InvalidInput("shape: give the output file with -o OUT");
  OutputPlan plan;  // every file of the run, checked before any work; outputs committed together
  plan.output(a.output, OutputKind::Mesh, "-o");
  plan.begin();
  const Mesh mesh = make_shape(a.name, a.resolution);
  WriteOptions wo;
  wo.binary = !a.ascii;
  write_mesh(a.output, mesh, wo);
  plan.commit();
  if (a.quiet) return;
  std::cout << "shape: " << a.name << " at resolution " << a.resolution << " -> " << a.output << ": "
            << mesh.num_vertices() << " vertices, " << mesh.num_faces() << " faces, " << patches(patch_count) << "\n";
}

const Registrar kRegistration("shape", 20, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c =
      app.add_subcommand("shape", "Write a built-in procedural test mesh (msmesh shape --list shows the names)");
  c->add_option("name", a->name, "Shape name; --list shows them");
  c->add_option("-o,--output", a->output, "Output mesh; format from the extension (obj, off, ply, stl)");
  add_number_option(c, "-r,--resolution", a->resolution,
                    cli_number("shape", "resolution", ParameterType::Integer, {1, kMaxShapeResolution}),
                    "Resolution level (larger = finer; about resolution^2 faces per cube face)");
  c->add_flag("--list", a->list, "List the shape names with their numbers of smooth patches");
  c->add_flag("--ascii", a->ascii, "Write PLY/STL as ascii instead of binary");
  add_quiet_flag(c, a->quiet);
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
