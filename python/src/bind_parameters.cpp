// Bindings of the parameter tables (msmesh/parameters.h): what msmesh/__init__.py makes its
// keyword arguments, their checks and docstrings from, so that Python and the CLI name, check
// and default every parameter alike.
#include <string>

#include "bindings.h"
#include "msmesh/denoise.h"
#include "msmesh/errors.h"
#include "msmesh/inpaint.h"
#include "msmesh/parameters.h"
#include "msmesh/presets.h"
#include "msmesh/render.h"
#include "msmesh/segment.h"

namespace py = pybind11;

namespace msmesh::python {

namespace {

const char* type_name(ParameterType t) {
  switch (t) {
    case ParameterType::Real:
      return "float";
    case ParameterType::Integer:
      return "int";
    case ParameterType::Boolean:
      return "bool";
  }
  return "float";
}

/// The table as a list of dicts, with the value each of `defaults` (label -> options) gives.
template <class Options>
py::list table(const ParameterTable<Options>& t, const std::vector<std::pair<std::string, Options>>& defaults) {
  py::list out;
  for (const Parameter<Options>& p : t) {
    const ParameterInfo& i = p.info;
    py::dict d;
    d["name"] = i.key();
    d["option"] = "--" + i.name;
    d["symbol"] = i.symbol;
    d["unit"] = i.unit;
    d["type"] = type_name(i.type);
    d["range"] = i.describe_range();
    d["help"] = i.help;
    d["group"] = i.group;
    py::dict values;
    for (const auto& [label, o] : defaults) values[py::str(label)] = p.get(o);
    d["defaults"] = values;
    out.append(d);
  }
  return out;
}

/// Sets parameter `name` (Python spelling) on `o`, checked; the message names `name=`.
template <class Options>
void set(const ParameterTable<Options>& t, Options& o, const std::string& name, double value) {
  const Parameter<Options>* p = find_parameter(t, name);
  if (!p) throw InvalidInput("unknown parameter '" + name + "'");
  check_parameter(p->info, value, name);
  p->set(o, value);
}

/// Every parameter of `o` as a dict keyed by its Python name, with Python types.
template <class Options>
py::dict values(const ParameterTable<Options>& t, const Options& o) {
  py::dict d;
  for (const Parameter<Options>& p : t) {
    const double x = p.get(o);
    switch (p.info.type) {
      case ParameterType::Boolean:
        d[py::str(p.info.key())] = x != 0;
        break;
      case ParameterType::Integer:
        d[py::str(p.info.key())] = static_cast<long long>(x);
        break;
      case ParameterType::Real:
        d[py::str(p.info.key())] = x;
        break;
    }
  }
  return d;
}

template <class Options>
void bind_table(py::module_& m, const ParameterTable<Options>& t) {
  m.def(
      "set_parameter", [&t](Options& o, const std::string& name, double value) { set(t, o, name, value); },
      py::arg("options"), py::arg("name"), py::arg("value"));
  m.def(
      "parameters", [&t](const Options& o) { return values(t, o); }, py::arg("options"));
}

}  // namespace

void set_denoise_parameter(DenoiseOptions& o, const std::string& name, double value) {
  set(denoise_parameters(), o, name, value);
}

namespace {

py::list table_binding(const std::string& kind) {
  if (kind == "denoise") {
    std::vector<std::pair<std::string, DenoiseOptions>> d;
    for (const std::string& name : preset_names()) d.emplace_back(name, preset_options(name));
    return table(denoise_parameters(), d);
  }
  if (kind == "normal_filter") return table(normal_filter_parameters(), {{"", NormalFilterOptions{}}});
  if (kind == "vertex_update") return table(vertex_update_parameters(), {{"", VertexUpdateOptions{}}});
  if (kind == "inpaint") return table(inpaint_parameters(), {{"", InpaintOptions{}}});
  if (kind == "render") return table(render_parameters(), {{"", RenderOptions{}}});
  if (kind == "segment") {
    std::vector<std::pair<std::string, SegmentOptions>> d;
    for (const std::string& name : preset_names()) {
      d.emplace_back(name, SegmentOptions{});
      d.back().second.normals = preset_options(name).normals;
    }
    return table(segment_parameters(), d);
  }
  throw InvalidInput("unknown parameter table '" + kind +
                     "'; valid: denoise, normal_filter, vertex_update, inpaint, segment, render");
}

py::dict resolve_preset_binding(const std::string& name, const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                double strength) {
  const ResolvedPreset r =
      run_without_gil(py::none(), [&](const ProgressCallback&) { return resolve_preset(name, V, F, strength); });
  py::dict d;
  d["requested"] = r.requested;
  d["preset"] = r.preset;
  d["automatic"] = r.automatic;
  d["reason"] = r.reason();
  d["options"] = r.options;
  if (r.automatic) {
    d["sharp_fraction"] = r.choice.sharp_fraction;
    d["crease_line_fraction"] = r.choice.crease_line_fraction;
    d["steep_line_fraction"] = r.choice.steep_line_fraction;
    d["flat_fraction"] = r.choice.flat_fraction;
    d["noise_level"] = r.choice.noise_level;
    d["noise_sigma"] = r.noise.sigma;
    d["noise_sigma_rms"] = r.noise.sigma_rms;
    d["noise_outlier_fraction"] = r.noise.outlier_fraction;
    d["noise_sigma_noise"] = r.noise.sigma_noise;
    d["noise_detail"] = r.noise.detail;
    d["noise_across_ratio"] = r.noise.across_ratio;
    d["noise_level_used"] = r.sigma;
    d["noise_detail_as_noise"] = r.detail_as_noise;
    d["noise_detail_ease"] = r.detail_ease;
    d["noise_despiked"] = r.despiked;
    d["noise_sigma_rms_despiked"] = r.noise_despiked.sigma_rms;
    d["quadric_excess"] = r.quadric_excess;
    d["featureless_limit"] = r.featureless_limit;
    d["featureless"] = r.featureless;
    d["second_round"] = r.second_round;
  }
  d["strength"] = r.strength;
  return d;
}

}  // namespace

void bind_parameters(py::module_& m) {
  m.def("parameter_table", &table_binding, py::arg("kind"));
  m.def("default_preset", &default_preset);
  m.def("resolve_preset", &resolve_preset_binding, py::arg("name"), py::arg("V"), py::arg("F"),
        py::arg("strength") = 1.0);
  m.attr("MIN_STRENGTH") = kMinStrength;
  m.attr("MAX_STRENGTH") = kMaxStrength;
  bind_table(m, denoise_parameters());
  bind_table(m, normal_filter_parameters());
  bind_table(m, vertex_update_parameters());
  bind_table(m, inpaint_parameters());
  bind_table(m, segment_parameters());
  bind_table(m, render_parameters());
}

}  // namespace msmesh::python
