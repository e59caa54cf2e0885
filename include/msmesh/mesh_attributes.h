// Carrying a mesh's attributes (colours, texture coordinates, materials, groups, properties:
// mesh.h) over to a mesh made from it, when processing adds, removes or reorders vertices and
// faces (repair, inpainting, hole punching, segment parts).
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "msmesh/mesh.h"

namespace msmesh {

/// Fills the attributes of `result` (whose V and F are set) from `source`. Vertex i of the
/// result comes from source vertex vertex_origin(i), face f from source face face_origin(f);
/// −1 marks a new vertex or face. `flipped` (empty or #F of result) marks faces whose corners
/// 1 and 2 were swapped relative to their source face (reoriented). Then:
///  - per-vertex attributes (colours, uv, normals, extra properties) follow their vertices;
///    a new vertex takes the values of the nearest source vertex (fewest edges away);
///  - per-face attributes (colours, material, group, object) follow their faces; a new face
///    takes those of the nearest source face (fewest shared edges away);
///  - texture coordinates follow the corners of source faces; new faces get none (−1 in
///    face_texcoords): per-vertex uv becomes per-corner (texcoords, face_texcoords) when a new
///    face or a merged vertex keeps it from being per-vertex;
///  - names, material libraries, position type and the glTF document are copied.
/// Returns one note per attribute that was invented or dropped (empty when none), e.g.
/// "12 new faces have no texture coordinates".
std::vector<std::string> carry_attributes(const Mesh& source, Mesh& result, const Eigen::VectorXi& vertex_origin,
                                          const Eigen::VectorXi& face_origin, const std::vector<bool>& flipped = {});

/// Copies the attributes that belong to the whole file rather than to vertices or faces: the
/// material libraries, the material, group and object names, the position type and the glTF
/// document (carry_attributes does this too).
void copy_document_attributes(const Mesh& source, Mesh& result);

/// True when `mesh` has any attribute besides V and F.
bool has_attributes(const Mesh& mesh);

/// Per-corner texture coordinates turned per-vertex (mesh.uv) when every corner of each vertex
/// names the same coordinates and none is missing; returns whether it did (and leaves the mesh
/// unchanged when not). Unreferenced vertices keep their row of mesh.uv when it has #V rows, else
/// get (0, 0).
bool corner_uv_to_vertex_uv(Mesh& mesh);

}  // namespace msmesh
