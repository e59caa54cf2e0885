// msmesh noise: seeded Gaussian (white or correlated) or impulsive noise, σ in units of the mean edge length.
#include <iostream>
#include <memory>

#include "command.h"
#include "data_notes.h"
#include "msmesh/errors.h"
#include "msmesh/geometry.h"
#include "msmesh/io.h"
#include "msmesh/noise.h"
#include "number_option.h"
#include "output_plan.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::string input, output, direction = "normal";
  NoiseOptions options;
  bool in_place = false, ascii = false, quiet = false;
};

void run(const Args& a) {
  NoiseOptions o = a.options;
  o.direction = a.direction == "random" ? NoiseDirection::Random : NoiseDirection::Normal;
  o.validate();     // before any file is touched
  OutputPlan plan;  // every file of the run, checked before any work; outputs committed together
  plan.input(a.input).in_place(a.in_place).output(a.output, OutputKind::Mesh, "-o");
  plan.begin();

  ReadNotes read_notes;
  Mesh mesh = read_mesh(a.input, read_notes);
  const Eigen::MatrixXd V = add_noise(mesh.V, mesh.F, o);
  Eigen::Index moved = 0;
  for (Eigen::Index i = 0; i < V.rows(); ++i) moved += V.row(i) != mesh.V.row(i) ? 1 : 0;
  const double l = mean_edge_length(mesh.V, mesh.F);
  mesh.V = V;
  if (mesh.vertex_normals.size() > 0) mesh.vertex_normals = vertex_normals(mesh.V, mesh.F);  // match the result
  WriteOptions wo;
  wo.binary = !a.ascii;
  write_mesh(a.output, mesh, wo);
  plan.commit();
  print_notes(data_notes(a.input, read_notes, {}, mesh, a.output));

  if (a.quiet) return;
  std::cout << "noise: " << a.input << " -> " << a.output << ": "
            << (o.impulsive_fraction > 0 ? "impulsive (fraction " + fmt(o.impulsive_fraction) + ")"
                : o.correlation > 0      ? "Gaussian correlated over " + std::to_string(o.correlation) + " passes"
                                         : "Gaussian")
            << ", sigma " << fmt(o.sigma) << " x mean edge " << fmt(l) << " = " << fmt(o.sigma * l) << ", "
            << (o.direction == NoiseDirection::Normal ? "along vertex normals" : "random directions") << ", seed "
            << o.seed << ", " << moved << "/" << mesh.V.rows() << " vertices moved\n";
}

const Registrar kRegistration("noise", 30, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c = app.add_subcommand(
      "noise", "Add seeded noise as in the denoising literature (sigma in units of the mean edge length)");
  c->add_option("input", a->input, "Input mesh (obj, off, ply, stl, gltf, glb; also .gz)")->required();
  c->add_option("-o,--output", a->output, "Output mesh; format from the extension")->required();
  const ParameterTable<NoiseOptions>& table = noise_parameters();
  add_number_option(c, "--sigma", table[0], a->options, "Standard deviation, a multiple of the mean edge length");
  c->add_option("--direction", a->direction,
                "normal: along vertex normals; random: uniformly random directions (same RMS length)")
      ->check(CLI::IsMember({"normal", "random"}))
      ->capture_default_str();
  add_number_option(c, "--impulsive", table[1], a->options,
                    "Impulsive noise: displace only this fraction of the vertices (0: every vertex)");
  add_number_option(c, "--seed", table[2], a->options, "Random seed; the same seed gives the same mesh on any machine");
  add_number_option(c, "--correlation", table[3], a->options,
                    "Correlated noise like a depth camera's: average the displacements with their neighbours' this "
                    "many times, then scale back to sigma (0: white noise; not with --impulsive)");
  c->add_flag("--ascii", a->ascii, "Write PLY/STL as ascii instead of binary");
  add_quiet_flag(c, a->quiet);
  c->add_flag("--in-place", a->in_place, "Allow the output to overwrite the input file");
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
