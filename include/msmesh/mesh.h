// The mesh type: plain Eigen data, as in libigl, with the attributes mesh files carry.
#pragma once
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

namespace msmesh {

/// The scalar type a value had in its file, so that a writer can store it the same way
/// (a float32 PLY stays float32). Values are held as double in memory whatever the type.
enum class ScalarType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

/// One extra per-vertex scalar property of a file (PLY `quality`, `intensity`, a scanner's
/// `value`, ...): its name, #V values and the type it was stored with.
struct VertexProperty {
  std::string name;
  Eigen::VectorXd values;
  ScalarType type = ScalarType::Float64;
};

/// A triangle mesh and its attributes. Every attribute is optional: empty (0 rows) when the
/// file does not have it. Attributes with #V rows follow the vertices, those with #F rows the
/// faces; the processing commands keep them consistent (mesh_attributes.h).
///  - V: #V by 3 vertex positions.
///  - F: #F by 3 vertex indices, counter-clockwise seen from outside.
///  - vertex_colors: #V by 3 (RGB) or #V by 4 (RGBA), components in [0,1].
///  - uv: #V by 2 per-vertex texture coordinates (origin at the bottom left, as in OBJ and PLY).
///  - vertex_normals: #V by 3; filled when the file has normals. Commands that move vertices
///    recompute them (geometry.h vertex_normals) so that they match the result.
///  - face_colors: #F by 3 (RGB) or #F by 4 (RGBA), components in [0,1] (PLY face colours, e.g.
///    those `msmesh segment` writes).
///  - texcoords, face_texcoords: per-corner texture coordinates, for textures with seams (one
///    vertex, several uv): texcoords is a #T by 2 table and face_texcoords #F by 3 indices into
///    it, one per corner of each face (−1: that corner has none, e.g. a face added by hole
///    filling). When a file's texture coordinates are per-vertex they fill `uv` instead.
///  - material_libraries: OBJ `mtllib` file names as written in the file (relative to its folder).
///  - material_names, face_materials: material names (OBJ `usemtl`, glTF material names) and #F
///    indices into them (−1: no material).
///  - group_names, face_groups: OBJ `g` groups (glTF: one group per source primitive) and #F
///    indices into them (−1: none). object_names, face_objects: the same for OBJ `o` objects.
///  - vertex_properties: extra per-vertex scalars (PLY), each with #V values.
///  - position_type: the scalar type of the file's coordinates (Float32 for a float PLY or a
///    glTF); a writer that can choose stores them the same way. An STL input keeps the default
///    Float64 (STL itself can only store float).
///  - gltf_document: the source glTF document (a GLB in memory: materials, textures, images,
///    nodes, everything but the geometry that V and F replace), kept so that writing a glTF
///    gives back the same scene with the processed geometry. Shared, never modified.
struct Mesh {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  Eigen::MatrixXd vertex_colors;
  Eigen::MatrixXd uv;
  Eigen::MatrixXd vertex_normals;
  Eigen::MatrixXd face_colors;
  Eigen::MatrixXd texcoords;
  Eigen::MatrixXi face_texcoords;
  std::vector<std::string> material_libraries;
  std::vector<std::string> material_names;
  Eigen::VectorXi face_materials;
  std::vector<std::string> group_names;
  Eigen::VectorXi face_groups;
  std::vector<std::string> object_names;
  Eigen::VectorXi face_objects;
  std::vector<VertexProperty> vertex_properties;
  ScalarType position_type = ScalarType::Float64;
  std::shared_ptr<const std::string> gltf_document;

  Eigen::Index num_vertices() const { return V.rows(); }
  Eigen::Index num_faces() const { return F.rows(); }
};

/// Throws InvalidInput (message prefixed by `what`, e.g. a file name) unless V is #V by 3
/// with finite values, F is #F by 3 with indices in [0, #V), and no face repeats a vertex.
/// Zero-area faces and non-manifold configurations are accepted (the operators handle them).
void validate_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const std::string& what = "mesh");

/// Throws InvalidInput (message prefixed by `what`) unless every attribute of `mesh` is empty
/// or has the shape documented above (rows matching V or F, indices in range or −1).
void validate_attributes(const Mesh& mesh, const std::string& what = "mesh");

/// Lower-case name of a scalar type as PLY writes it ("uchar", "float", ...).
const char* scalar_type_name(ScalarType type);

}  // namespace msmesh
