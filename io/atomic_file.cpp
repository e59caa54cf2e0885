// Atomic file output: write to a new temporary file in the target's folder, flush it to disk,
// then rename it over the target. rename(2) within one folder is atomic, so readers see the
// old file or the complete new one, never a partial write. Devices and FIFOs cannot be renamed
// over (that would replace /dev/null by a regular file): their content is staged in an
// anonymous file and copied into them once complete. An OutputTransaction keeps every staged
// output until its commit(), so the outputs of a run appear together or not at all.
//
// The temporary files alive at any moment are listed in a registry a signal handler can read
// (a linked list of fixed-size slots that are never freed, published with atomic stores), so
// SIGINT, SIGTERM, ... remove them before the process dies (install_output_signal_handlers).
#include "msmesh/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <mutex>
#include <ostream>
#include <random>
#include <streambuf>
#include <utility>
#include <vector>

#include "msmesh/errors.h"

namespace msmesh {
namespace {

namespace fs = std::filesystem;

// ---- The registry of temporary files and folders, for the signal handler -----------------

enum SlotState : int { Free = 0, File = 1, Folder = 2 };

struct TempSlot {
  std::atomic<TempSlot*> next{nullptr};
  std::atomic<int> state{Free};
  char path[PATH_MAX] = {};
};

std::atomic<TempSlot*> g_slots{nullptr};  // slots are never freed: a handler may be walking them
std::mutex g_slots_mutex;

/// Lists `p` (absolute) as a temporary file or folder to remove on a signal, until destroyed.
class TempRegistration {
 public:
  TempRegistration(const fs::path& p, SlotState kind) {
    std::error_code ec;
    const std::string s = fs::absolute(p, ec).string();
    if (ec || s.size() >= PATH_MAX) throw IoError(p.string() + ": path too long");
    std::lock_guard<std::mutex> lock(g_slots_mutex);
    for (TempSlot* t = g_slots.load(); t && !slot_; t = t->next.load())
      if (t->state.load() == Free) slot_ = t;
    if (!slot_) {
      slot_ = new TempSlot;
      slot_->next.store(g_slots.load());
      g_slots.store(slot_);
    }
    std::memcpy(slot_->path, s.c_str(), s.size() + 1);  // while free, the handler skips the slot
    slot_->state.store(kind);
  }
  ~TempRegistration() { slot_->state.store(Free); }
  TempRegistration(const TempRegistration&) = delete;
  TempRegistration& operator=(const TempRegistration&) = delete;

 private:
  TempSlot* slot_ = nullptr;
};

/// Async-signal-safe: unlink, rmdir, signal and raise only.
extern "C" void remove_temporaries_and_reraise(int sig) {
  const int saved_errno = errno;
  for (TempSlot* t = g_slots.load(); t; t = t->next.load())
    if (t->state.load() == File) ::unlink(t->path);
  for (int pass = 0; pass < 16; ++pass)  // nested folders: the inner ones go first
    for (TempSlot* t = g_slots.load(); t; t = t->next.load())
      if (t->state.load() == Folder) ::rmdir(t->path);
  ::signal(sig, SIG_DFL);
  ::raise(sig);  // blocked while the handler runs: delivered, with the default action, on return
  errno = saved_errno;
}

// ---- Writing through a file descriptor, keeping errno ------------------------------------

std::string write_error(int err) {
  if (err == EFBIG) return "file size limit exceeded (ulimit -f)";
  if (err == ENOSPC) return "no space left on device";
  if (err == EDQUOT) return "disk quota exceeded";
  return std::strerror(err);
}

/// Writes all of [p, p + n) to fd (retrying after signals); 0 or the errno of the failure.
int write_all(int fd, const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return 0;
}

/// A buffered stream buffer on a file descriptor that remembers why a write failed (an
/// ofstream only says that it failed).
class FdBuf : public std::streambuf {
 public:
  explicit FdBuf(int fd) : fd_(fd), buf_(new char[kSize]) { setp(buf_.get(), buf_.get() + kSize); }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (n < static_cast<std::streamsize>(kSize)) return std::streambuf::xsputn(s, n);
    if (!drain() || (error_ = write_all(fd_, s, static_cast<std::size_t>(n))) != 0) return 0;
    return n;
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  static constexpr std::size_t kSize = std::size_t(1) << 16;
  bool drain() {
    if (error_ != 0) return false;
    const std::size_t n = static_cast<std::size_t>(pptr() - pbase());
    if (n > 0) error_ = write_all(fd_, pbase(), n);
    setp(buf_.get(), buf_.get() + kSize);
    return error_ == 0;
  }
  int fd_;
  int error_ = 0;
  std::unique_ptr<char[]> buf_;
};

/// Runs `fill` on a stream writing to fd; throws IoError naming `path` when a write fails.
void fill_descriptor(int fd, const std::string& path, const std::function<void(std::ostream&)>& fill) {
  FdBuf buf(fd);
  std::ostream out(&buf);
  fill(out);
  out.flush();
  if (buf.error() != 0) throw IoError(path + ": write failed: " + write_error(buf.error()));
  if (!out) throw IoError(path + ": write failed");
}

// ---- Staged outputs ----------------------------------------------------------------------

constexpr std::size_t kNameMax = NAME_MAX;  // bytes in one file name (255 on Linux)

/// An output written completely and waiting to be put in place: either a temporary file
/// beside the target, to rename over it, or an anonymous file whose content is copied into
/// the target (a device, a FIFO, standard output).
class Staged {
 public:
  Staged(std::string path, fs::path target) : path_(std::move(path)), target_(std::move(target)) {}
  Staged(Staged&& o) noexcept
      : path_(std::move(o.path_)),
        target_(std::move(o.target_)),
        tmp_(std::exchange(o.tmp_, fs::path())),
        fd_(std::exchange(o.fd_, -1)),
        out_fd_(o.out_fd_),
        copy_(o.copy_),
        registration_(std::move(o.registration_)) {}
  Staged& operator=(Staged&&) = delete;
  ~Staged() { discard(); }

  /// Writes the content next to the target, in a new temporary file; an existing target's
  /// permission bits (and owner, where allowed) carry over.
  void write_beside(const struct stat* existing, const std::function<void(std::ostream&)>& fill) {
    create_temporary_sibling();
    if (existing) {
      if (::fchown(fd_, existing->st_uid, existing->st_gid) != 0) {
        // not permitted (another owner and not root): the new file is ours, as with cp
      }
      if (::fchmod(fd_, existing->st_mode & 0777) != 0)
        throw IoError(path_ + ": cannot keep the permissions of the existing file: " + std::strerror(errno));
    }
    fill_descriptor(fd_, path_, fill);
    if (::fsync(fd_) != 0) throw IoError(path_ + ": cannot flush the file to disk: " + write_error(errno));
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) throw IoError(path_ + ": write failed while closing the file: " + write_error(errno));
  }

  /// Writes the content to an anonymous temporary file, to copy into the target at commit
  /// (or to file descriptor `out_fd` when it is ≥ 0: standard output).
  void write_for_copy(int out_fd, const std::function<void(std::ostream&)>& fill) {
    out_fd_ = out_fd;
    copy_ = true;
    fd_ = anonymous_file();
    fill_descriptor(fd_, path_, fill);
  }

  /// Puts the output in place (rename, or copy into the device, FIFO or standard output).
  void put_in_place() {
    if (copy_) {
      copy_into_target();
    } else {
      if (::rename(tmp_.c_str(), target_.c_str()) != 0)
        throw IoError(path_ + ": cannot rename the temporary file into place: " + std::strerror(errno));
      registration_.reset();
      tmp_.clear();
    }
  }
  bool copies() const { return copy_; }

 private:
  void create_temporary_sibling() {
    static std::atomic<unsigned> counter{0};
    if (target_.filename().empty()) throw IoError(path_ + ": not a file name");
    const fs::path dir = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
    std::random_device rd;
    for (int attempt = 0; attempt < 16; ++attempt) {
      const std::string suffix =
          ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + "-" + std::to_string(rd() % 1000000);
      std::string name = "." + target_.filename().string() + suffix;
      if (name.size() > kNameMax) name = ".msmesh" + suffix;  // a long target name: keep within NAME_MAX
      const fs::path tmp = dir / name;
      auto registration = std::make_unique<TempRegistration>(tmp, File);  // before the file exists
      // Mode 0666: the umask decides a new file's permissions, as for a plain ofstream.
      const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd >= 0) {
        fd_ = fd;
        tmp_ = tmp;
        registration_ = std::move(registration);
        return;
      }
      if (errno != EEXIST)
        throw IoError(path_ + ": cannot create a temporary file in '" + dir.string() + "': " + std::strerror(errno));
    }
    throw IoError(path_ + ": cannot create a unique temporary file in '" + dir.string() + "'");
  }

  /// An unnamed file in the system's temporary folder: nothing to remove, even after a signal.
  int anonymous_file() const {
    std::error_code ec;
    fs::path dir = fs::temp_directory_path(ec);
    if (ec) dir = "/tmp";
    int fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
    if (fd >= 0) return fd;
    std::string name = (dir / "msmesh-XXXXXX").string();  // no O_TMPFILE here: create and unlink
    fd = ::mkostemp(name.data(), O_CLOEXEC);
    if (fd < 0)
      throw IoError(path_ + ": cannot create a temporary file in '" + dir.string() + "': " + std::strerror(errno));
    ::unlink(name.c_str());
    return fd;
  }

  void copy_into_target() {
    int out = out_fd_;
    if (out < 0) {
      struct stat st;
      const bool regular = ::stat(target_.c_str(), &st) == 0 && S_ISREG(st.st_mode);  // /proc/self/fd/N
      out = ::open(target_.c_str(), O_WRONLY | O_CLOEXEC | (regular ? O_TRUNC : 0));
      if (out < 0) throw IoError(path_ + ": cannot open for writing: " + std::strerror(errno));
    } else {
      std::fflush(stdout);
    }
    int err = ::lseek(fd_, 0, SEEK_SET) < 0 ? errno : 0;
    std::vector<char> chunk(std::size_t(1) << 16);
    while (err == 0) {
      const ssize_t r = ::read(fd_, chunk.data(), chunk.size());
      if (r < 0 && errno == EINTR) continue;
      if (r < 0) err = errno;
      if (r <= 0) break;
      err = write_all(out, chunk.data(), static_cast<std::size_t>(r));
    }
    if (out != out_fd_ && ::close(out) != 0 && err == 0) err = errno;
    if (err != 0 && out_fd_ == STDOUT_FILENO) throw IoError("cannot write to standard output: " + write_error(err));
    if (err != 0) throw IoError(path_ + ": write failed: " + write_error(err));
  }

  void discard() noexcept {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!tmp_.empty()) ::unlink(tmp_.c_str());
    tmp_.clear();
    registration_.reset();
  }

  std::string path_;  ///< as the caller named it (messages)
  fs::path target_;   ///< the file written (links followed)
  fs::path tmp_;      ///< the temporary sibling, while it exists
  int fd_ = -1;
  int out_fd_ = -1;
  bool copy_ = false;
  std::unique_ptr<TempRegistration> registration_;
};

/// Writes `fill` for `path` completely, staged; `to_stdout` sends it to file descriptor 1.
Staged stage(const std::string& path, bool to_stdout, const std::function<void(std::ostream&)>& fill) {
  if (to_stdout) {
    Staged s(path, fs::path());
    s.write_for_copy(STDOUT_FILENO, fill);
    return s;
  }
  const fs::path target = resolve_output_path(path);
  struct stat st;
  const bool exists = ::stat(target.c_str(), &st) == 0;
  Staged s(path, target);
  if (exists && S_ISDIR(st.st_mode)) throw IoError(path + ": is a directory");
  if (exists && S_ISSOCK(st.st_mode)) throw IoError(path + ": is a socket; cannot write a file there");
  const bool magic_link = target.string().rfind("/proc/", 0) == 0;  // /dev/stdout and the like
  if (exists && (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) || S_ISFIFO(st.st_mode) || magic_link))
    s.write_for_copy(-1, fill);
  else
    s.write_beside(exists ? &st : nullptr, fill);
  return s;
}

}  // namespace

// ---- OutputTransaction -------------------------------------------------------------------

struct OutputTransaction::Impl {
  Impl* previous = nullptr;
  std::vector<std::string> stdout_paths;
  std::vector<Staged> staged;
  std::vector<std::unique_ptr<TempRegistration>> folders;  ///< created here, in order
  std::vector<fs::path> folder_paths;

  bool to_stdout(const std::string& path) const {
    for (const std::string& p : stdout_paths)
      if (p == path) return true;
    return false;
  }
  void discard() noexcept {
    staged.clear();  // each removes its temporary file
    for (auto it = folder_paths.rbegin(); it != folder_paths.rend(); ++it) ::rmdir(it->c_str());
    folders.clear();
    folder_paths.clear();
  }
};

namespace {
thread_local OutputTransaction::Impl* t_active = nullptr;
}

OutputTransaction::OutputTransaction() : impl_(std::make_unique<Impl>()) {
  impl_->previous = t_active;
  t_active = impl_.get();
}

OutputTransaction::~OutputTransaction() {
  impl_->discard();
  t_active = impl_->previous;
}

void OutputTransaction::send_to_standard_output(const std::string& path) { impl_->stdout_paths.push_back(path); }

void OutputTransaction::commit() {
  if (t_active == impl_.get()) t_active = impl_->previous;  // later writes go straight into place
  // Copies first: writing into a device, FIFO or standard output is what can still fail
  // (a full device, a reader gone); every file is complete on disk before the renames.
  for (Staged& s : impl_->staged)
    if (s.copies()) s.put_in_place();
  for (Staged& s : impl_->staged)
    if (!s.copies()) s.put_in_place();
  impl_->staged.clear();
  impl_->folders.clear();  // the created folders stay
  impl_->folder_paths.clear();
}

// ---- Free functions ----------------------------------------------------------------------

std::string resolve_output_path(const std::string& path) {
  fs::path p(path);
  for (int depth = 0; depth < 40; ++depth) {
    struct stat st;
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p.string();
    std::error_code ec;
    const fs::path folder = fs::canonical(p.has_parent_path() ? p.parent_path() : fs::path("."), ec);
    if (!ec && folder.string().rfind("/proc/", 0) == 0) return (folder / p.filename()).string();  // magic link
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) return p.string();
    p = to.is_absolute() ? to : (p.has_parent_path() ? p.parent_path() / to : to);
  }
  throw IoError(path + ": too many levels of symbolic links");
}

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill) {
  OutputTransaction::Impl* tx = t_active;
  Staged s = stage(path, tx && tx->to_stdout(path), fill);
  if (tx)
    tx->staged.push_back(std::move(s));
  else
    s.put_in_place();
}

void write_text_file(const std::string& path, const std::string& text) {
  write_file_atomically(path, [&text](std::ostream& out) { out.write(text.data(), std::streamsize(text.size())); });
}

void create_output_folder(const std::string& dir) {
  fs::path target = fs::path(dir).lexically_normal();
  if (!target.has_filename() && target.has_parent_path()) target = target.parent_path();  // "parts/"
  std::vector<fs::path> missing;                                                          // innermost first
  for (fs::path p = target; !p.empty(); p = p.parent_path()) {
    struct stat st;
    if (::stat(p.c_str(), &st) == 0) break;
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (::mkdir(it->c_str(), 0777) != 0) {
      if (errno == EEXIST) continue;
      throw IoError("cannot create the folder '" + dir + "': " + std::strerror(errno));
    }
    if (t_active) {
      t_active->folders.push_back(std::make_unique<TempRegistration>(*it, Folder));
      t_active->folder_paths.push_back(*it);
    }
  }
  struct stat st;
  if (::stat(target.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) throw IoError(dir + ": not a folder");
}

void install_output_signal_handlers() {
  for (const int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE}) {
    struct sigaction old;
    if (::sigaction(sig, nullptr, &old) != 0) continue;
    if ((old.sa_flags & SA_SIGINFO) != 0 || old.sa_handler != SIG_DFL) continue;  // ignored or handled: keep
    struct sigaction sa;
    std::memset(&sa, 0, sizeof sa);
    sa.sa_handler = remove_temporaries_and_reraise;
    sigemptyset(&sa.sa_mask);
    ::sigaction(sig, &sa, nullptr);
  }
  ::signal(SIGXFSZ, SIG_IGN);  // write(2) then fails with EFBIG, reported as an IoError
}

}  // namespace msmesh
