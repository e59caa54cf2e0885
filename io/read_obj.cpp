// OBJ reader (CGAL's read_OBJ behind guards). CGAL refuses any record it does not know (e.g.
// 'l') and lets index #V+1 and 0 through its own range check; it only says "false", so
// failures are diagnosed here. Vertex colours, texture coordinates and normals, which CGAL's
// soup reader drops, are read here too.
#include <CGAL/IO/OBJ.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "msmesh/errors.h"
#include "read_common.h"

namespace msmesh::io_detail {
namespace {

bool obj_keyword_known_to_cgal(std::string_view s) {
  static const char* const known[] = {
      "v",     "vt",    "vn",     "f",        "vp",         "bevel",      "lod",      "ctech",   "c_interp",
      "usemap", "usemtl", "stech", "d_interp", "mtllib",     "shadow_obj", "trace_obj", "o",      "g",
      "s",     "p",     "cstype", "deg",      "step",       "bmat",       "con",      "curv",    "curv2",
      "surf",  "parm",  "trim",   "hole",     "scrv",       "sp",         "end",      "surf_1",  "q0_1",
      "q1_1",  "curv2d_1", "surf_2", "q0_2",  "q1_2",       "curv2d_2",   "bsp",      "bzp",     "cdc",
      "cdp",   "res"};
  for (const char* k : known)
    if (s == k) return true;
  return !s.empty() && s.front() == '#';
}

/// Why CGAL's OBJ reader refused the file (it only says false).
std::string diagnose_obj(std::string_view data) {
  const auto lines = split_lines(data);
  long long vertices = 0, faces = 0;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const auto w = split_words(lines[n]);
    if (w.empty()) continue;
    const std::string where = "line " + std::to_string(n + 1) + ": ";
    if (w[0] == "v") {
      if (w.size() < 4) return where + "vertex record with fewer than 3 coordinates";
      for (int c = 1; c <= 3; ++c) {
        const auto x = parse_double(w[c]);
        if (!x) return where + "cannot read vertex coordinate " + quote_word(w[c]);
        if (!std::isfinite(*x)) return where + "non-finite vertex coordinate " + quote_word(w[c]);
      }
      ++vertices;
    } else if (w[0] == "f") {
      ++faces;
    } else if (!obj_keyword_known_to_cgal(w[0])) {
      return where + "unsupported OBJ record " + quote_word(w[0]) +
             " (CGAL's OBJ reader accepts v, vt, vn, f, o, g, s, usemtl, mtllib and free-form records)";
    }
  }
  if (vertices == 0) return "no vertices ('v' records)";
  if (faces == 0) return "no faces ('f' records)";
  // Face indices: CGAL rejects those beyond the vertex count (1-based, negative = relative).
  long long seen = 0;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const auto w = split_words(lines[n]);
    if (w.empty()) continue;
    if (w[0] == "v") ++seen;
    if (w[0] != "f") continue;
    for (std::size_t k = 1; k < w.size(); ++k) {
      const auto idx = parse_integer(w[k].substr(0, w[k].find('/')));
      if (!idx) break;
      if (*idx > vertices || *idx == 0 || *idx < -seen)
        return "line " + std::to_string(n + 1) + ": face refers to vertex " + std::to_string(*idx) +
               ", but the file has " + std::to_string(vertices) + " vertices (indices are 1-based)";
    }
  }
  return "malformed OBJ file (CGAL's reader failed)";
}

/// `data` without the lines whose record CGAL's OBJ reader refuses (e.g. 'l' polylines).
std::string without_unknown_obj_records(std::string_view data) {
  std::string kept;
  kept.reserve(data.size());
  for (const std::string_view line : split_lines(data)) {
    const auto w = split_words(line);
    if (w.empty() || obj_keyword_known_to_cgal(w[0])) kept.append(line).push_back('\n');
  }
  return kept;
}

/// Vertex colours ("v x y z r g b"), texture coordinates and normals of an OBJ file as
/// per-vertex arrays. Per-corner values ("f v/vt/vn") become per-vertex when every corner of a
/// vertex names the same value; otherwise (seams) they are dropped and noted.
void read_obj_attributes(std::string_view data, Soup& soup) {
  const std::size_t nv = soup.points.size();
  std::vector<std::array<double, 3>> rgb, vn;
  std::vector<std::array<double, 2>> vt;
  bool all_rgb = true;
  std::size_t vertices = 0;
  // Per vertex: the vt / vn index its corners name (-1 none yet, -2 conflicting).
  std::vector<long long> vertex_vt(nv, -1), vertex_vn(nv, -1);
  bool corners_without_vt = false, corners_without_vn = false, any_vt = false, any_vn = false;
  auto resolve = [](long long idx, std::size_t count) -> long long {  // 1-based / negative -> 0-based
    if (idx > 0) return idx - 1;
    if (idx < 0) return static_cast<long long>(count) + idx;
    return -1;
  };
  auto assign = [](std::vector<long long>& slot, std::size_t v, long long idx) {
    if (slot[v] == -1) slot[v] = idx;
    else if (slot[v] != idx) slot[v] = -2;
  };
  for (const std::string_view line : split_lines(data)) {
    const auto w = split_words(line);
    if (w.empty()) continue;
    if (w[0] == "v") {
      ++vertices;
      if (w.size() >= 7) {
        std::array<double, 3> c{};
        for (int k = 0; k < 3; ++k) {
          const auto x = parse_double(w[4 + k]);
          if (!x || !std::isfinite(*x)) all_rgb = false;
          c[k] = x ? *x : 0.0;
        }
        rgb.push_back(c);
      } else {
        all_rgb = false;
      }
    } else if (w[0] == "vt" && w.size() >= 2) {
      const auto u = parse_double(w[1]);
      const auto v = w.size() >= 3 ? parse_double(w[2]) : std::optional<double>(0.0);
      vt.push_back({u ? *u : 0.0, v ? *v : 0.0});
    } else if (w[0] == "vn" && w.size() >= 4) {
      std::array<double, 3> n{};
      for (int k = 0; k < 3; ++k) {
        const auto x = parse_double(w[1 + k]);
        n[k] = x ? *x : 0.0;
      }
      vn.push_back(n);
    } else if (w[0] == "f") {
      for (std::size_t k = 1; k < w.size(); ++k) {
        const std::string_view corner = w[k];
        const std::size_t s1 = corner.find('/');
        const auto vi = parse_integer(corner.substr(0, s1));
        if (!vi) continue;
        const long long v = resolve(*vi, vertices);
        if (v < 0 || static_cast<std::size_t>(v) >= nv) continue;
        std::string_view t, n;
        if (s1 != std::string_view::npos) {
          const std::size_t s2 = corner.find('/', s1 + 1);
          t = corner.substr(s1 + 1, s2 == std::string_view::npos ? std::string_view::npos : s2 - s1 - 1);
          if (s2 != std::string_view::npos) n = corner.substr(s2 + 1);
        }
        const auto ti = t.empty() ? std::nullopt : parse_integer(t);
        const auto ni = n.empty() ? std::nullopt : parse_integer(n);
        if (ti) {
          any_vt = true;
          const long long r = resolve(*ti, vt.size());
          assign(vertex_vt, static_cast<std::size_t>(v), r >= 0 && static_cast<std::size_t>(r) < vt.size() ? r : -2);
        } else {
          corners_without_vt = true;
        }
        if (ni) {
          any_vn = true;
          const long long r = resolve(*ni, vn.size());
          assign(vertex_vn, static_cast<std::size_t>(v), r >= 0 && static_cast<std::size_t>(r) < vn.size() ? r : -2);
        } else {
          corners_without_vn = true;
        }
      }
    }
  }
  if (all_rgb && rgb.size() == nv && nv > 0) {
    double top = 0;
    for (const auto& c : rgb)
      for (double x : c) top = std::max(top, x);
    const double scale = top > 1.0 ? 1.0 / 255.0 : 1.0;  // some exporters write 0..255
    for (auto& c : rgb)
      for (double& x : c) x = std::clamp(x * scale, 0.0, 1.0);
    soup.rgb = std::move(rgb);
  }
  // A vertex no face refers to takes the texture coordinate / normal of the same index when
  // there is one (files that list them in step with the vertices), else 0.
  auto per_vertex = [&](std::vector<long long>& slot, std::size_t count) {
    for (std::size_t v = 0; v < nv; ++v)
      if (slot[v] == -1) slot[v] = v < count ? static_cast<long long>(v) : -3;
    return std::none_of(slot.begin(), slot.end(), [](long long x) { return x == -2; });
  };
  if (any_vt) {
    if (corners_without_vt || !per_vertex(vertex_vt, vt.size())) {
      soup.notes.uv_dropped = true;
    } else {
      soup.uv.resize(nv, {0.0, 0.0});
      for (std::size_t v = 0; v < nv; ++v)
        if (vertex_vt[v] >= 0) soup.uv[v] = vt[static_cast<std::size_t>(vertex_vt[v])];
      // Non-finite values (e.g. "vt 1e999 0") drop the attribute, as for PLY.
      for (const auto& t : soup.uv)
        if (!std::isfinite(t[0]) || !std::isfinite(t[1])) {
          soup.uv.clear();
          break;
        }
    }
  }
  if (any_vn) {
    soup.notes.had_normals = true;
    if (!corners_without_vn && per_vertex(vertex_vn, vn.size())) {
      soup.normals.resize(nv, {0.0, 0.0, 0.0});
      for (std::size_t v = 0; v < nv; ++v)
        if (vertex_vn[v] >= 0) soup.normals[v] = vn[static_cast<std::size_t>(vertex_vn[v])];
      // Non-finite normals are recomputed instead (libFuzzer found them passed through).
      for (const auto& n : soup.normals)
        if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2])) {
          soup.normals.clear();
          break;
        }
    }
  }
}

}  // namespace

void read_obj(const std::string& path, std::string_view data, Soup& soup) {
  {
    std::size_t v = 0, f = 0;
    for (std::size_t at = 0; at < data.size();) {
      if (data.compare(at, 2, "v ") == 0) ++v;
      if (data.compare(at, 2, "f ") == 0) ++f;
      const std::size_t nl = data.find('\n', at);
      at = nl == std::string_view::npos ? data.size() : nl + 1;
    }
    soup.points.reserve(v);
    soup.polygons.reserve(f);
  }
  bool ok;
  {
    MemoryStream in(data);
    ok = CGAL::IO::read_OBJ(in, soup.points, soup.polygons, CGAL::parameters::verbose(false));
  }
  std::string filtered;
  if (!ok && diagnose_obj(data).find("unsupported OBJ record") != std::string::npos) {
    // Records that are not part of a surface (lines 'l', vertex colours 'vc', ...) are skipped.
    filtered = without_unknown_obj_records(data);
    data = filtered;
    soup = Soup();
    MemoryStream in(data);
    ok = CGAL::IO::read_OBJ(in, soup.points, soup.polygons, CGAL::parameters::verbose(false));
  }
  if (!ok) throw IoError(path + ": " + diagnose_obj(data));
  // CGAL's own index check lets index #V + 1 and index 0 through; report those 1-based.
  for (const Polygon& poly : soup.polygons)
    for (std::size_t idx : poly)
      if (idx >= soup.points.size()) throw IoError(path + ": " + diagnose_obj(data));
  read_obj_attributes(data, soup);
}

}  // namespace msmesh::io_detail
