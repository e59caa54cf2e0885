// OBJ reader (our own, one pass over the lines). Every number goes through read_text.h's
// strict parsers: a coordinate is a whole decimal word, a face corner is `v`, `v/vt`, `v//vn`
// or `v/vt/vn` with integer indices (1-based, negative = relative to the records read so far),
// and anything else ("2.9", "1e3", "+1", an index beyond int, 0) is refused naming the line and
// the word. Any whitespace separates words (tabs, \r, \v, \f as spaces); a UTF-8 byte-order
// mark is skipped; '#' starts a comment. Records that are not part of a surface ('l', 'p',
// 'usemtl', unknown keywords, ...) are skipped. Vertex colours ("v x y z r g b"), texture
// coordinates and normals are read too.
//
// Until this reader, CGAL's read_OBJ was used: it split corners on ' ' only (tabs lost faces),
// read "2.9" as 2, ended a face at an overflowing index and refused the BOM's first line.
#include <algorithm>
#include <array>
#include <cctype>
#include <climits>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "msmesh/errors.h"
#include "read_common.h"
#include "read_obj_plain.h"

namespace msmesh::io_detail {
namespace {

/// One face corner's indices as written (0 = absent).
struct ObjCorner {
  long long v = 0, vt = 0, vn = 0;
};

/// Parses a corner word `v`, `v/vt`, `v//vn` or `v/vt/vn`; returns the problem, or "".
std::string parse_obj_corner(std::string_view word, ObjCorner& c) {
  std::string_view part[3];
  int parts = 0;
  for (std::size_t start = 0;;) {
    const std::size_t slash = word.find('/', start);
    if (parts == 3) return "too many '/'";
    part[parts++] = word.substr(start, slash == std::string_view::npos ? std::string_view::npos : slash - start);
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  // "1/" and "1//" leave an empty last part; only the middle one (vt in "1//3") may be empty.
  if (part[parts - 1].empty() && parts > 1) return "an empty index after '/'";
  long long* const out[3] = {&c.v, &c.vt, &c.vn};
  for (int k = 0; k < parts; ++k) {
    if (k == 1 && parts == 3 && part[k].empty()) continue;
    const std::string_view p = part[k];
    const auto x = parse_strict_integer(p, INT_MIN + 1LL, INT_MAX);
    if (!x) {
      if (parse_strict_integer(p, LLONG_MIN + 1, LLONG_MAX) || (p.size() > 19 && parse_double(p)))
        return "index " + quote_word(p) + " does not fit in an int";
      return "an index must be an integer";
    }
    if (*x == 0) return "index 0 (OBJ indices are 1-based; negative ones count back from the last record)";
    *out[k] = *x;
  }
  return "";
}

/// 1-based or negative (relative to `count` records so far) to 0-based.
long long resolve_obj_index(long long idx, std::size_t count) {
  return idx > 0 ? idx - 1 : static_cast<long long>(count) + idx;
}

}  // namespace

void read_obj(const std::string& path, std::string_view data, Soup& soup) {
  data = without_utf8_bom(data);
  if (read_plain_obj(data, soup)) return;  // vertices and triangles only, on every core
  // A quick first pass counts the records by their first letter (lines starting "v", "f",
  // anything else) so that the arrays are allocated once; the parse itself is one pass over
  // the lines, found in place (no array of lines, no string per line or per number).
  {
    std::size_t v_lines = 0, f_lines = 0;
    for (const char* p = data.data(); p != nullptr && p < data.data() + data.size();) {
      const char* const end = data.data() + data.size();
      if (end - p >= 2 && is_space(p[1])) v_lines += p[0] == 'v', f_lines += p[0] == 'f';
      p = static_cast<const char*>(std::memchr(p, '\n', static_cast<std::size_t>(end - p)));
      if (p) ++p;
    }
    soup.points.reserve(v_lines);
    soup.flat.start.reserve(f_lines + 1);
    soup.flat.corners.reserve(3 * f_lines);
    for (auto* per_face : {&soup.polygon_material, &soup.polygon_group, &soup.polygon_object})
      per_face->reserve(f_lines);
  }
  auto fail = [&](std::size_t n, const std::string& what) {
    throw IoError(path + ": line " + std::to_string(n + 1) + ": " + what);
  };
  std::vector<std::array<double, 3>> rgb, vn;
  std::vector<std::array<double, 2>> vt;
  bool all_rgb = true;
  // Per corner, in polygon order: the 0-based vt / vn index (-1 none), filled lazily once the
  // first corner with one appears.
  std::vector<long long> corner_vt, corner_vn;
  std::size_t corners = 0;
  long long max_index = -1;  // largest 0-based vertex index of a positive (forward) reference
  std::size_t max_index_line = 0;
  std::vector<std::string_view> w;
  // Materials, groups and objects: the current one of each (−1 none) and the names seen.
  int material = -1, group = -1, object = -1;
  bool any_material = false, any_group = false, any_object = false;
  auto name_index = [](std::vector<std::string>& names, const std::string& name) {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it != names.end()) return static_cast<int>(it - names.begin());
    names.push_back(name);
    return static_cast<int>(names.size() - 1);
  };
  // The rest of a record's line after its keyword (names may contain spaces).
  std::string_view line;  // the current line, without its '\n' (and a trailing '\r')
  auto rest_of = [&]() {
    const std::size_t hash = line.find('#');
    if (hash != std::string_view::npos) line = line.substr(0, hash);
    std::size_t i = 0;
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    std::size_t e = line.size();
    while (e > i && std::isspace(static_cast<unsigned char>(line[e - 1]))) --e;
    return std::string(line.substr(i, e - i));
  };
  std::size_t skipped_lines = 0, skipped_points = 0, smoothing = 0, other = 0;
  std::string first_other;
  auto number = [&](std::size_t n, std::string_view word, const char* what) {
    const auto x = parse_double(word);
    if (!x) fail(n, std::string("cannot read ") + what + " " + quote_word(word));
    return *x;
  };
  std::size_t n = 0, next = 0;  // line number - 1; where the next line starts
  for (std::size_t start = 0; start < data.size(); start = next, ++n) {
    const char* const nl = static_cast<const char*>(std::memchr(data.data() + start, '\n', data.size() - start));
    const std::size_t end = nl ? static_cast<std::size_t>(nl - data.data()) : data.size();
    line = data.substr(start, end - start);
    next = end + 1;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    split_words(line, w);
    const auto comment = std::find_if(w.begin(), w.end(), [](std::string_view s) { return s.front() == '#'; });
    w.erase(comment, w.end());
    if (w.empty()) continue;
    if (w[0] == "v") {
      if (w.size() < 4) fail(n, "vertex record with fewer than 3 coordinates");
      double p[3];
      for (int c = 0; c < 3; ++c) {
        p[c] = number(n, w[1 + c], "vertex coordinate");
        if (!std::isfinite(p[c])) fail(n, "non-finite vertex coordinate " + quote_word(w[1 + c]));
      }
      soup.points.emplace_back(p[0], p[1], p[2]);
      if (w.size() >= 7 && all_rgb) {
        std::array<double, 3> col{};
        for (int k = 0; k < 3; ++k) {
          const auto x = parse_double(w[4 + k]);
          if (!x || !std::isfinite(*x)) all_rgb = false;
          col[k] = x ? *x : 0.0;
        }
        rgb.push_back(col);
      } else {
        all_rgb = false;
      }
    } else if (w[0] == "vt") {
      if (w.size() < 2) fail(n, "texture coordinate record without a value");
      vt.push_back(
          {number(n, w[1], "texture coordinate"), w.size() >= 3 ? number(n, w[2], "texture coordinate") : 0.0});
    } else if (w[0] == "vn") {
      if (w.size() < 4) fail(n, "normal record with fewer than 3 components");
      vn.push_back({number(n, w[1], "normal component"), number(n, w[2], "normal component"),
                    number(n, w[3], "normal component")});
    } else if (w[0] == "mtllib") {
      // Several file names may follow; each is found from the OBJ file's folder.
      auto& libs = soup.extra.material_libraries;
      for (std::size_t k = 1; k < w.size(); ++k) {
        const std::filesystem::path name{std::string(w[k])};
        const std::string lib =
            (name.is_absolute() ? name : std::filesystem::path(path).parent_path() / name).lexically_normal().string();
        if (std::find(libs.begin(), libs.end(), lib) == libs.end()) libs.push_back(lib);
      }
    } else if (w[0] == "usemtl") {
      material = name_index(soup.extra.material_names, rest_of());
    } else if (w[0] == "g") {
      group = name_index(soup.extra.group_names, rest_of());  // "g" alone: the default group ""
    } else if (w[0] == "o") {
      object = name_index(soup.extra.object_names, rest_of());
    } else if (w[0] == "l") {
      ++skipped_lines;
    } else if (w[0] == "p") {
      ++skipped_points;
    } else if (w[0] == "s") {
      if (w.size() > 1 && w[1] != "off" && w[1] != "0") ++smoothing;
    } else if (w[0] == "f") {
      any_material = any_material || material >= 0;
      any_group = any_group || group >= 0;
      any_object = any_object || object >= 0;
      soup.polygon_material.push_back(material);
      soup.polygon_group.push_back(group);
      soup.polygon_object.push_back(object);
      for (std::size_t k = 1; k < w.size(); ++k, ++corners) {
        ObjCorner c;
        const std::string problem = parse_obj_corner(w[k], c);
        if (!problem.empty()) fail(n, "bad face corner " + quote_word(w[k]) + ": " + problem);
        const long long v = resolve_obj_index(c.v, soup.points.size());
        if (v < 0)
          fail(n, "face refers to vertex " + std::to_string(c.v) + ", but only " + std::to_string(soup.points.size()) +
                      " vertices precede it");
        if (c.v > 0 && v > max_index) max_index = v, max_index_line = n;
        soup.flat.corners.push_back(static_cast<std::size_t>(v));
        auto attribute = [&](std::vector<long long>& slots, long long idx, std::size_t count) {
          if (idx == 0 && slots.empty()) return;
          slots.resize(corners, -1);
          const long long r = idx == 0 ? -1 : resolve_obj_index(idx, count);
          slots.push_back(idx != 0 && r < 0 ? -2 : r);  // -2: before the first record
        };
        attribute(corner_vt, c.vt, vt.size());
        attribute(corner_vn, c.vn, vn.size());
      }
      soup.flat.close();
    } else {
      // Free-form geometry and unknown keywords are not part of the surface.
      if (other++ == 0) first_other = std::string(w[0].substr(0, 20));
    }
  }
  if (!any_material) soup.polygon_material.clear();
  if (!any_group) soup.polygon_group.clear();
  if (!any_object) soup.polygon_object.clear();
  if (skipped_lines)
    soup.notes.dropped.push_back(std::to_string(skipped_lines) + " OBJ line elements ('l') are not kept");
  if (skipped_points)
    soup.notes.dropped.push_back(std::to_string(skipped_points) + " OBJ point elements ('p') are not kept");
  if (smoothing) soup.notes.dropped.emplace_back("OBJ smoothing groups ('s') are not kept (normals are recomputed)");
  if (other)
    soup.notes.dropped.push_back(std::to_string(other) + " OBJ records of unknown kind (the first '" + first_other +
                                 "') are not kept");
  if (soup.points.empty()) throw IoError(path + ": no vertices ('v' records)");
  if (soup.flat.size() == 0) throw IoError(path + ": no faces ('f' records)");
  const std::size_t nv = soup.points.size();
  if (max_index >= static_cast<long long>(nv))
    fail(max_index_line, "face refers to vertex " + std::to_string(max_index + 1) + ", but the file has " +
                             std::to_string(nv) + " vertices (indices are 1-based)");

  if (all_rgb && rgb.size() == nv) {
    double top = 0;
    for (const auto& c : rgb)
      for (double x : c) top = std::max(top, x);
    const double scale = top > 1.0 ? 1.0 / 255.0 : 1.0;  // some exporters write 0..255
    for (auto& c : rgb)
      for (double& x : c) x = std::clamp(x * scale, 0.0, 1.0);
    soup.rgb = std::move(rgb);
  }
  // Per-corner values ("f v/vt/vn") become per-vertex when every corner of a vertex names the
  // same value; otherwise (seams) they are dropped and noted. A vertex no face refers to takes
  // the value of the same index when there is one (files that list them in step with the
  // vertices), else 0.
  auto per_vertex = [&](std::vector<long long>& slots, std::size_t count, std::vector<long long>& of_vertex) {
    slots.resize(corners, -1);
    if (std::find(slots.begin(), slots.end(), -1) != slots.end()) return false;  // corners without one
    of_vertex.assign(nv, -1);  // -1 none yet, -2 conflicting or out of range
    std::size_t corner = 0;
    for (std::size_t v : soup.flat.corners) {
      const long long idx = slots[corner++] < static_cast<long long>(count) ? slots[corner - 1] : -2;
      long long& slot = of_vertex[v];
      slot = slot == -1 ? idx : slot == idx ? slot : -2;
    }
    for (std::size_t v = 0; v < nv; ++v)
      if (of_vertex[v] == -1) of_vertex[v] = v < count ? static_cast<long long>(v) : -3;
    return std::find(of_vertex.begin(), of_vertex.end(), -2) == of_vertex.end();
  };
  std::vector<long long> vertex_vt, vertex_vn;
  if (!corner_vt.empty()) {
    if (!per_vertex(corner_vt, vt.size(), vertex_vt)) {
      // Seams: texture coordinates per corner (corners without one or naming a vt that does
      // not exist get none, -1); non-finite values drop them all, as for PLY.
      bool finite = true;
      for (const auto& t : vt) finite = finite && std::isfinite(t[0]) && std::isfinite(t[1]);
      if (finite) {
        soup.texcoord_table = vt;
        soup.corner_texcoord = corner_vt;
        std::size_t bad = 0;
        for (long long& c : soup.corner_texcoord)
          if (c < -1 || c >= static_cast<long long>(vt.size())) c = -1, ++bad;
        if (bad)
          soup.notes.dropped.push_back(std::to_string(bad) +
                                       " face corners name a texture coordinate that does not exist; they have none");
      } else {
        soup.notes.dropped.emplace_back("texture coordinates with a non-finite value are not kept");
      }
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
  if (!corner_vn.empty()) {
    soup.notes.had_normals = true;
    if (per_vertex(corner_vn, vn.size(), vertex_vn)) {
      soup.normals.resize(nv, {0.0, 0.0, 0.0});
      for (std::size_t v = 0; v < nv; ++v)
        if (vertex_vn[v] >= 0) soup.normals[v] = vn[static_cast<std::size_t>(vertex_vn[v])];
      // Non-finite normals are recomputed instead (libFuzzer found them passed through).
      for (const auto& nrm : soup.normals)
        if (!std::isfinite(nrm[0]) || !std::isfinite(nrm[1]) || !std::isfinite(nrm[2])) {
          soup.normals.clear();
          break;
        }
    }
  }
}

}  // namespace msmesh::io_detail
