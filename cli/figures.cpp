#include "figures.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "msmesh/png.h"
#include "msmesh/segment.h"
#include "msmesh/text.h"
#include "msmesh/topology.h"
#include "number_option.h"
#include "usage_error.h"

namespace msmesh::cli {

void write_png(const std::string& path, const Image& image) {
  const std::vector<std::uint8_t> bytes = encode_png(image);
  write_file_atomically(path, [&](std::ostream& os) {
    os.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  });
}

std::pair<int, int> parse_size(const std::string& text) {
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos)
    throw InvalidInput("--size = '" + text + "' is not WxH with W and H in [1, 16384] (e.g. 800x600)");
  const ParameterTable<RenderOptions>& t = render_parameters();
  const double w = parse_parameter(t[0].info, text.substr(0, x), "--size width");
  const double h = parse_parameter(t[1].info, text.substr(x + 1), "--size height");
  return {static_cast<int>(w), static_cast<int>(h)};
}

namespace {
/// `check(text)` run while the command line is parsed; its InvalidInput becomes a UsageError.
CLI::Option* checked(CLI::Option* o, std::function<void(const std::string&)> check) {
  return o->check(CLI::Validator(
      [check = std::move(check)](std::string& text) {
        try {
          check(text);
        } catch (const InvalidInput& e) {
          throw UsageError(e.what());
        }
        return std::string();
      },
      ""));
}
}  // namespace

CLI::Option* add_size_option(CLI::App* c, std::string& size, const std::string& help) {
  return checked(c->add_option("--size", size, help)->capture_default_str(),
                 [](const std::string& text) { parse_size(text); });
}

CLI::Option* add_feature_edges_option(CLI::App* c, double& degrees, const std::string& help) {
  return add_number_option(
      c, "--feature-edges", degrees,
      cli_number(c->get_name(), "feature-edges", ParameterType::Real, {0, 180, false, true}, "degrees"), help);
}

CLI::Option* add_supersample_option(CLI::App* c, int& supersample) {
  return add_number_option(c, "--supersample", supersample, render_parameters()[2].info,
                           "Samples per pixel along each axis (anti-aliasing)");
}

CLI::Option* add_error_max_option(CLI::App* c, double& degrees, const std::string& help) {
  return add_number_option(c, "--error-max", degrees,
                           cli_number(c->get_name(), "error-max", ParameterType::Real, {0, 180}, "degrees"), help);
}

}  // namespace msmesh::cli
