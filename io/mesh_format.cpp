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

std::string mesh_format_from_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl") return ext.substr(1);
  throw IoError(path + ": unknown mesh format " + (ext.empty() ? std::string("(no extension)") : quote_word(ext)) +
                "; expected .obj, .off, .ply or .stl");
}

}  // namespace msmesh
