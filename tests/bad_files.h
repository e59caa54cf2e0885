// Broken mesh files, each with the problem its error message must name: read through the
// library (test_read_mesh.cpp, BrokenFiles.*) and through the CLI (cli/test_broken_files_cli.cpp).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace msmesh::test {

struct BadFile {
  const char* name;     ///< file name (the extension picks the reader)
  std::string content;  ///< file bytes
  const char* problem;  ///< expected in the message
};

inline std::string binary_ply_header(const std::string& counts) {
  return "ply\nformat binary_little_endian 1.0\n" + counts +
         "property float x\nproperty float y\nproperty float z\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
}

inline std::vector<BadFile> bad_files() {
  std::vector<BadFile> c;
  const std::string tet_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  c.push_back({"nofaces.obj", tet_obj, "no faces"});
  c.push_back({"nofaces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", "no faces"});
  c.push_back({"nofaces.ply",
               "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
               "property float z\nend_header\n0 0 0\n1 0 0\n0 1 0\n",
               "no faces"});
  c.push_back({"novertices.off", "OFF\n0 0 0\n", "no vertices"});
  c.push_back({"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "non-finite"});
  c.push_back({"inf.off", "OFF\n3 1 0\n0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n", "non-finite"});
  c.push_back({"nan.ply",
               "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
               "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
               "0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n",
               "non-finite"});
  c.push_back({"oob.obj", tet_obj + "f 1 2 5\n", "refers to vertex 5"});
  c.push_back({"oob.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "refers to vertex 3"});
  c.push_back({"oob.ply",
               "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
               "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
               "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
               "refers to vertex 7"});
  c.push_back({"huge.ply", binary_ply_header("element vertex 1000000000000\n") + std::string(60, '\0'),
               "header declares 1000000000000 vertex"});
  c.push_back({"huge.off", "OFF\n2000000000 1 0\n0 0 0\n", "header declares 2000000000 vertices"});
  {
    std::string stl(80, ' ');
    const std::uint32_t n = 4000000000u;
    stl.append(reinterpret_cast<const char*>(&n), 4);
    stl.append(50, '\0');
    c.push_back({"huge.stl", stl, "header declares 4000000000 triangles"});
  }
  {
    std::string ply = binary_ply_header("element vertex 3\n");
    for (int i = 0; i < 5; ++i) ply.append(4, '\0');  // 5 of 9 floats
    c.push_back({"truncated.ply", ply, "truncated"});
    std::string stl(80, ' ');
    const std::uint32_t n = 2;
    stl.append(reinterpret_cast<const char*>(&n), 4);
    stl.append(70, '\0');  // 1.4 of 2 triangles
    c.push_back({"truncated.stl", stl, "truncated"});
    c.push_back({"truncated.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n", "truncated"});
  }
  c.push_back({"magic.ply", "plx\nformat ascii 1.0\nend_header\n", "not a PLY file"});
  c.push_back({"magic.off", "FOO\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "not an OFF file"});
  c.push_back({"magic.stl", "this is not an stl", "not an STL file"});
  c.push_back({"empty.obj", "", "empty file"});
  c.push_back({"garbage.obj", "v 0 0 0\nv 1 0\nf 1 2 3\n", "fewer than 3 coordinates"});
  c.push_back({"mesh.xyz", "0 0 0\n", "unknown mesh format"});
  return c;
}

}  // namespace msmesh::test
