// The command-line options of a parameter table (msmesh/parameters.h): one `--name VALUE` per
// numeric parameter, `--name` / `--no-name` per boolean one, each with its symbol, range, unit,
// help and the real default(s) in --help, and applied with the table's checks (a message that
// names the option as typed; usage error, exit 2).
#pragma once
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "json.h"
#include "msmesh/parameters.h"
#include "usage_error.h"

namespace msmesh::cli {

/// "α > 0, fidelity to the input normals (eq. 15) [default: cad 2.5, smooth 2]".
template <class Options>
std::string parameter_help(const Parameter<Options>& p, const std::vector<std::pair<std::string, Options>>& defaults) {
  const ParameterInfo& i = p.info;
  std::string h = i.symbol.empty() ? "" : i.symbol + ": ";
  h += i.help;
  if (i.type != ParameterType::Boolean) h += "; " + i.describe_range();
  if (!i.unit.empty()) h += " " + i.unit;
  if (!defaults.empty()) {
    const bool same = std::all_of(defaults.begin(), defaults.end(),
                                  [&](const auto& d) { return p.get(d.second) == p.get(defaults[0].second); });
    std::string d;
    for (const auto& [label, o] : defaults) {
      if (!d.empty()) d += ", ";
      d += (label.empty() || same ? "" : label + " ") + i.format(p.get(o));
      if (same) break;
    }
    h += " [default: " + d + "]";
  }
  return h;
}

template <class Options>
class ParameterOptions {
 public:
  /// Adds the options of `table` to `cmd`, in help groups named after the parameters' groups
  /// followed by `group_note` ("Normal filtering (override the preset)"). `defaults` are labelled
  /// option sets whose values --help shows (e.g. {"cad", ...}, {"smooth", ...}; one unlabelled
  /// set for a single default). `only`: names to add (empty: all).
  ParameterOptions(CLI::App* cmd, const ParameterTable<Options>& table,
                   const std::vector<std::pair<std::string, Options>>& defaults, const std::string& group_note,
                   const std::vector<std::string>& only = {}) {
    for (const Parameter<Options>& p : table) {
      if (!only.empty() && std::find(only.begin(), only.end(), p.info.name) == only.end()) continue;
      std::string group = p.info.group;
      if (!group.empty()) group[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(group[0])));
      if (!group_note.empty()) group += " " + group_note;
      auto e = std::make_unique<Entry>();
      e->p = &p;
      const std::string help = parameter_help(p, defaults);
      if (p.info.type == ParameterType::Boolean) {
        e->on = cmd->add_flag("--" + p.info.name)->description(help)->group(group);
        e->off = cmd->add_flag("--no-" + p.info.name)->description("the opposite of --" + p.info.name)->group(group);
      } else {
        e->on = cmd->add_option("--" + p.info.name, e->text, help)
                    ->group(group)
                    ->type_name(p.info.type == ParameterType::Integer ? "INT" : "NUM");
      }
      entries_.push_back(std::move(e));
    }
  }

  /// True when the user gave the option (either spelling of a boolean).
  bool given(const std::string& name) const {
    for (const auto& e : entries_)
      if (e->p->info.name == name) return e->on->count() > 0 || (e->off && e->off->count() > 0);
    return false;
  }

  /// Checks every given value (as apply() does) without setting anything: called before any
  /// work, when the options they will be applied to are not known yet.
  void check() const {
    Options scratch;
    apply(scratch);
  }

  /// Sets every given option on `o`. Throws UsageError naming the option for a value that is
  /// not a number, out of range, or a boolean given both ways.
  void apply(Options& o) const {
    for (const auto& e : entries_) {
      const ParameterInfo& i = e->p->info;
      if (i.type == ParameterType::Boolean) {
        // --name=VALUE is strict as every number: 0/1, true/false, yes/no, on/off.
        bool on = false, off = false;
        for (const CLI::Option* flag : {e->on, e->off})
          for (const std::string& text : flag->results()) {
            double x = 0;
            try {
              x = parse_parameter(i, text.empty() ? "1" : text, flag->get_name());
            } catch (const InvalidInput& bad) {
              throw UsageError(bad.what());
            }
            ((x != 0) == (flag == e->on) ? on : off) = true;
          }
        if (on && off) throw UsageError("--" + i.name + " and --no-" + i.name + " contradict each other");
        if (on || off) e->p->set(o, on ? 1.0 : 0.0);
        continue;
      }
      if (e->on->count() == 0) continue;
      try {
        e->p->set(o, parse_parameter(i, e->text, "--" + i.name));
      } catch (const InvalidInput& x) {
        throw UsageError(x.what());
      }
    }
  }

 private:
  struct Entry {
    const Parameter<Options>* p = nullptr;
    std::string text;  // the value as typed
    CLI::Option* on = nullptr;
    CLI::Option* off = nullptr;  // --no-NAME of a boolean
  };
  std::vector<std::unique_ptr<Entry>> entries_;  // stable addresses: CLI11 writes into them
};

/// Every parameter of `options` as a JSON object, keyed as in Python ("normal_iterations").
template <class Options>
Json parameters_json(const ParameterTable<Options>& table, const Options& options) {
  Json j;
  for (const Parameter<Options>& p : table) {
    const double x = p.get(options);
    if (p.info.type == ParameterType::Boolean)
      j.add(p.info.key(), x != 0);
    else if (p.info.type == ParameterType::Integer)
      j.add(p.info.key(), static_cast<long long>(x));
    else
      j.add(p.info.key(), x);
  }
  return j;
}

}  // namespace msmesh::cli
