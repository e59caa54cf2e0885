// A program built against the installed msmesh package (find_package(msmesh), targets
// msmesh::core and msmesh::io): reads a mesh, denoises it as `msmesh denoise` does (preset
// "auto", with its second round under heavy noise), writes the result.
//   msmesh_consumer noisy.obj denoised.obj
#include <msmesh/denoise.h>
#include <msmesh/errors.h>
#include <msmesh/geometry.h>
#include <msmesh/io.h>
#include <msmesh/presets.h>
#include <msmesh/second_round.h>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: msmesh_consumer INPUT OUTPUT\n";
    return 2;
  }
  try {
    msmesh::Mesh mesh = msmesh::read_mesh(argv[1]);
    const msmesh::ResolvedPreset preset = msmesh::resolve_preset("auto", mesh.V, mesh.F);
    const msmesh::DenoiseResult result = msmesh::denoise_in_rounds(mesh.V, mesh.F, preset, preset.options, {});
    mesh.V = result.V;
    if (mesh.vertex_normals.rows() > 0) mesh.vertex_normals = msmesh::vertex_normals(mesh.V, mesh.F);
    msmesh::write_mesh(argv[2], mesh);
    std::cout << argv[2] << ": " << mesh.num_vertices() << " vertices, " << mesh.num_faces() << " faces, preset "
              << preset.preset << ", " << result.normal_report.iterations << " normal iterations\n";
  } catch (const msmesh::Error& e) {
    std::cerr << "msmesh_consumer: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
