// Atomic file output (library msmesh_io): every file msmesh writes appears completely or not
// at all.
#pragma once
#include <functional>
#include <iosfwd>
#include <string>

namespace msmesh {

/// Writes `text` to `path` atomically (temporary file, then rename).
void write_text_file(const std::string& path, const std::string& text);

/// Writes `path` atomically: `fill` writes the content to a stream on a new temporary file in
/// the same folder, which is flushed to disk and renamed over `path`. When anything fails
/// (including an exception thrown by `fill`, which is rethrown) the temporary file is removed
/// and `path` is left as it was. Throws IoError naming `path` for file-system failures.
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill);

}  // namespace msmesh
