// msmesh params: the parameters a run would use — for a preset, or for a mesh with --preset auto
// (and why auto chose what it chose) — with their symbols, units, ranges and meaning.
#include <iostream>
#include <memory>

#include "command.h"
#include "json.h"
#include "msmesh/inpaint.h"
#include "msmesh/io.h"
#include "msmesh/parameters.h"
#include "msmesh/presets.h"
#include "msmesh/segment.h"
#include "parameter_options.h"
#include "usage_error.h"

namespace msmesh::cli {
namespace {

struct Args {
  std::string mesh, preset, command = "denoise";  // preset "": the command's default
  bool json = false, quiet = false;
};

/// `s` padded with spaces to `width` characters (UTF-8 code points, as the symbols are).
std::string pad(const std::string& s, std::size_t width) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return s + std::string(n < width ? width - n : 1, ' ');
}

template <class Options>
void print_table(const ParameterTable<Options>& table, const Options& o) {
  std::string group;
  for (const Parameter<Options>& p : table) {
    const ParameterInfo& i = p.info;
    if (i.group != group) {
      group = i.group;
      std::cout << "  " << group << ":\n";
    }
    std::cout << "    " << pad("--" + i.name, 27) << pad(i.symbol, 4) << pad(i.format(p.get(o)), 12) << i.help << " ("
              << i.describe_range() << (i.unit.empty() ? "" : " " + i.unit) << ")\n";
  }
}

template <class Options>
void show(const Args& a, const ParameterTable<Options>& table, const Options& o, const std::string& preset,
          const std::string& why) {
  if (a.json) {
    Json j;
    j.add("command", a.command);
    if (!a.mesh.empty()) j.add("mesh", a.mesh);
    if (!preset.empty()) j.add("preset", preset).add("preset_reason", why);
    j.add("parameters", parameters_json(table, o));
    std::cout << j.str() << "\n";
    return;
  }
  if (a.quiet) return;
  std::cout << "msmesh " << a.command;
  if (!a.mesh.empty()) std::cout << " " << a.mesh;
  if (!preset.empty()) std::cout << ": preset " << preset << ", " << why;
  std::cout << "\n";
  print_table(table, o);
}

void run(Args a) {
  if (a.command == "inpaint") {
    if (!a.preset.empty()) throw UsageError("params: inpaint has no presets (drop --preset)");
    show(a, inpaint_parameters(), InpaintOptions{}, "", "");
    return;
  }
  if (a.command == "segment") {
    if (a.preset.empty()) a.preset = "cad";  // as `msmesh segment`
    if (a.preset == "auto") throw UsageError("params: segment's presets are cad and smooth (no auto)");
  }
  if (a.preset.empty()) a.preset = default_preset();
  if (a.preset == "auto" && a.mesh.empty())
    throw UsageError("params: --preset auto is chosen from a mesh: give MESH, or --preset " +
                     std::string("cad or smooth"));
  ResolvedPreset r;
  if (a.mesh.empty()) {
    r.requested = r.preset = a.preset;
    r.options = preset_options(a.preset);
  } else {
    const Mesh mesh = read_mesh(a.mesh);
    r = resolve_preset(a.preset, mesh.V, mesh.F);
  }
  if (a.command == "segment") {
    SegmentOptions o;
    o.normals = r.options.normals;
    show(a, segment_parameters(), o, r.preset, r.reason());
    return;
  }
  show(a, denoise_parameters(), r.options, r.preset, r.reason());
}

const Registrar kRegistration("params", 55, [](CLI::App& app) {
  auto a = std::make_shared<Args>();
  CLI::App* c = app.add_subcommand("params", "Print the parameters a preset (or, for a mesh, preset auto) gives");
  c->add_option("mesh", a->mesh, "Mesh to resolve --preset auto for (obj, off, ply, stl, gltf, glb; also .gz)");
  std::vector<std::string> presets = preset_names();
  presets.insert(presets.begin(), "auto");
  c->add_option("--preset", a->preset,
                "auto (needs MESH; the default of denoise), cad (the default of segment) or smooth")
      ->check(CLI::IsMember(presets));
  c->add_option("--command", a->command, "Whose parameters: denoise, segment or inpaint")
      ->check(CLI::IsMember({"denoise", "segment", "inpaint"}))
      ->capture_default_str();
  c->add_flag("--json", a->json, "Print one JSON object instead of the table");
  add_quiet_flag(c, a->quiet);
  c->callback([a]() { run(*a); });
});

}  // namespace
}  // namespace msmesh::cli
