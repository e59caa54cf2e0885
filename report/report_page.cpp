#include "msmesh/report_page.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "msmesh/color_map.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"
#include "msmesh/json_writer.h"
#include "msmesh/mesh_coloring.h"
#include "msmesh/topology.h"

// The viewer bundle, embedded at build time (see report/README.md): CMake reads
// report/dist/viewer.js into a generated header. Without it (a build system that did not run
// that step) the script is read from the source tree at run time.
#if __has_include("msmesh_report_viewer_js.h")
#include "msmesh_report_viewer_js.h"
#define MSMESH_HAVE_EMBEDDED_VIEWER 1
#endif

namespace msmesh {

namespace {

std::string html_escape(const std::string& s) {
  std::string o;
  o.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&':
        o += "&amp;";
        break;
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '"':
        o += "&quot;";
        break;
      case '\'':
        o += "&#39;";
        break;
      default:
        o += c;
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
    if (!all.empty())
      error_max = error_scale(Eigen::Map<Eigen::VectorXd>(all.data(), static_cast<Eigen::Index>(all.size())));
  }
  std::vector<Json> meshes;
  for (const auto& m : d.meshes) {
    validate_mesh(m.V, m.F, "report mesh '" + m.name + "'");
    Json j;
    j.add("name", m.name)
        .add("vertices", static_cast<long long>(m.V.rows()))
        .add("faces", static_cast<long long>(m.F.rows()));
    const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> Vr = m.V;
    const Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor> Fr = m.F;
    j.add("positions", floats_b64(Vr.data(), static_cast<size_t>(Vr.size())));
    // Meshes with the faces of an earlier one (input, result, truth of a denoising) share its
    // index array.
    int same = -1;
    for (size_t k = 0; k < meshes.size() && same < 0; ++k)
      if (d.meshes[k].F.rows() == m.F.rows() && d.meshes[k].F == m.F) same = static_cast<int>(k);
    if (same >= 0)
      j.add("indices_of", same);
    else
      j.add("indices", ints_b64(Fr.data(), static_cast<size_t>(Fr.size())));
    if (m.face_error_deg.size()) {
      if (m.face_error_deg.size() != m.F.rows())
        throw InvalidInput("report mesh '" + m.name + "': face_error_deg size");
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
  j.add("meshes", meshes)
      .add("initial_mesh", d.initial_mesh)
      .add("initial_color", d.initial_color)
      .add("error_max", error_max)
      .add("label_colors", label_rgb);
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
  o << "<svg class=\"plot\" xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " << W << " " << H << "\" width=\"" << W
    << "\" height=\"" << H << "\" role=\"img\" aria-label=\"" << html_escape(p.title) << "\">";
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
    const double lx = ml + 4 + 250.0 * static_cast<double>(s % 2), ly = H - 10;  // legends of the first two series
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
    << "<title>" << html_escape(d.title) << "</title><style>" << kStyle
    << "</style>"
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

}  // namespace msmesh
