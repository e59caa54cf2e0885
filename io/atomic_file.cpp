// Atomic file output: write to a new temporary file in the target's folder, flush it to disk,
// then rename it over the target. rename(2) within one folder is atomic, so readers see the
// old file or the complete new one, never a partial write.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include "msmesh/errors.h"
#include "msmesh/atomic_file.h"

namespace msmesh {
namespace {

namespace fs = std::filesystem;

std::string errno_message(int err) { return std::strerror(err); }

/// Creates a new, empty temporary file next to `target` and returns its path. The name is
/// reserved with O_EXCL so concurrent writers (threads or processes) never share one; the
/// mode 0666 lets the umask decide the final permissions, as for a plain ofstream.
fs::path create_temporary_sibling(const std::string& path) {
  static std::atomic<unsigned> counter{0};
  const fs::path target(path);
  if (target.filename().empty()) throw IoError(path + ": not a file name");
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::random_device rd;
  for (int attempt = 0; attempt < 16; ++attempt) {
    const fs::path tmp = dir / ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                                std::to_string(counter++) + "-" + std::to_string(rd() % 1000000));
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      ::close(fd);
      return tmp;
    }
    if (errno != EEXIST)
      throw IoError(path + ": cannot create a temporary file in '" + dir.string() + "': " + errno_message(errno));
  }
  throw IoError(path + ": cannot create a unique temporary file in '" + dir.string() + "'");
}

/// fsync so that after a crash the renamed file has its content, not zero length.
bool sync_to_disk(const fs::path& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0;
  ::close(fd);
  return ok;
}

}  // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill) {
  {
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw IoError(path + ": is a directory");
  }
  const fs::path tmp = create_temporary_sibling(path);
  auto discard = [&tmp] {
    std::error_code ec;
    fs::remove(tmp, ec);
  };
  try {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw IoError(path + ": cannot open temporary file '" + tmp.string() + "' for writing");
    fill(out);
    out.flush();
    if (!out) throw IoError(path + ": write failed (disk full or I/O error)");
    out.close();
    if (out.fail()) throw IoError(path + ": write failed while closing the file");
    if (!sync_to_disk(tmp)) throw IoError(path + ": cannot flush the file to disk: " + errno_message(errno));
    std::error_code ec;
    fs::rename(tmp, path, ec);
    if (ec) throw IoError(path + ": cannot rename the temporary file into place: " + ec.message());
  } catch (...) {
    discard();
    throw;
  }
}

void write_text_file(const std::string& path, const std::string& text) {
  write_file_atomically(path, [&text](std::ostream& out) { out.write(text.data(), std::streamsize(text.size())); });
}

}  // namespace msmesh
