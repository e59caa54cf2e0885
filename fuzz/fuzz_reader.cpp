// libFuzzer target for one mesh reader: the bytes are read as a file of format
// MSMESH_FUZZ_FORMAT ("obj", "off", "ply", "stl", "gltf", "glb", or "obj.gz": gzip inflated
// then read as OBJ; a compile definition, one program per format). A reader may refuse the
// input with IoError or InvalidInput; anything else (another exception, a crash, a sanitizer
// report, a hang, a mesh that breaks read_mesh's promises) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "mesh_check.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"

#ifndef MSMESH_FUZZ_FORMAT
#error "MSMESH_FUZZ_FORMAT must name the format"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const msmesh::Mesh mesh = msmesh::read_mesh_from_memory(bytes, MSMESH_FUZZ_FORMAT, "fuzz." MSMESH_FUZZ_FORMAT);
    const std::string problem = msmesh::fuzz::mesh_problem(mesh);
    if (!problem.empty()) {
      std::fprintf(stderr, "read_mesh returned an invalid mesh: %s\n", problem.c_str());
      std::abort();
    }
  } catch (const msmesh::IoError&) {
  } catch (const msmesh::InvalidInput&) {
  }
  return 0;
}
