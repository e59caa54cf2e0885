// The mesh format a path names, by its extension (shared by reading and writing).
#include "msmesh/mesh_format.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

#include "msmesh/errors.h"
#include "read_text.h"

namespace msmesh {

using io_detail::quote_word;

namespace {

std::string lower_extension(const std::filesystem::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

bool is_gzip_path(const std::string& path) { return lower_extension(std::filesystem::path(path)) == ".gz"; }

std::string mesh_format_from_path(const std::string& path) {
  std::filesystem::path p(path);
  const bool gz = is_gzip_path(path);
  if (gz) p = p.stem();  // "m.ply.gz" -> "m.ply"
  const std::string ext = lower_extension(p);
  if (ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl" || ext == ".gltf" || ext == ".glb")
    return ext.substr(1);
  const std::string shown = ext.empty() ? std::string("(no extension)") : quote_word(ext);
  throw IoError(path + ": unknown mesh format " + (gz ? shown + " under .gz" : shown) +
                "; expected .obj, .off, .ply, .stl, .gltf or .glb, optionally followed by .gz");
}

}  // namespace msmesh
