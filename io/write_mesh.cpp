// write_mesh: the checks before writing and the writer of the path's format (write_obj.cpp,
// write_off.cpp, write_ply.cpp, write_stl.cpp, write_gltf.cpp), through write_file_atomically,
// gzip-compressed for `.gz` paths; unsupported_attributes.
#include "msmesh/write_mesh.h"

#include <Eigen/Core>
#include <cmath>
#include <ostream>
#include <sstream>
#include <string>

#include "gzip.h"
#include "msmesh/atomic_file.h"
#include "msmesh/errors.h"
#include "msmesh/mesh_format.h"
#include "write_common.h"

namespace msmesh {
namespace io_detail {

void check_for_writing(const std::string& path, const Mesh& mesh) {
  const Eigen::MatrixXd& V = mesh.V;
  const Eigen::MatrixXi& F = mesh.F;
  auto fail = [&path](const std::string& what) { throw InvalidInput(path + ": cannot write mesh: " + what); };
  if (V.cols() != 3)
    fail("vertex array must be #V by 3, got " + std::to_string(V.rows()) + " by " + std::to_string(V.cols()));
  if (F.rows() > 0 && F.cols() != 3)
    fail("face array must be #F by 3, got " + std::to_string(F.rows()) + " by " + std::to_string(F.cols()));
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(V(i, c))) fail("vertex " + std::to_string(i) + " has a non-finite coordinate");
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (F(f, k) < 0 || F(f, k) >= V.rows())
        fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(F(f, k)) + ", out of range [0, " +
             std::to_string(V.rows()) + ")");
  try {
    validate_attributes(mesh, path + ": cannot write mesh");
  } catch (const InvalidInput&) {
    throw;
  }
  for (const VertexProperty& p : mesh.vertex_properties)
    for (char c : p.name)
      if (std::isspace(static_cast<unsigned char>(c)))
        fail("vertex property name '" + p.name + "' contains whitespace");
}

}  // namespace io_detail

using namespace io_detail;  // the writers' shared pieces (write_common.h)

void write_mesh(const std::string& path, const Mesh& mesh, const WriteOptions& options) {
  const std::string format = mesh_format_from_path(path);
  check_for_writing(path, mesh);
  auto fill = [&](std::ostream& out) {
    OutBuffer o(out);
    if (format == "obj")
      write_obj(o, mesh, path);
    else if (format == "off")
      write_off(o, mesh);
    else if (format == "ply")
      write_ply(o, mesh, options.binary, nullptr);
    else if (format == "stl")
      write_stl(o, mesh, options.binary, path);
    else
      write_gltf(o, mesh, format == "glb", path);
    o.finish();
  };
  if (!is_gzip_path(path)) {
    write_file_atomically(path, fill);
    return;
  }
  std::ostringstream plain;
  fill(plain);
  const std::string packed = gzip(plain.str(), path);
  write_file_atomically(
      path, [&](std::ostream& out) { out.write(packed.data(), static_cast<std::streamsize>(packed.size())); });
}

std::vector<std::string> unsupported_attributes(const Mesh& m, const std::string& path) {
  const std::string format = mesh_format_from_path(path);
  const bool obj = format == "obj", off = format == "off", ply = format == "ply", stl = format == "stl";
  const bool gltf = format == "gltf" || format == "glb";
  const std::string name = gltf ? "glTF" : obj ? "OBJ" : off ? "OFF" : ply ? "PLY" : "STL";
  std::vector<std::string> out;
  auto lost = [&](bool has, bool kept, const std::string& what) {
    if (has && !kept) out.push_back(name + " cannot hold " + what + ": not written");
  };
  lost(m.vertex_colors.size() > 0, !stl, "vertex colours");
  lost(m.vertex_colors.cols() == 4, ply || gltf, "vertex alpha");
  lost(m.uv.size() > 0 || m.face_texcoords.size() > 0, obj || ply || gltf, "texture coordinates");
  lost(m.vertex_normals.size() > 0, obj || ply || gltf, "vertex normals (readers recompute them)");
  lost(m.face_colors.size() > 0, ply, "face colours");
  lost(!m.material_libraries.empty(), obj, "material libraries (mtllib)");
  lost(m.face_materials.size() > 0, obj || gltf, "materials per face");
  lost(m.face_groups.size() > 0, obj || gltf, "groups");
  lost(m.face_objects.size() > 0, obj, "objects ('o')");
  if (!m.vertex_properties.empty() && !ply && !gltf) {
    std::string names;
    for (std::size_t k = 0; k < m.vertex_properties.size(); ++k)
      names += (k ? ", '" : "'") + m.vertex_properties[k].name + "'";
    out.push_back(name + " cannot hold extra vertex properties (" + names + "): not written");
  }
  lost(static_cast<bool>(m.gltf_document), gltf, "the glTF scene (its materials, textures and nodes)");
  return out;
}

}  // namespace msmesh
