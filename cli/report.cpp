#include "report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "field_output.h"
#include "json.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "msmesh/metrics.h"
#include "msmesh/parameters.h"
#include "msmesh/png.h"
#include "msmesh/text.h"

// The viewer bundle, embedded at build time (see report/README.md): CMake reads
// report/dist/viewer.js into a generated header. Without it (a build system that did not run
// that step) the script is read from the source tree at run time.
#if __has_include("msmesh_report_viewer_js.h")
#include "msmesh_report_viewer_js.h"
#define MSMESH_HAVE_EMBEDDED_VIEWER 1
#endif

namespace msmesh::cli {

namespace {
inline std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}
}  // namespace

// =======================================================================================
// Figures
// =======================================================================================

void write_png(const std::string& path, const Image& image) {
  const std::vector<std::uint8_t> bytes = encode_png(image);
  write_file_atomically(path, [&](std::ostream& os) {
    os.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  });
}

std::pair<int, int> parse_size(const std::string& text) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  std::istringstream is(text);
  if (!(is >> w >> x >> h) || (x != 'x' && x != 'X') || (is >> extra) || w < 1 || h < 1 || w > 16384 || h > 16384)
    throw InvalidInput("size '" + text + "' is not WxH with W and H in [1, 16384] (e.g. 800x600)");
  return {w, h};
}

Eigen::VectorXd read_edge_field(const std::string& path, const Topology& topo) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot open the edge field file '" + path + "'");
  std::unordered_map<std::uint64_t, Eigen::Index> index;
  index.reserve(static_cast<size_t>(topo.num_edges()) * 2);
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e) index[edge_key(topo.edges(e, 0), topo.edges(e, 1))] = e;
  Eigen::VectorXd v = Eigen::VectorXd::Constant(topo.num_edges(), std::numeric_limits<double>::quiet_NaN());
  std::string line;
  long line_no = 0;
  // PLY (as written by --save-field x.ply): skip the header and the vertex lines.
  long skip = 0, edges_left = -1;
  if (in.peek() == 'p') {
    long vertices = 0;
    bool ended = false;
    while (std::getline(in, line)) {
      ++line_no;
      std::istringstream ls(line);
      std::string a, b;
      long n = 0;
      ls >> a;
      if (a == "format" && ls >> b && b != "ascii")
        throw IoError("'" + path + "': only ascii PLY edge fields are read (msmesh denoise --save-field writes them)");
      if (a == "element" && ls >> b >> n) {
        if (b == "vertex") vertices = n;
        else if (b == "edge") edges_left = n;
      }
      if (a == "end_header") {
        ended = true;
        break;
      }
    }
    if (!ended || edges_left < 0) throw IoError("'" + path + "' is not a PLY file with an edge element");
    skip = vertices;
  }
  Eigen::Index seen = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (skip > 0) {
      --skip;
      continue;
    }
    if (edges_left == 0) break;
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream ls(line);
    long long i = 0, j = 0;
    double value = 0;
    if (!(ls >> i)) continue;  // blank or comment line
    if (!(ls >> j >> value) || !std::isfinite(value))
      throw IoError("'" + path + "' line " + std::to_string(line_no) + ": expected 'i j v' with a finite v");
    if (edges_left > 0) --edges_left;
    const auto it = (i < 0 || j < 0 || i > INT32_MAX || j > INT32_MAX) ? index.end()
                                                                        : index.find(edge_key(int(i), int(j)));
    if (it == index.end())
      throw InvalidInput("'" + path + "' line " + std::to_string(line_no) + ": (" + std::to_string(i) + ", " +
                         std::to_string(j) + ") is not an edge of the mesh (was the field written for another mesh?)");
    if (std::isnan(v(it->second))) ++seen;
    v(it->second) = value;
  }
  if (seen != topo.num_edges())
    throw InvalidInput("'" + path + "' gives the field on " + std::to_string(seen) + " of the mesh's " +
                       std::to_string(topo.num_edges()) + " edges (was it written for another mesh?)");
  return v;
}

Eigen::VectorXi read_face_labels(const std::string& path, Eigen::Index faces) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot open the labels file '" + path + "'");
  std::vector<int> labels;
  std::string line;
  long line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream ls(line);
    long long x = 0;
    while (ls >> x) {
      if (x < 0 || x > INT32_MAX)
        throw IoError("'" + path + "' line " + std::to_string(line_no) + ": label " + std::to_string(x) +
                      " is not in [0, 2^31)");
      labels.push_back(static_cast<int>(x));
    }
    if (!ls.eof()) throw IoError("'" + path + "' line " + std::to_string(line_no) + ": not an integer label");
  }
  if (static_cast<Eigen::Index>(labels.size()) != faces)
    throw IoError("'" + path + "' has " + std::to_string(labels.size()) + " labels; the mesh has " +
                  std::to_string(faces) + " faces");
  return Eigen::Map<Eigen::VectorXi>(labels.data(), static_cast<Eigen::Index>(labels.size()));
}

double error_scale(const Eigen::VectorXd& values) {
  std::vector<double> x;
  for (Eigen::Index i = 0; i < values.size(); ++i)
    if (std::isfinite(values(i))) x.push_back(values(i));
  if (x.empty()) return 1;
  const size_t k = std::min(x.size() - 1, static_cast<size_t>(std::floor(0.98 * double(x.size()))));
  std::nth_element(x.begin(), x.begin() + static_cast<long>(k), x.end());
  const double p = std::max(x[k], 1e-3);
  const double decade = std::pow(10.0, std::floor(std::log10(p)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= p * (1 - 1e-12)) return m * decade;
  return 10 * decade;
}

Coloring error_coloring(const Eigen::VectorXd& angle_deg, double max_deg) {
  Coloring c;
  const double top = max_deg > 0 ? max_deg : error_scale(angle_deg);
  c.style.face_colors.resize(angle_deg.size(), 3);
  for (Eigen::Index f = 0; f < angle_deg.size(); ++f)
    c.style.face_colors.row(f) = heat_color(angle_deg(f) / top).transpose();
  c.has_bar = true;
  c.bar.map = heat_color;
  c.bar.min = 0;
  c.bar.max = top;
  c.bar.ticks = 5;
  c.bar.title = "angle error (deg)";
  c.bar.max_is_clamped = angle_deg.size() > 0 && angle_deg.maxCoeff() > top;
  c.summary = "angle error, colour scale 0-" + format_tick(top) + " deg (max " +
              format_tick(angle_deg.size() ? angle_deg.maxCoeff() : 0.0) + ")";
  return c;
}

Coloring field_coloring(const Eigen::MatrixXi& F, Eigen::Index num_vertices, const Eigen::VectorXd& v) {
  const Topology topo = build_topology(F, num_vertices);
  if (v.size() != topo.num_edges())
    throw InvalidInput("edge field has " + std::to_string(v.size()) + " values; the mesh has " +
                       std::to_string(topo.num_edges()) + " edges");
  const Eigen::VectorXd vn = normalize_edge_field(v);
  // Smooth edges (normalised v near 1) would be drawn nearly in the face colour: leave them out.
  constexpr double kDrawBelow = 0.9;
  std::vector<Eigen::Index> drawn;
  for (Eigen::Index e = 0; e < vn.size(); ++e)
    if (vn(e) < kDrawBelow) drawn.push_back(e);
  Coloring c;
  c.style.lines.resize(static_cast<Eigen::Index>(drawn.size()), 2);
  c.style.line_colors.resize(static_cast<Eigen::Index>(drawn.size()), 3);
  for (size_t k = 0; k < drawn.size(); ++k) {
    c.style.lines.row(k) = topo.edges.row(drawn[k]);
    c.style.line_colors.row(k) = field_color(vn(drawn[k])).transpose();
  }
  c.has_bar = true;
  c.bar.map = field_color;
  c.bar.min = v.size() ? v.minCoeff() : 0.0;
  c.bar.max = v.size() ? v.maxCoeff() : 1.0;
  c.bar.ticks = 3;
  c.bar.title = "edge field v";
  c.summary = "edge field v in [" + format_tick(c.bar.min) + ", " + format_tick(c.bar.max) + "], " +
              std::to_string(drawn.size()) + " edges drawn (normalised v < 0.9)";
  return c;
}

Coloring label_coloring(const Eigen::MatrixXi& F, Eigen::Index num_vertices, const Eigen::VectorXi& labels) {
  if (labels.size() != F.rows())
    throw InvalidInput("got " + std::to_string(labels.size()) + " labels for " + std::to_string(F.rows()) + " faces");
  const Topology topo = build_topology(F, num_vertices);
  Coloring c;
  c.style.face_colors.resize(F.rows(), 3);
  for (Eigen::Index f = 0; f < F.rows(); ++f) c.style.face_colors.row(f) = label_color(labels(f)).transpose();
  std::vector<Eigen::Index> cut;
  for (Eigen::Index e = 0; e < topo.num_edges(); ++e)
    if (topo.edge_face_count(e) >= 2 && labels(topo.edge_faces(e, 0)) != labels(topo.edge_faces(e, 1)))
      cut.push_back(e);
  c.style.lines.resize(static_cast<Eigen::Index>(cut.size()), 2);
  for (size_t k = 0; k < cut.size(); ++k) c.style.lines.row(k) = topo.edges.row(cut[k]);
  c.style.line_colors = Eigen::RowVector3d(0.15, 0.15, 0.15);
  const int count = labels.size() ? labels.maxCoeff() + 1 : 0;
  c.summary = std::to_string(count) + " labels, " + std::to_string(cut.size()) + " boundary edges drawn";
  return c;
}

Image add_color_bar(const Image& picture, const Coloring& c) {
  if (!c.has_bar) return picture;
  const int scale = picture.width >= 700 ? 2 : 1;
  const int pad = 8 * scale, h = 2 * text_height(scale) + 8 * scale;
  Image strip(picture.width, h + 2 * pad);
  const int w = std::min(picture.width - 2 * pad, 560 * scale);
  draw_color_bar(strip, (picture.width - w) / 2, pad, w, h, c.bar, scale);
  return vstack({picture, strip});
}

// =======================================================================================
// HTML report
// =======================================================================================

namespace {

std::string html_escape(const std::string& s) {
  std::string o;
  o.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      case '\'': o += "&#39;"; break;
      default: o += c;
    }
  }
  return o;
}

std::string base64(const std::vector<std::uint8_t>& b) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string o;
  o.reserve((b.size() + 2) / 3 * 4);
  for (size_t i = 0; i < b.size(); i += 3) {
    const std::uint32_t n = (std::uint32_t(b[i]) << 16) | (i + 1 < b.size() ? std::uint32_t(b[i + 1]) << 8 : 0) |
                            (i + 2 < b.size() ? std::uint32_t(b[i + 2]) : 0);
    o += table[(n >> 18) & 63];
    o += table[(n >> 12) & 63];
    o += i + 1 < b.size() ? table[(n >> 6) & 63] : '=';
    o += i + 2 < b.size() ? table[n & 63] : '=';
  }
  return o;
}

// Little-endian 32-bit words, whatever the host's byte order (typed arrays in the browser are
// little-endian on every platform that matters; the viewer reads them with DataView).
void put_le32(std::vector<std::uint8_t>& out, std::uint32_t w) {
  for (int s = 0; s < 32; s += 8) out.push_back(static_cast<std::uint8_t>((w >> s) & 0xFF));
}
std::uint32_t float_bits(float f) {
  std::uint32_t w;
  std::memcpy(&w, &f, sizeof w);
  return w;
}

std::string floats_b64(const double* x, size_t n) {
  std::vector<std::uint8_t> b;
  b.reserve(n * 4);
  for (size_t i = 0; i < n; ++i) put_le32(b, float_bits(static_cast<float>(x[i])));
  return base64(b);
}
template <class Int>
std::string ints_b64(const Int* x, size_t n) {
  std::vector<std::uint8_t> b;
  b.reserve(n * 4);
  for (size_t i = 0; i < n; ++i) put_le32(b, static_cast<std::uint32_t>(x[i]));
  return base64(b);
}

std::string viewer_data_json(const ReportData& d) {
  // Error colour scale: that of the mesh shown first (usually the result), so its errors are
  // readable; the others (a noisy input) saturate at the top colour. The viewer lets the
  // reader change it.
  double error_max = 0;
  {
    std::vector<double> all;
    const bool first_has = d.initial_mesh >= 0 && d.initial_mesh < static_cast<int>(d.meshes.size()) &&
                           d.meshes[d.initial_mesh].face_error_deg.size() > 0;
    for (size_t i = 0; i < d.meshes.size(); ++i) {
      if (first_has && static_cast<int>(i) != d.initial_mesh) continue;
      const auto& e = d.meshes[i].face_error_deg;
      all.insert(all.end(), e.data(), e.data() + e.size());
    }
    if (!all.empty()) error_max = error_scale(Eigen::Map<Eigen::VectorXd>(all.data(), static_cast<Eigen::Index>(all.size())));
  }
  std::vector<Json> meshes;
  for (const auto& m : d.meshes) {
    validate_mesh(m.V, m.F, "report mesh '" + m.name + "'");
    Json j;
    j.add("name", m.name).add("vertices", static_cast<long long>(m.V.rows()))
        .add("faces", static_cast<long long>(m.F.rows()));
    const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> Vr = m.V;
    const Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor> Fr = m.F;
    j.add("positions", floats_b64(Vr.data(), static_cast<size_t>(Vr.size())));
    // Meshes with the faces of an earlier one (input, result, truth of a denoising) share its
    // index array.
    int same = -1;
    for (size_t k = 0; k < meshes.size() && same < 0; ++k)
      if (d.meshes[k].F.rows() == m.F.rows() && d.meshes[k].F == m.F) same = static_cast<int>(k);
    if (same >= 0) j.add("indices_of", same);
    else j.add("indices", ints_b64(Fr.data(), static_cast<size_t>(Fr.size())));
    if (m.face_error_deg.size()) {
      if (m.face_error_deg.size() != m.F.rows()) throw InvalidInput("report mesh '" + m.name + "': face_error_deg size");
      j.add("error", floats_b64(m.face_error_deg.data(), static_cast<size_t>(m.face_error_deg.size())));
      j.add("error_max_of_mesh", m.face_error_deg.maxCoeff());
    }
    if (m.edge_field.size()) {
      const Topology topo = build_topology(m.F, m.V.rows());
      if (m.edge_field.size() != topo.num_edges()) throw InvalidInput("report mesh '" + m.name + "': edge_field size");
      const Eigen::Matrix<int, Eigen::Dynamic, 2, Eigen::RowMajor> Er = topo.edges;
      j.add("edges", ints_b64(Er.data(), static_cast<size_t>(Er.size())));
      j.add("field", floats_b64(m.edge_field.data(), static_cast<size_t>(m.edge_field.size())));
      j.add("field_min", m.edge_field.minCoeff()).add("field_max", m.edge_field.maxCoeff());
    }
    if (m.face_labels.size()) {
      if (m.face_labels.size() != m.F.rows()) throw InvalidInput("report mesh '" + m.name + "': face_labels size");
      j.add("labels", ints_b64(m.face_labels.data(), static_cast<size_t>(m.face_labels.size())));
    }
    if (!m.highlighted_faces.empty()) {
      if (static_cast<Eigen::Index>(m.highlighted_faces.size()) != m.F.rows())
        throw InvalidInput("report mesh '" + m.name + "': highlighted_faces size");
      std::vector<std::uint32_t> flags(m.highlighted_faces.begin(), m.highlighted_faces.end());
      j.add("highlight", ints_b64(flags.data(), flags.size()));
    }
    meshes.push_back(j);
  }
  // Label colours from the library, so the viewer matches the PNGs and segment's .ply.
  int max_label = -1;
  for (const auto& m : d.meshes)
    if (m.face_labels.size()) max_label = std::max(max_label, m.face_labels.maxCoeff());
  std::vector<double> label_rgb;
  for (int l = 0; l <= max_label; ++l) {
    const Eigen::Vector3d c = label_color(l);
    label_rgb.insert(label_rgb.end(), {c(0), c(1), c(2)});
  }
  Json j;
  j.add("meshes", meshes).add("initial_mesh", d.initial_mesh).add("initial_color", d.initial_color)
      .add("error_max", error_max).add("label_colors", label_rgb);
  std::string s = j.str();
  // Inside <script>, "</" could close the element: JSON allows "<\/" for it.
  for (size_t p = 0; (p = s.find("</", p)) != std::string::npos; p += 3) s.replace(p, 2, "<\\/");
  return s;
}

// ---- inline SVG plots ------------------------------------------------------------------

std::string svg_num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", x);
  return b;
}

std::string plot_svg(const ReportPlot& p) {
  const double W = 520, H = 290, ml = 70, mr = 16, mt = 30, mb = 64;
  const double pw = W - ml - mr, ph = H - mt - mb;
  static const char* palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
  // Data range.
  size_t n_max = 0;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  // A log axis leaves out values ≤ 0 (a residual that starts at 0); linear when none is > 0.
  bool log_y = false;
  if (p.log_y)
    for (const auto& [name, values] : p.series)
      for (double v : values) log_y = log_y || (std::isfinite(v) && v > 0);
  for (const auto& [name, values] : p.series) {
    n_max = std::max(n_max, values.size());
    for (double v : values)
      if (std::isfinite(v) && (!log_y || v > 0)) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
  }
  std::ostringstream o;
  o << "<svg class=\"plot\" xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " << W << " " << H << "\" width=\""
    << W << "\" height=\"" << H << "\" role=\"img\" aria-label=\"" << html_escape(p.title) << "\">";
  o << "<text x=\"" << ml << "\" y=\"18\" class=\"pt\">" << html_escape(p.title) << "</text>";
  if (n_max == 0 || !std::isfinite(lo)) {
    o << "<text x=\"" << ml + 10 << "\" y=\"" << mt + ph / 2 << "\">no data</text></svg>";
    return o.str();
  }
  auto ty = [&](double v) { return log_y ? std::log10(v) : v; };
  double y0 = ty(lo), y1 = ty(hi);
  std::vector<double> ticks;
  if (log_y) {
    y0 = std::floor(y0);
    y1 = std::ceil(y1);
    if (y1 <= y0) y1 = y0 + 1;
    const int step = std::max(1, static_cast<int>(std::ceil((y1 - y0) / 6)));
    for (double t = y0; t <= y1 + 1e-9; t += step) ticks.push_back(t);
  } else {
    if (y0 > 0) y0 = 0;
    if (y1 <= y0) y1 = y0 + 1;
    const double raw = (y1 - y0) / 5, mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = mag;
    for (double m : {1.0, 2.0, 5.0, 10.0})
      if (m * mag >= raw) {
        step = m * mag;
        break;
      }
    y0 = std::floor(y0 / step) * step;
    y1 = std::ceil(y1 / step) * step;
    for (double t = y0; t <= y1 + step * 1e-9; t += step) ticks.push_back(t);
  }
  const double x_hi = std::max<double>(2, static_cast<double>(n_max));
  auto px = [&](double k) { return ml + pw * (k - 1) / (x_hi - 1); };
  auto py = [&](double v) { return mt + ph * (1 - (ty(v) - y0) / (y1 - y0)); };
  // Grid and axes.
  for (double t : ticks) {
    const double y = mt + ph * (1 - (t - y0) / (y1 - y0));
    o << "<line x1=\"" << ml << "\" x2=\"" << ml + pw << "\" y1=\"" << svg_num(y) << "\" y2=\"" << svg_num(y)
      << "\" class=\"grid\"/>";
    const std::string label = log_y ? (t == 0 ? "1" : "1e" + std::to_string(static_cast<int>(t))) : format_tick(t);
    o << "<text x=\"" << ml - 6 << "\" y=\"" << svg_num(y + 4) << "\" text-anchor=\"end\">" << label << "</text>";
  }
  const int xstep = std::max(1, static_cast<int>(std::ceil((x_hi - 1) / 8.0)));
  for (int k = 1; k <= static_cast<int>(x_hi); k += xstep) {
    o << "<line x1=\"" << svg_num(px(k)) << "\" x2=\"" << svg_num(px(k)) << "\" y1=\"" << mt + ph << "\" y2=\""
      << mt + ph + 4 << "\" class=\"axis\"/>";
    o << "<text x=\"" << svg_num(px(k)) << "\" y=\"" << mt + ph + 17 << "\" text-anchor=\"middle\">" << k << "</text>";
  }
  o << "<rect x=\"" << ml << "\" y=\"" << mt << "\" width=\"" << pw << "\" height=\"" << ph << "\" class=\"frame\"/>";
  o << "<text x=\"" << ml + pw / 2 << "\" y=\"" << mt + ph + 33 << "\" text-anchor=\"middle\">iteration</text>";
  o << "<text transform=\"translate(14," << mt + ph / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
    << html_escape(p.y_label) << (log_y ? " (log)" : "") << "</text>";
  // Series and legend.
  for (size_t s = 0; s < p.series.size(); ++s) {
    const auto& [name, values] = p.series[s];
    const char* color = palette[s % 6];
    std::string path;  // "M" starts a new piece after a value the axis cannot show
    bool pen_down = false;
    for (size_t k = 0; k < values.size(); ++k) {
      const double v = values[k];
      if (!std::isfinite(v) || (log_y && v <= 0)) {
        pen_down = false;
        continue;
      }
      path += (pen_down ? "L" : "M") + svg_num(px(double(k + 1))) + " " + svg_num(py(v)) + " ";
      pen_down = true;
    }
    if (values.size() == 1 && std::isfinite(values[0]))
      o << "<circle cx=\"" << svg_num(px(1)) << "\" cy=\"" << svg_num(py(values[0])) << "\" r=\"3\" fill=\"" << color
        << "\"/>";
    o << "<path fill=\"none\" stroke=\"" << color << "\" stroke-width=\"2\" d=\"" << path << "\"/>";
    const double lx = ml + 4 + 250.0 * static_cast<double>(s % 2), ly = H - 10 - 0.0 * static_cast<double>(s / 2);
    if (s < 2) {
      o << "<line x1=\"" << lx << "\" x2=\"" << lx + 18 << "\" y1=\"" << ly - 4 << "\" y2=\"" << ly - 4
        << "\" stroke=\"" << color << "\" stroke-width=\"3\"/>";
      o << "<text x=\"" << lx + 24 << "\" y=\"" << ly << "\">" << html_escape(name) << "</text>";
    }
  }
  o << "</svg>";
  return o.str();
}

std::string table_html(const ReportTable& t) {
  std::ostringstream o;
  o << "<table><thead><tr>";
  for (const auto& h : t.header) o << "<th>" << html_escape(h) << "</th>";
  o << "</tr></thead><tbody>";
  for (const auto& row : t.rows) {
    o << "<tr>";
    for (const auto& c : row) o << "<td>" << html_escape(c) << "</td>";
    o << "</tr>";
  }
  o << "</tbody></table>";
  return o.str();
}

const char* const kStyle = R"css(
:root{--ink:#222;--muted:#667;--line:#dde;--accent:#1f5fa8}
*{box-sizing:border-box}
body{margin:0;font:15px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,sans-serif;color:var(--ink);background:#f6f7f9}
header,section,footer{max-width:1100px;margin:0 auto;padding:12px 20px}
header h1{font-size:22px;margin:18px 0 2px}
.sub{color:var(--muted);margin:0}
h2{font-size:17px;margin:18px 0 8px}
.card{background:#fff;border:1px solid var(--line);border-radius:8px;padding:12px 16px}
.viewer{position:relative;height:560px;background:#fff;border:1px solid var(--line);border-radius:8px;overflow:hidden}
.viewer canvas{display:block;width:100%;height:100%;touch-action:none}
.toolbar{display:flex;flex-wrap:wrap;gap:8px 16px;align-items:center;margin:0 0 8px}
.toolbar .group{display:flex;gap:4px;align-items:center}
.toolbar button{font:inherit;padding:4px 12px;border:1px solid #bcc;border-radius:5px;background:#fff;cursor:pointer}
.toolbar button.on{background:var(--accent);border-color:var(--accent);color:#fff}
.toolbar select{font:inherit;padding:3px 6px}
.legend{position:absolute;right:12px;bottom:12px;background:rgba(255,255,255,.9);border:1px solid var(--line);border-radius:6px;padding:6px 10px;font-size:13px}
.legend .bar{width:220px;height:12px;border:1px solid #888;margin:4px 0 2px}
.legend .ends{display:flex;justify-content:space-between}
.hint{position:absolute;left:12px;bottom:10px;color:var(--muted);font-size:12px}
.msg{position:absolute;inset:0;display:flex;align-items:center;justify-content:center;color:#a22;padding:20px;text-align:center}
table{border-collapse:collapse;background:#fff;border:1px solid var(--line);font-variant-numeric:tabular-nums}
th,td{padding:5px 12px;border-bottom:1px solid var(--line);text-align:left}
th{background:#eef1f5;font-weight:600}
td:not(:first-child){text-align:right}
.plots{display:flex;flex-wrap:wrap;gap:12px}
.tables{display:flex;flex-wrap:wrap;gap:0 28px;align-items:flex-start}
.legend input{width:5em;font:inherit}
svg.plot{background:#fff;border:1px solid var(--line);border-radius:8px;font-size:12px;fill:var(--ink)}
svg.plot .pt{font-weight:600;font-size:13px}
svg.plot .grid{stroke:#e4e6ea}
svg.plot .axis{stroke:#888}
svg.plot .frame{fill:none;stroke:#888}
footer{color:var(--muted);font-size:12px;padding-bottom:30px}
)css";

}  // namespace

const std::string& report_viewer_script() {
#ifdef MSMESH_HAVE_EMBEDDED_VIEWER
  static const std::string script(msmesh_report_viewer_js, sizeof(msmesh_report_viewer_js) - 1);
#else
  static const std::string script = [] {
    const std::filesystem::path p =
        std::filesystem::path(__FILE__).parent_path().parent_path() / "report" / "dist" / "viewer.js";
    std::ifstream in(p, std::ios::binary);
    if (!in)
      throw IoError("the report viewer script is not built into this program and '" + p.string() +
                    "' cannot be read (see report/README.md)");
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
  }();
#endif
  return script;
}

std::string report_html(const ReportData& d) {
  const std::string& script = report_viewer_script();
  if (script.find("</script") != std::string::npos)
    throw IoError("the report viewer script contains '</script' and cannot be inlined (rebuild report/dist/viewer.js)");
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
    << "<meta name=\"viewport\" content=\"width=device-width,initial-scale=1\">"
    << "<meta name=\"generator\" content=\"msmesh 0.1.0\">"
    << "<title>" << html_escape(d.title) << "</title><style>" << kStyle << "</style>"
    // Errors are collected from the start, for people (shown in the viewer) and for tests.
    << "<script>window.msmeshErrors=[];window.addEventListener('error',function(e){"
       "window.msmeshErrors.push(String(e.message||e))});</script>"
    << "</head><body>\n";
  o << "<header><h1>" << html_escape(d.title) << "</h1>";
  if (!d.subtitle.empty()) o << "<p class=\"sub\">" << html_escape(d.subtitle) << "</p>";
  o << "</header>\n";
  if (!d.meshes.empty()) {
    o << "<section><div id=\"msmesh-toolbar\" class=\"toolbar\"></div>"
      << "<div id=\"msmesh-viewer\" class=\"viewer\"><noscript><div class=\"msg\">The 3D viewer needs "
         "JavaScript.</div></noscript></div></section>\n";
  }
  o << "<section class=\"tables\">";
  for (const auto& [title, table] : d.tables)
    o << "<div><h2>" << html_escape(title) << "</h2>" << table_html(table) << "</div>";
  if (!d.parameters.empty()) {
    ReportTable t;
    t.header = {"parameter", "value"};
    for (const auto& [k, v] : d.parameters) t.rows.push_back({k, v});
    o << "<div><h2>Parameters</h2>" << table_html(t) << "</div>";
  }
  o << "</section>\n";
  if (!d.notes.empty()) {
    o << "<section>";
    for (const auto& n : d.notes) o << "<p>" << html_escape(n) << "</p>";
    o << "</section>\n";
  }
  if (!d.plots.empty()) {
    o << "<section><h2>Convergence</h2><div class=\"plots\">";
    for (const auto& p : d.plots) o << plot_svg(p);
    o << "</div></section>\n";
  }
  o << "<footer>Generated by msmesh 0.1.0. Self-contained page: the 3D viewer is built on three.js (MIT "
       "licence, notice in the script below); drag to rotate, wheel to zoom, right-drag to pan.</footer>\n";
  if (!d.meshes.empty()) {
    o << "<script type=\"application/json\" id=\"msmesh-data\">" << viewer_data_json(d) << "</script>\n";
    o << "<script>" << script << "</script>\n";
  }
  o << "</body></html>\n";
  return o.str();
}

void write_report(const std::string& path, const ReportData& data) {
  const std::string html = report_html(data);
  write_text_file(path, html);
}

// =======================================================================================
// Reports of the subcommands
// =======================================================================================

namespace {

std::string num(double x, int precision = 4) {
  if (!std::isfinite(x)) return "-";
  char b[48];
  std::snprintf(b, sizeof b, "%.*g", precision, x);
  return b;
}

std::string file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

/// The rows of the report's parameter table, from the parameter table (parameters.h): every
/// parameter whose group is in `groups` (empty: all).
template <class Options>
void add_parameters(ReportData& d, const ParameterTable<Options>& table, const Options& o,
                    const std::vector<std::string>& groups = {}) {
  for (const Parameter<Options>& p : table) {
    const ParameterInfo& i = p.info;
    if (!groups.empty() && std::find(groups.begin(), groups.end(), i.group) == groups.end()) continue;
    std::string value = i.type == ParameterType::Boolean ? (p.get(o) != 0 ? "yes" : "no") : i.format(p.get(o));
    if (!i.unit.empty()) value += " " + i.unit;
    d.parameters.push_back({i.name + (i.symbol.empty() ? "" : " (" + i.symbol + ")") + ": " + i.help, value});
  }
}

void add_plots(ReportData& d, const NormalFilterResult& n, const VertexUpdateResult* v) {
  if (!n.residual_history.empty() || !n.change_history.empty()) {
    ReportPlot p;
    p.title = "Normal filtering (Algorithm 1)";
    p.y_label = "mean-edge units";
    p.series.push_back({"residual |p - grad N|_V", n.residual_history});
    p.series.push_back({"change |N(k+1) - N(k)|_U", n.change_history});
    d.plots.push_back(p);
  }
  if (!n.energy_history.empty()) {
    ReportPlot p;
    p.title = "Energy (15) per iteration";
    p.y_label = "energy";
    p.log_y = false;
    p.series.push_back({"energy", n.energy_history});
    d.plots.push_back(p);
  }
  if (v && !v->change_history.empty()) {
    ReportPlot p;
    p.title = "Vertex update (Algorithm 2)";
    p.y_label = "RMS vertex move";
    p.series.push_back({"RMS vertex move (mean edges)", v->change_history});
    d.plots.push_back(p);
  }
}

}  // namespace

void write_denoise_report(const std::string& path, const std::string& input_path, const Mesh& input,
                          const Eigen::MatrixXd& result_V, const Mesh* truth, const std::string& method,
                          const std::string& preset, const DenoiseOptions& o, const DenoiseResult& r) {
  ReportData d;
  d.title = "msmesh denoise: " + file_name(input_path);
  d.subtitle = std::to_string(input.V.rows()) + " vertices, " + std::to_string(input.F.rows()) + " faces; method " +
               method + (o.method == DenoiseMethod::Bilateral ? "" : ", preset " + preset);
  ReportMesh in{"input", input.V, input.F, {}, {}, {}, {}};
  ReportMesh out{"result", result_V, input.F, {}, r.v, {}, {}};
  Evaluation ev_in, ev_out;
  if (truth) {
    ev_in = evaluate(input.V, input.F, truth->V, truth->F);
    ev_out = evaluate(result_V, input.F, truth->V, truth->F);
    if (ev_in.same_connectivity) in.face_error_deg = ev_in.normals.angle_rad * (180.0 / M_PI);
    if (ev_out.same_connectivity) out.face_error_deg = ev_out.normals.angle_rad * (180.0 / M_PI);
  }
  d.meshes.push_back(in);
  d.meshes.push_back(out);
  if (truth) d.meshes.push_back({"truth", truth->V, truth->F, {}, {}, {}, {}});
  d.initial_mesh = 1;
  d.initial_color = out.face_error_deg.size() ? "error" : (r.v.size() ? "field" : "shaded");

  d.parameters.push_back({"input", input_path});
  d.parameters.push_back({"method", method});
  if (o.method != DenoiseMethod::Bilateral) {
    d.parameters.push_back({"preset", preset});
    d.parameters.push_back({"IRLA reweighting", o.method == DenoiseMethod::NMSTV ? "on (NMSTV)" : "off (MSTV)"});
    add_parameters(d, denoise_parameters(), o, {"normal filtering", "vertex update", "solver"});
  } else {
    add_parameters(d, denoise_parameters(), o, {"bilateral filtering"});
  }

  if (truth) {
    ReportTable t;
    t.header = {"mesh", "MSAE (x1e-3)", "mean angle (deg)", "flipped faces", "dist. mean (x1e-3)", "dist. RMS (x1e-3)",
                "dist. max (x1e-3)"};
    auto row = [&](const std::string& name, const Evaluation& e) {
      const bool s = e.same_connectivity;
      t.rows.push_back({name, s ? num(e.normals.msae * 1e3) : "-", s ? num(e.normals.mean_angle_deg) : "-",
                        s ? std::to_string(e.normals.flipped) : "-", num(e.distances.mean * 1e3),
                        num(e.distances.rms * 1e3), num(e.distances.max * 1e3)});
    };
    row("input", ev_in);
    row("result", ev_out);
    d.tables.push_back({"Error against the ground truth", t});
    d.notes.push_back("MSAE: mean over faces of the squared angle (radians) between result and truth face normals, "
                      "printed x1e-3 as in the paper; mean angle: the plain mean angle in degrees. Distances: "
                      "vertex to truth surface over the truth's bounding-box diagonal.");
  }
  ReportTable run;
  run.header = {"stage", "iterations", "converged", "seconds", "final value"};
  if (o.method != DenoiseMethod::Bilateral) {
    const auto& n = r.normal_report;
    run.rows.push_back({"normal filtering", std::to_string(n.iterations), n.converged ? "yes" : "no",
                        num(r.seconds_normals, 3),
                        n.residual_history.empty() ? "-" : "residual " + num(n.residual_history.back())});
  } else {
    run.rows.push_back({"bilateral normals", std::to_string(o.bilateral.normal_iterations), "-",
                        num(r.seconds_normals, 3), "-"});
  }
  const auto& v = r.vertex_report;
  run.rows.push_back({"vertex update", std::to_string(v.iterations), v.converged ? "yes" : "no",
                      num(r.seconds_vertices, 3),
                      v.change_history.empty() ? "-" : "RMS move " + num(v.change_history.back())});
  d.tables.push_back({"Run", run});
  add_plots(d, r.normal_report, &r.vertex_report);
  write_report(path, d);
}

void write_segment_report(const std::string& path, const std::string& input_path, const Mesh& mesh,
                          const SegmentOptions& o, const SegmentResult& r) {
  ReportData d;
  d.title = "msmesh segment: " + file_name(input_path);
  d.subtitle = std::to_string(mesh.F.rows()) + " faces, " + std::to_string(r.count) + " segments";
  d.meshes.push_back({"mesh", mesh.V, mesh.F, {}, r.v, r.labels, {}});
  d.initial_color = "labels";
  d.parameters.push_back({"input", input_path});
  add_parameters(d, segment_parameters(), o);
  ReportTable t;
  t.header = {"segment", "faces", "area", "area (%)"};
  std::vector<long> faces(r.count, 0);
  for (Eigen::Index f = 0; f < r.labels.size(); ++f) ++faces[r.labels(f)];
  const double total = r.areas.sum();
  for (int s = 0; s < r.count; ++s)
    t.rows.push_back({std::to_string(s), std::to_string(faces[s]), num(r.areas(s)),
                      num(total > 0 ? 100 * r.areas(s) / total : 0.0, 3)});
  d.tables.push_back({"Segments", t});
  d.notes.push_back("Multicut found " + std::to_string(r.multicut_count) + " segments (objective " + num(r.objective) +
                    "); segments below the minimum area were merged into a neighbour.");
  add_plots(d, r.normal_report, nullptr);
  write_report(path, d);
}

void write_inpaint_report(const std::string& path, const std::string& input_path, const Mesh& input,
                          const InpaintResult& r, const Mesh* truth, const InpaintOptions& o) {
  ReportData d;
  d.title = "msmesh inpaint: " + file_name(input_path);
  d.subtitle = std::to_string(r.filled) + " of " + std::to_string(r.holes.size()) + " holes filled; " +
               std::to_string(r.F.rows() - input.F.rows()) + " faces added";
  d.meshes.push_back({"input", input.V, input.F, {}, {}, {}, {}});
  ReportMesh out{"result", r.V, r.F, {}, {}, {}, r.new_faces};
  d.meshes.push_back(out);
  if (truth) d.meshes.push_back({"truth", truth->V, truth->F, {}, {}, {}, {}});
  d.initial_mesh = 1;
  d.parameters.push_back({"input", input_path});
  add_parameters(d, inpaint_parameters(), o);
  ReportTable t;
  t.header = {"hole", "edges", "diameter", "action", "new faces", "features"};
  for (size_t i = 0; i < r.holes.size(); ++i) {
    const HoleReport& rep = r.reports[i];
    const char* action = rep.action == HoleAction::Filled ? "filled" : rep.action == HoleAction::Failed ? "failed" : "skipped";
    t.rows.push_back({std::to_string(i), std::to_string(r.holes[i].edges), num(r.holes[i].diameter, 3),
                      std::string(action) + (rep.reason.empty() ? "" : " (" + rep.reason + ")"),
                      std::to_string(rep.new_faces),
                      rep.action == HoleAction::Filled ? (rep.features ? "recovered" : "fair patch") : "-"});
  }
  d.tables.push_back({"Holes", t});
  if (truth) {
    const InpaintErrors e = inpaint_errors(input.V, input.F, r.V, r.F, r.new_faces, truth->V, truth->F);
    ReportTable f;
    f.header = {"points", "max (x1e-3)", "mean (x1e-3)", "RMS (x1e-3)", "new-face normal error (deg)"};
    f.rows.push_back({std::to_string(e.points), num(e.max * 1e3), num(e.mean * 1e3), num(e.rms * 1e3),
                      num(e.mean_normal_error_deg)});
    d.tables.push_back({"Filled region against the ground truth", f});
  }
  d.notes.push_back("New faces are tinted in the viewer's shaded mode. Plots: the last feature-recovery round, on the region around the recovered holes.");
  add_plots(d, r.normal_report, &r.vertex_report);
  write_report(path, d);
}

}  // namespace msmesh::cli
