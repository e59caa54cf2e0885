// glTF 2.0 reading and writing (read_gltf, write_gltf: read_common.h, write_common.h) through
// tinygltf (Debian's libtinygltf-dev), the only translation unit that includes it.
//
// Why tinygltf rather than assimp: it is small, reads and writes glTF exactly as the
// specification has it, and keeps everything it does not interpret (materials, textures,
// images, nodes, animations, extensions) in its Model, so a scene can be written back with
// only the geometry replaced; assimp converts every format to its own scene graph and back,
// losing glTF materials and extensions on the way.
//
// Reading: every triangle primitive (modes TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN) of every
// mesh gives faces; POSITION, NORMAL, COLOR_0 and TEXCOORD_0 are read (float or normalized
// integer components) and application-specific scalar attributes "_NAME" (extra vertex
// properties, float32), in each mesh's own coordinates (node transforms are not applied: they
// stay in the document and apply again when the result is shown). glTF splits vertices where
// texture coordinates or normals differ (seams, creases); vertices of one mesh at exactly the
// same position are joined again, so the surface is connected, and the texture coordinates
// are kept per corner. Each primitive becomes a group (Mesh::face_groups) and its material the
// face material. The whole document is kept (Mesh::gltf_document, a GLB in memory, external
// buffers and embedded images inside it, external images referenced by path).
//
// Writing: with a document, each of its triangle primitives gets the faces of its group, as new
// POSITION, NORMAL, COLOR_0, TEXCOORD_0 and indices accessors (vertices split where a vertex
// has several texture coordinates); the old geometry is removed, and everything else is
// written back unchanged (one buffer: the GLB's binary chunk, or embedded in a .gltf). Without
// one, a document with one mesh, one primitive per material and a plain material per name.
// Texture coordinates are flipped (v = 1 − v): glTF's origin is the top left, Mesh::uv's the
// bottom left (OBJ, PLY).
#include <tiny_gltf.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "msmesh/errors.h"
#include "read_common.h"
#include "write_common.h"

namespace msmesh::io_detail {
namespace {

namespace fs = std::filesystem;
using tinygltf::Accessor;
using tinygltf::Model;
using tinygltf::Primitive;

/// Image loader that keeps the encoded bytes (as_is) instead of decoding them.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  image->as_is = true;
  image->image.assign(bytes, bytes + size);
  return true;
}

std::string base64(const std::vector<unsigned char>& in) {
  static const char* const k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < in.size(); i += 3) {
    const std::uint32_t b0 = in[i], b1 = i + 1 < in.size() ? in[i + 1] : 0, b2 = i + 2 < in.size() ? in[i + 2] : 0;
    const std::uint32_t v = (b0 << 16) | (b1 << 8) | b2;
    out.push_back(k[(v >> 18) & 63]);
    out.push_back(k[(v >> 12) & 63]);
    out.push_back(i + 1 < in.size() ? k[(v >> 6) & 63] : '=');
    out.push_back(i + 2 < in.size() ? k[v & 63] : '=');
  }
  return out;
}

/// Image writer: external images keep their uri, images with their bytes in memory become data
/// URIs (the bytes as they were, never re-encoded).
bool write_image_as_is(const std::string*, const std::string*, const tinygltf::Image* image, bool, std::string* out_uri,
                       void*) {
  if (!image->uri.empty()) {
    *out_uri = image->uri;
    return true;
  }
  if (image->image.empty()) return false;
  *out_uri = "data:" + (image->mimeType.empty() ? std::string("image/png") : image->mimeType) + ";base64," +
             base64(image->image);
  return true;
}

bool is_triangles(const Primitive& p) { return p.mode == -1 || p.mode == 4 || p.mode == 5 || p.mode == 6; }

/// A uri relative to the folder `from` rewritten relative to the folder `to` (data URIs and
/// absolute ones unchanged).
std::string rebase_uri(const std::string& uri, const fs::path& from, const fs::path& to) {
  if (uri.empty() || uri.rfind("data:", 0) == 0 || uri.find("://") != std::string::npos) return uri;
  const fs::path p(uri);
  if (p.is_absolute()) return uri;
  std::error_code ec;
  const fs::path target = fs::absolute(from.empty() ? fs::path(".") : from, ec) / p;
  const fs::path base = fs::absolute(to.empty() ? fs::path(".") : to, ec);
  if (ec) return uri;
  const fs::path rel = target.lexically_normal().lexically_relative(base.lexically_normal());
  return rel.empty() ? uri : rel.generic_string();
}

/// The values of accessor `index` as doubles, `components` per element (normalized integers
/// scaled to [0,1] or [-1,1]); every offset checked against the buffers.
std::vector<double> read_accessor(const std::string& path, const Model& m, int index, int& components,
                                  const char* what) {
  auto fail = [&](const std::string& problem) {
    throw IoError(path + ": glTF accessor " + std::to_string(index) + " (" + what + "): " + problem);
  };
  if (index < 0 || index >= static_cast<int>(m.accessors.size())) fail("does not exist");
  const Accessor& a = m.accessors[static_cast<std::size_t>(index)];
  if (a.sparse.isSparse) fail("sparse accessors are not supported");
  components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
  const int size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
  if (components <= 0 || components > 16 || size <= 0) fail("unknown type or component type");
  const std::size_t n = a.count;
  std::vector<double> out;
  if (a.bufferView < 0) {  // no data: zeros (glTF 2.0 §3.6.2.1)
    // Nothing in the file bounds the count: at most 2^24 values (128 MB).
    if (n > (std::size_t(1) << 24) / static_cast<std::size_t>(components))
      fail("count too large for an accessor without data");
    out.assign(n * static_cast<std::size_t>(components), 0.0);
    return out;
  }
  if (a.bufferView >= static_cast<int>(m.bufferViews.size())) fail("refers to a bufferView that does not exist");
  const tinygltf::BufferView& bv = m.bufferViews[static_cast<std::size_t>(a.bufferView)];
  if (bv.buffer < 0 || bv.buffer >= static_cast<int>(m.buffers.size())) fail("its bufferView has no buffer");
  const std::vector<unsigned char>& buf = m.buffers[static_cast<std::size_t>(bv.buffer)].data;
  const int stride = a.ByteStride(bv);
  if (stride <= 0) fail("invalid byteStride");
  const std::size_t elem = static_cast<std::size_t>(size) * static_cast<std::size_t>(components);
  if (bv.byteOffset > buf.size() || bv.byteLength > buf.size() - bv.byteOffset)
    fail("its bufferView runs past the end of its buffer (truncated file?)");
  if (n > 0) {
    const double last = static_cast<double>(a.byteOffset) + static_cast<double>(stride) * double(n - 1) + double(elem);
    if (last > static_cast<double>(bv.byteLength)) fail("runs past the end of its bufferView (truncated file?)");
  }
  out.resize(n * static_cast<std::size_t>(components));
  const unsigned char* base = buf.data() + bv.byteOffset + a.byteOffset;
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char* e = base + i * static_cast<std::size_t>(stride);
    for (int c = 0; c < components; ++c) {
      const unsigned char* p = e + static_cast<std::size_t>(c) * static_cast<std::size_t>(size);
      double v = 0;
      switch (a.componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
          float f;
          std::memcpy(&f, p, 4);
          v = f;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: {
          std::memcpy(&v, p, 8);
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
          v = a.normalized ? *p / 255.0 : *p;
          break;
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
          const auto s = static_cast<std::int8_t>(*p);
          v = a.normalized ? std::max(s / 127.0, -1.0) : s;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
          std::uint16_t u;
          std::memcpy(&u, p, 2);
          v = a.normalized ? u / 65535.0 : u;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
          std::int16_t s;
          std::memcpy(&s, p, 2);
          v = a.normalized ? std::max(s / 32767.0, -1.0) : s;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
          std::uint32_t u;
          std::memcpy(&u, p, 4);
          v = u;
          break;
        }
        case TINYGLTF_COMPONENT_TYPE_INT: {
          std::int32_t s;
          std::memcpy(&s, p, 4);
          v = s;
          break;
        }
        default:
          fail("unknown component type");
      }
      out[i * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)] = v;
    }
  }
  return out;
}

/// What is wrong with a GLB container, or "": a 12-byte header ("glTF", version 2, the length
/// of the whole, at most the bytes present), then chunks of an 8-byte header (length, type) and
/// that many bytes, each within the declared length. tinygltf 2.7.0 copies the binary chunk by
/// its declared length without checking it against the file (libFuzzer: a heap overread).
std::string glb_container_problem(std::string_view data) {
  auto u32 = [&](std::size_t at) {
    const auto* b = reinterpret_cast<const unsigned char*>(data.data() + at);
    return std::uint32_t(b[0]) | (std::uint32_t(b[1]) << 8) | (std::uint32_t(b[2]) << 16) | (std::uint32_t(b[3]) << 24);
  };
  if (data.size() < 12 || data.substr(0, 4) != "glTF") return "it does not start with a 12-byte 'glTF' header";
  if (u32(4) != 2) return "version " + std::to_string(u32(4)) + " (GLB 2 is read)";
  const std::size_t length = u32(8);
  if (length > data.size())
    return "the header declares " + std::to_string(length) + " bytes, but the file has " + std::to_string(data.size());
  int chunk = 0;
  for (std::size_t at = 12; at < length; ++chunk) {
    if (length - at < 8) return "chunk " + std::to_string(chunk) + " is cut short in its header";
    const std::size_t bytes = u32(at);
    if (bytes > length - at - 8)
      return "chunk " + std::to_string(chunk) + " declares " + std::to_string(bytes) + " bytes, but only " +
             std::to_string(length - at - 8) + " follow it";
    at += 8 + bytes;
  }
  return "";
}

/// Loads a glTF or GLB from memory; external buffers and images are looked up in `base_dir`.
Model load_model(const std::string& path, std::string_view data, bool glb, const std::string& base_dir,
                 std::string* warnings) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keep_image_bytes, nullptr);
  Model model;
  std::string err, warn;
  const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
  if (data.size() > std::numeric_limits<unsigned int>::max()) throw IoError(path + ": glTF file too large (> 4 GB)");
  if (glb) {
    const std::string problem = glb_container_problem(data);
    if (!problem.empty()) throw IoError(path + ": not a valid GLB file: " + problem);
  }
  const bool ok =
      glb ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes, static_cast<unsigned int>(data.size()), base_dir)
          : loader.LoadASCIIFromString(&model, &err, &warn, data.data(), static_cast<unsigned int>(data.size()),
                                       base_dir);
  auto first_line = [](std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    const std::size_t nl = s.find('\n');
    return nl == std::string::npos ? s : s.substr(0, nl) + " (...)";
  };
  if (!ok)
    throw IoError(path + ": not a valid " + (glb ? "GLB" : "glTF") +
                  " file: " + (err.empty() ? std::string("tinygltf could not parse it") : first_line(err)));
  if (warnings) *warnings = first_line(warn);
  for (const std::string& ext : model.extensionsRequired)
    if (ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression" || ext == "KHR_mesh_quantization")
      throw IoError(path + ": the glTF file requires the extension " + ext + ", which msmesh cannot read");
  return model;
}

struct Key {
  std::array<double, 3> p;
  bool operator==(const Key& o) const { return p == o.p; }
};
struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::size_t h = 0;
    for (double d : k.p) {
      std::uint64_t b;
      const double z = d + 0.0;  // -0 as +0
      std::memcpy(&b, &z, 8);
      h = h * 1000003u ^ std::hash<std::uint64_t>()(b);
    }
    return h;
  }
};

}  // namespace

void read_gltf(const std::string& path, std::string_view data, bool glb, Soup& soup) {
  const fs::path folder = fs::path(path).parent_path();
  std::string warn;
  Model model = load_model(path, data, glb, folder.empty() ? "." : folder.string(), &warn);
  if (!warn.empty()) soup.notes.dropped.push_back("glTF: " + warn);
  soup.extra.position_type = ScalarType::Float32;
  for (std::size_t i = 0; i < model.materials.size(); ++i)
    soup.extra.material_names.push_back(model.materials[i].name.empty() ? "material " + std::to_string(i)
                                                                        : model.materials[i].name);
  bool any_color = false, any_uv = false, any_normals = false, color4 = false, uv_finite = true;
  std::size_t skipped = 0, targets = 0;
  std::vector<std::string> other_attributes, prop_names;
  std::vector<std::vector<double>> prop_values;
  std::vector<std::vector<char>> prop_set;
  struct VertexData {
    std::array<double, 4> color{1, 1, 1, 1};
    std::array<double, 3> normal{0, 0, 0};
    bool has_color = false, has_normal = false, normal_conflict = false;
  };
  std::vector<VertexData> vd;
  std::size_t color_conflicts = 0;
  for (std::size_t mi = 0; mi < model.meshes.size(); ++mi) {
    const tinygltf::Mesh& mesh = model.meshes[mi];
    std::unordered_map<Key, std::size_t, KeyHash> weld;  // within one glTF mesh
    for (std::size_t pi = 0; pi < mesh.primitives.size(); ++pi) {
      const Primitive& prim = mesh.primitives[pi];
      if (!is_triangles(prim)) {
        ++skipped;
        continue;
      }
      const auto pos = prim.attributes.find("POSITION");
      if (pos == prim.attributes.end())
        throw IoError(path + ": glTF mesh " + std::to_string(mi) + " primitive " + std::to_string(pi) +
                      " has no POSITION attribute");
      int nc = 0;
      const std::vector<double> P = read_accessor(path, model, pos->second, nc, "POSITION");
      if (nc != 3) throw IoError(path + ": glTF POSITION accessor " + std::to_string(pos->second) + " is not VEC3");
      const std::size_t n = P.size() / 3;
      auto attribute = [&](const char* name, std::initializer_list<int> sizes, int& comps) {
        const auto it = prim.attributes.find(name);
        if (it == prim.attributes.end()) return std::vector<double>();
        std::vector<double> A = read_accessor(path, model, it->second, comps, name);
        if (std::find(sizes.begin(), sizes.end(), comps) == sizes.end() ||
            A.size() / static_cast<std::size_t>(comps) != n)
          throw IoError(path + ": glTF " + name + " accessor " + std::to_string(it->second) +
                        " has the wrong type or count for its primitive");
        return A;
      };
      int cn = 0, cc = 0, ct = 0;
      const std::vector<double> N = attribute("NORMAL", {3}, cn);
      const std::vector<double> C = attribute("COLOR_0", {3, 4}, cc);
      const std::vector<double> T = attribute("TEXCOORD_0", {2}, ct);
      // Application-specific scalar attributes ("_NAME", glTF 2.0 §3.7.2.1) are extra vertex
      // properties (as msmesh writes them).
      std::vector<std::pair<std::size_t, std::vector<double>>> props;  // (property slot, values)
      for (const auto& [name, acc] : prim.attributes) {
        if (name.size() > 1 && name[0] == '_' && acc >= 0 && acc < static_cast<int>(model.accessors.size()) &&
            model.accessors[static_cast<std::size_t>(acc)].type == TINYGLTF_TYPE_SCALAR) {
          int one = 0;
          std::vector<double> A = read_accessor(path, model, acc, one, name.c_str());
          if (A.size() != n) throw IoError(path + ": glTF " + name + " accessor has the wrong count for its primitive");
          const std::string pname = name.substr(1);
          auto at = std::find(prop_names.begin(), prop_names.end(), pname);
          if (at == prop_names.end()) {
            prop_names.push_back(pname);
            prop_values.emplace_back();
            prop_set.emplace_back();
            at = prop_names.end() - 1;
          }
          props.emplace_back(static_cast<std::size_t>(at - prop_names.begin()), std::move(A));
          continue;
        }
        if (name != "POSITION" && name != "NORMAL" && name != "COLOR_0" && name != "TEXCOORD_0" &&
            std::find(other_attributes.begin(), other_attributes.end(), name) == other_attributes.end())
          other_attributes.push_back(name);
      }
      targets += prim.targets.size();
      any_normals = any_normals || !N.empty();
      any_color = any_color || !C.empty();
      color4 = color4 || cc == 4;
      any_uv = any_uv || !T.empty();
      // Vertices: joined with earlier ones at the same position (within this mesh).
      std::vector<std::size_t> vertex(n);
      const std::size_t tc0 = soup.texcoord_table.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Key k{{P[3 * i], P[3 * i + 1], P[3 * i + 2]}};
        for (double x : k.p)
          if (!std::isfinite(x)) throw IoError(path + ": glTF POSITION has a non-finite coordinate");
        const auto [it, inserted] = weld.emplace(k, soup.points.size());
        if (inserted) {
          soup.points.emplace_back(k.p[0], k.p[1], k.p[2]);
          vd.emplace_back();
        }
        vertex[i] = it->second;
        VertexData& d = vd[it->second];
        if (!C.empty()) {
          std::array<double, 4> c{1, 1, 1, 1};
          for (int j = 0; j < cc; ++j) {
            const double x = C[i * cc + j];
            c[static_cast<std::size_t>(j)] = x >= 0 ? std::min(x, 1.0) : 0.0;  // NaN: 0
          }
          if (d.has_color && c != d.color) ++color_conflicts;
          if (!d.has_color) d.color = c, d.has_color = true;
        }
        if (!N.empty()) {
          const std::array<double, 3> nn{N[3 * i], N[3 * i + 1], N[3 * i + 2]};
          if (!std::isfinite(nn[0]) || !std::isfinite(nn[1]) || !std::isfinite(nn[2])) d.normal_conflict = true;
          if (d.has_normal && nn != d.normal) d.normal_conflict = true;
          if (!d.has_normal) d.normal = nn, d.has_normal = true;
        }
        if (!T.empty()) {
          uv_finite = uv_finite && std::isfinite(T[2 * i]) && std::isfinite(T[2 * i + 1]);
          soup.texcoord_table.push_back({T[2 * i], 1.0 - T[2 * i + 1]});
        }
      }
      for (auto& [slot, A] : props) {
        prop_values[slot].resize(soup.points.size(), 0.0);
        prop_set[slot].resize(soup.points.size(), 0);
        for (std::size_t i = 0; i < n; ++i)
          if (!prop_set[slot][vertex[i]]) prop_values[slot][vertex[i]] = A[i], prop_set[slot][vertex[i]] = 1;
      }
      // Faces.
      std::vector<std::size_t> idx;
      const auto ind = prim.indices;
      if (ind >= 0) {
        // glTF 2.0 §3.7.2.1: indices are unsigned bytes, shorts or ints, never floats or normalized.
        if (ind < static_cast<int>(model.accessors.size())) {
          const Accessor& ia = model.accessors[static_cast<std::size_t>(ind)];
          const int t = ia.componentType;
          if ((t != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && t != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
               t != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) ||
              ia.normalized)
            throw IoError(path + ": glTF indices accessor " + std::to_string(ind) +
                          " does not hold unsigned integers (componentType " + std::to_string(t) + ")");
        }
        int ic = 0;
        const std::vector<double> I = read_accessor(path, model, ind, ic, "indices");
        if (ic != 1) throw IoError(path + ": glTF indices accessor " + std::to_string(ind) + " is not SCALAR");
        idx.reserve(I.size());
        for (double x : I) {
          if (!(x >= 0 && x < static_cast<double>(n)))
            throw IoError(path + ": glTF mesh " + std::to_string(mi) + " primitive " + std::to_string(pi) + ": index " +
                          std::to_string(static_cast<long long>(x)) + " out of range [0, " + std::to_string(n) + ")");
          idx.push_back(static_cast<std::size_t>(x));
        }
      } else {
        idx.resize(n);
        for (std::size_t i = 0; i < n; ++i) idx[i] = i;
      }
      std::vector<std::array<std::size_t, 3>> tris;
      const int mode = prim.mode == -1 ? 4 : prim.mode;
      if (mode == 4) {
        for (std::size_t i = 0; i + 2 < idx.size(); i += 3) tris.push_back({idx[i], idx[i + 1], idx[i + 2]});
      } else if (mode == 5) {
        for (std::size_t i = 0; i + 2 < idx.size(); ++i)
          tris.push_back(i % 2 == 0 ? std::array<std::size_t, 3>{idx[i], idx[i + 1], idx[i + 2]}
                                    : std::array<std::size_t, 3>{idx[i + 1], idx[i], idx[i + 2]});
      } else {
        for (std::size_t i = 1; i + 1 < idx.size(); ++i) tris.push_back({idx[0], idx[i], idx[i + 1]});
      }
      const int group = static_cast<int>(soup.extra.group_names.size());
      std::string gname = mesh.name.empty() ? "mesh " + std::to_string(mi) : mesh.name;
      if (mesh.primitives.size() > 1) gname += " primitive " + std::to_string(pi);
      // A primitive msmesh wrote for a group has its name in extras.
      if (prim.extras.IsObject() && prim.extras.Has("name") && prim.extras.Get("name").IsString())
        gname = prim.extras.Get("name").Get<std::string>();
      soup.extra.group_names.push_back(gname);
      const int material =
          prim.material >= 0 && prim.material < static_cast<int>(model.materials.size()) ? prim.material : -1;
      for (const auto& t : tris) {
        Polygon& poly = soup.polygons.emplace_back();
        for (std::size_t k : t) {
          poly.push_back(vertex[k]);
          soup.corner_texcoord.push_back(T.empty() ? -1 : static_cast<long long>(tc0 + k));
        }
        soup.polygon_group.push_back(group);
        soup.polygon_material.push_back(material);
      }
    }
  }
  if (soup.points.empty()) throw IoError(path + ": the glTF file has no triangle meshes");
  const std::size_t nv = soup.points.size();
  if (any_color) {
    soup.rgb.resize(nv);
    for (std::size_t i = 0; i < nv; ++i) soup.rgb[i] = {vd[i].color[0], vd[i].color[1], vd[i].color[2]};
    if (color4) {
      soup.alpha.resize(nv);
      for (std::size_t i = 0; i < nv; ++i) soup.alpha[i] = vd[i].color[3];
    }
  }
  for (std::size_t k = 0; k < prop_names.size(); ++k) {
    prop_values[k].resize(nv, 0.0);
    soup.extra.vertex_properties.push_back(
        {prop_names[k], Eigen::Map<const Eigen::VectorXd>(prop_values[k].data(), static_cast<Eigen::Index>(nv)),
         ScalarType::Float32});
  }
  if (any_normals) {
    soup.notes.had_normals = true;
    bool per_vertex = true;
    for (const VertexData& d : vd) per_vertex = per_vertex && d.has_normal && !d.normal_conflict;
    if (per_vertex) {
      soup.normals.resize(nv);
      for (std::size_t i = 0; i < nv; ++i) soup.normals[i] = vd[i].normal;
    }
  }
  if (any_uv && !uv_finite)
    soup.notes.dropped.emplace_back("glTF texture coordinates with a non-finite value are not kept");
  if (!any_uv || !uv_finite) soup.corner_texcoord.clear(), soup.texcoord_table.clear();
  bool any_material = false;
  for (int m : soup.polygon_material) any_material = any_material || m >= 0;
  if (!any_material) soup.polygon_material.clear();
  if (skipped)
    soup.notes.dropped.push_back(std::to_string(skipped) +
                                 " glTF primitives of points or lines are not processed (kept in the document as "
                                 "they are when written to glTF)");
  if (targets) soup.notes.dropped.push_back(std::to_string(targets) + " glTF morph targets are not kept");
  if (!other_attributes.empty()) {
    std::string list;
    for (const std::string& a : other_attributes) list += (list.empty() ? "" : ", ") + a;
    soup.notes.dropped.push_back("glTF vertex attributes not kept: " + list);
  }
  if (color_conflicts)
    soup.notes.dropped.push_back(std::to_string(color_conflicts) +
                                 " glTF vertex copies at the same position had different colours; the first is kept");

  // The document: buffers in memory (one GLB), external image paths made relative to the
  // current folder (write_gltf makes them relative to the output's folder).
  for (tinygltf::Buffer& b : model.buffers) b.uri.clear();
  for (tinygltf::Image& im : model.images)
    if (!im.uri.empty()) im.uri = rebase_uri(im.uri, folder, fs::path("."));
  tinygltf::TinyGLTF writer;
  writer.SetImageWriter(write_image_as_is, nullptr);
  std::ostringstream doc;
  if (!writer.WriteGltfSceneToStream(&model, doc, false, true))
    throw IoError(path + ": the glTF document could not be kept (tinygltf failed to serialise it)");
  soup.extra.gltf_document = std::make_shared<const std::string>(doc.str());
}

// ---------------------------------------------------------------------------------------------
// Writing

namespace {

/// Appends `bytes` to `bin` (4-byte aligned) as a new bufferView of buffer 0; returns its index.
int add_view(Model& m, std::vector<unsigned char>& bin, const void* bytes, std::size_t size, int target) {
  while (bin.size() % 4) bin.push_back(0);
  tinygltf::BufferView v;
  v.buffer = 0;
  v.byteOffset = bin.size();
  v.byteLength = size;
  v.target = target;
  const auto* b = static_cast<const unsigned char*>(bytes);
  bin.insert(bin.end(), b, b + size);
  m.bufferViews.push_back(v);
  return static_cast<int>(m.bufferViews.size() - 1);
}

int add_accessor(Model& m, std::vector<unsigned char>& bin, const std::vector<float>& values, int type, int comps,
                 bool min_max) {
  Accessor a;
  a.bufferView = add_view(m, bin, values.data(), values.size() * 4, TINYGLTF_TARGET_ARRAY_BUFFER);
  a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  a.type = type;
  a.count = values.size() / static_cast<std::size_t>(comps);
  if (min_max) {
    a.minValues.assign(static_cast<std::size_t>(comps), std::numeric_limits<double>::infinity());
    a.maxValues.assign(static_cast<std::size_t>(comps), -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < values.size(); ++i) {
      const std::size_t c = i % static_cast<std::size_t>(comps);
      a.minValues[c] = std::min(a.minValues[c], double(values[i]));
      a.maxValues[c] = std::max(a.maxValues[c], double(values[i]));
    }
  }
  m.accessors.push_back(a);
  return static_cast<int>(m.accessors.size() - 1);
}

/// Sets the geometry of `prim` to the faces `faces` of `mesh` (new accessors in `m`).
void set_geometry(Model& m, std::vector<unsigned char>& bin, const Mesh& mesh, const std::vector<int>& faces,
                  Primitive& prim) {
  const bool corner = mesh.face_texcoords.size() > 0, vuv = !corner && mesh.uv.size() > 0;
  const bool colors = mesh.vertex_colors.size() > 0, normals = mesh.vertex_normals.size() > 0;
  const int cc = static_cast<int>(mesh.vertex_colors.cols());
  std::map<std::pair<int, int>, std::uint32_t> out_vertex;  // (vertex, texcoord) -> output vertex
  std::vector<float> P, N, C, T;
  std::vector<std::vector<float>> X(mesh.vertex_properties.size());
  std::vector<std::uint32_t> I;
  for (int f : faces)
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.F(f, k), t = corner ? mesh.face_texcoords(f, k) : -1;
      const auto [it, inserted] = out_vertex.emplace(std::make_pair(v, t), static_cast<std::uint32_t>(P.size() / 3));
      if (inserted) {
        for (int c = 0; c < 3; ++c) P.push_back(static_cast<float>(mesh.V(v, c)));
        if (normals)
          for (int c = 0; c < 3; ++c) N.push_back(static_cast<float>(mesh.vertex_normals(v, c)));
        if (colors)
          for (int c = 0; c < cc; ++c) C.push_back(static_cast<float>(std::clamp(mesh.vertex_colors(v, c), 0.0, 1.0)));
        for (std::size_t p = 0; p < X.size(); ++p)
          X[p].push_back(static_cast<float>(mesh.vertex_properties[p].values(v)));
        if (corner || vuv) {
          const double u = corner ? (t >= 0 ? mesh.texcoords(t, 0) : 0.0) : mesh.uv(v, 0);
          const double w = corner ? (t >= 0 ? mesh.texcoords(t, 1) : 0.0) : mesh.uv(v, 1);
          T.push_back(static_cast<float>(u));
          T.push_back(static_cast<float>(1.0 - w));
        }
      }
      I.push_back(it->second);
    }
  prim.attributes.clear();
  prim.targets.clear();
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  prim.attributes["POSITION"] = add_accessor(m, bin, P, TINYGLTF_TYPE_VEC3, 3, true);
  if (normals) prim.attributes["NORMAL"] = add_accessor(m, bin, N, TINYGLTF_TYPE_VEC3, 3, false);
  if (colors)
    prim.attributes["COLOR_0"] = add_accessor(m, bin, C, cc == 4 ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3, cc, false);
  if (!T.empty()) prim.attributes["TEXCOORD_0"] = add_accessor(m, bin, T, TINYGLTF_TYPE_VEC2, 2, false);
  // Extra vertex properties as application-specific attributes "_NAME" (float32).
  for (std::size_t p = 0; p < X.size(); ++p)
    prim.attributes["_" + mesh.vertex_properties[p].name] = add_accessor(m, bin, X[p], TINYGLTF_TYPE_SCALAR, 1, false);
  Accessor a;
  a.bufferView = add_view(m, bin, I.data(), I.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  a.type = TINYGLTF_TYPE_SCALAR;
  a.count = I.size();
  m.accessors.push_back(a);
  prim.indices = static_cast<int>(m.accessors.size() - 1);
}

/// The source document with its triangle primitives' geometry replaced by `mesh`'s faces, the
/// old geometry removed, and every other bufferView copied into one new buffer.
Model replace_geometry(const std::string& path, const Mesh& mesh) {
  const std::string& doc = *mesh.gltf_document;
  Model src = load_model(path, doc, true, "", nullptr);
  // Triangle primitives, in the order read_gltf made groups of them.
  std::vector<std::pair<std::size_t, std::size_t>> prims;
  for (std::size_t mi = 0; mi < src.meshes.size(); ++mi)
    for (std::size_t pi = 0; pi < src.meshes[mi].primitives.size(); ++pi)
      if (is_triangles(src.meshes[mi].primitives[pi])) prims.emplace_back(mi, pi);
  std::vector<std::vector<int>> faces(prims.size());
  const bool groups = mesh.face_groups.size() == mesh.F.rows() && mesh.group_names.size() == prims.size();
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const int g = groups && mesh.face_groups(f) >= 0 ? mesh.face_groups(f) : 0;
    if (!prims.empty()) faces[static_cast<std::size_t>(g)].push_back(static_cast<int>(f));
  }
  Model out = src;
  out.accessors.clear();
  out.bufferViews.clear();
  out.buffers.assign(1, tinygltf::Buffer());
  std::vector<unsigned char> bin;
  // Accessors and bufferViews still used by what is kept (other primitives, skins, animations,
  // images), copied with their indices remapped.
  std::vector<int> view_map(src.bufferViews.size(), -1), accessor_map(src.accessors.size(), -1);
  auto view = [&](int v) {
    if (v < 0 || v >= static_cast<int>(src.bufferViews.size())) return -1;
    if (view_map[static_cast<std::size_t>(v)] >= 0) return view_map[static_cast<std::size_t>(v)];
    const tinygltf::BufferView& bv = src.bufferViews[static_cast<std::size_t>(v)];
    if (bv.buffer < 0 || bv.buffer >= static_cast<int>(src.buffers.size())) return -1;
    const auto& data = src.buffers[static_cast<std::size_t>(bv.buffer)].data;
    if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset) return -1;
    const int nv = add_view(out, bin, data.data() + bv.byteOffset, bv.byteLength, bv.target);
    tinygltf::BufferView& copy = out.bufferViews[static_cast<std::size_t>(nv)];
    copy.byteStride = bv.byteStride;
    copy.name = bv.name;
    copy.extras = bv.extras;
    return view_map[static_cast<std::size_t>(v)] = nv;
  };
  auto accessor = [&](int a) {
    if (a < 0 || a >= static_cast<int>(src.accessors.size())) return -1;
    if (accessor_map[static_cast<std::size_t>(a)] >= 0) return accessor_map[static_cast<std::size_t>(a)];
    Accessor copy = src.accessors[static_cast<std::size_t>(a)];
    copy.bufferView = view(copy.bufferView);
    if (copy.sparse.isSparse) {
      copy.sparse.indices.bufferView = view(copy.sparse.indices.bufferView);
      copy.sparse.values.bufferView = view(copy.sparse.values.bufferView);
    }
    out.accessors.push_back(copy);
    return accessor_map[static_cast<std::size_t>(a)] = static_cast<int>(out.accessors.size() - 1);
  };
  std::vector<std::vector<bool>> replaced(src.meshes.size());
  for (std::size_t mi = 0; mi < src.meshes.size(); ++mi) replaced[mi].assign(src.meshes[mi].primitives.size(), false);
  for (const auto& [mi, pi] : prims) replaced[mi][pi] = true;
  for (std::size_t mi = 0; mi < src.meshes.size(); ++mi)
    for (std::size_t pi = 0; pi < src.meshes[mi].primitives.size(); ++pi) {
      if (replaced[mi][pi]) continue;
      Primitive& p = out.meshes[mi].primitives[pi];
      for (auto& [name, a] : p.attributes) a = accessor(a);
      p.indices = accessor(p.indices);
      for (auto& target : p.targets)
        for (auto& [name, a] : target) a = accessor(a);
    }
  for (tinygltf::Skin& s : out.skins) s.inverseBindMatrices = accessor(s.inverseBindMatrices);
  for (tinygltf::Animation& an : out.animations)
    for (tinygltf::AnimationSampler& s : an.samplers) s.input = accessor(s.input), s.output = accessor(s.output);
  for (tinygltf::Image& im : out.images)
    if (im.bufferView >= 0) im.bufferView = view(im.bufferView);
  // The new geometry. A primitive left without faces is removed (its mesh keeps the others).
  for (std::size_t g = 0; g < prims.size(); ++g) {
    const auto [mi, pi] = prims[g];
    if (!faces[g].empty()) set_geometry(out, bin, mesh, faces[g], out.meshes[mi].primitives[pi]);
  }
  for (std::size_t mi = 0; mi < out.meshes.size(); ++mi) {
    auto& ps = out.meshes[mi].primitives;
    std::vector<Primitive> kept;
    for (std::size_t pi = 0; pi < ps.size(); ++pi) {
      const auto it = std::find(prims.begin(), prims.end(), std::make_pair(mi, pi));
      if (it == prims.end() || !faces[static_cast<std::size_t>(it - prims.begin())].empty()) kept.push_back(ps[pi]);
    }
    if (!kept.empty()) ps = std::move(kept);
  }
  out.buffers[0].data = std::move(bin);
  return out;
}

/// A new document for a mesh that did not come from glTF: one mesh, one primitive per group and
/// material (the group's name in the primitive's extras, as {"name": ...}).
Model new_document(const Mesh& mesh) {
  Model out;
  out.asset.version = "2.0";
  out.asset.generator = "msmesh";
  out.buffers.assign(1, tinygltf::Buffer());
  std::vector<unsigned char> bin;
  for (const std::string& name : mesh.material_names) {
    tinygltf::Material mat;
    mat.name = name;
    out.materials.push_back(mat);
  }
  std::map<std::pair<int, int>, std::vector<int>> parts;  // (group, material) -> faces
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f)
    parts[{mesh.face_groups.size() ? mesh.face_groups(f) : -1,
           mesh.face_materials.size() ? mesh.face_materials(f) : -1}]
        .push_back(static_cast<int>(f));
  tinygltf::Mesh gm;
  gm.name = "msmesh";
  for (const auto& [key, faces] : parts) {
    Primitive p;
    set_geometry(out, bin, mesh, faces, p);
    p.material = key.second;
    if (key.first >= 0) {
      tinygltf::Value::Object extras;
      extras["name"] = tinygltf::Value(mesh.group_names[static_cast<std::size_t>(key.first)]);
      p.extras = tinygltf::Value(extras);
    }
    gm.primitives.push_back(p);
  }
  out.meshes.push_back(gm);
  tinygltf::Node node;
  node.mesh = 0;
  out.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  out.scenes.push_back(scene);
  out.defaultScene = 0;
  out.buffers[0].data = std::move(bin);
  return out;
}

}  // namespace

void write_gltf(OutBuffer& o, const Mesh& mesh, bool glb, const std::string& path) {
  if (mesh.F.rows() == 0) throw InvalidInput(path + ": cannot write a glTF without faces");
  Model model = mesh.gltf_document ? replace_geometry(path, mesh) : new_document(mesh);
  // External images: paths relative to the current folder (read_gltf) made relative to the output's.
  const fs::path out_dir = fs::path(path).parent_path();
  for (tinygltf::Image& im : model.images)
    if (!im.uri.empty()) im.uri = rebase_uri(im.uri, fs::path("."), out_dir);
  tinygltf::TinyGLTF writer;
  writer.SetImageWriter(write_image_as_is, nullptr);
  std::ostringstream s;
  if (!writer.WriteGltfSceneToStream(&model, s, !glb, glb))
    throw IoError(path + ": tinygltf failed to write the glTF document");
  o.text(s.str());
}

}  // namespace msmesh::io_detail
