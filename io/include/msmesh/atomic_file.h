// Atomic file output (library msmesh_io): every file msmesh writes appears completely or not
// at all, and the outputs of one run can be put in place together (OutputTransaction).
#pragma once
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>

namespace msmesh {

/// Writes `text` to `path` atomically (temporary file, then rename).
void write_text_file(const std::string& path, const std::string& text);

/// Writes `path` atomically: `fill` writes the content to a stream on a new temporary file in
/// the folder of the target, which is flushed to disk and renamed over it. When anything fails
/// (including an exception thrown by `fill`, which is rethrown) the temporary file is removed
/// and `path` is left as it was. Throws IoError naming `path` for file-system failures (a full
/// disk, a file-size limit, ...).
///  - A symbolic link is followed (resolve_output_path): its target is replaced, the link stays.
///  - An existing target keeps its permission bits (and owner, where the system allows it).
///  - A target that is a character or block device or a FIFO (/dev/null, a named pipe) is
///    written to, never replaced: the content goes to an anonymous temporary file first and is
///    copied into the target once complete.
///  - The temporary file is named `.NAME.tmp-PID-N-R`, or `.msmesh.tmp-PID-N-R` when NAME is too
///    long for that to fit the file-name limit (255 bytes).
/// While an OutputTransaction is active on this thread, the output is only staged (complete,
/// on disk) and put in place by the transaction's commit().
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& fill);

/// The file a write to `path` lands in: `path` with every symbolic link in its last component
/// followed, relative links taken from the link's folder (the final target need not exist).
/// Throws IoError naming `path` for a loop (more than 40 links).
std::string resolve_output_path(const std::string& path);

/// The outputs of one run, put in place all together or not at all. While a transaction is
/// alive, write_file_atomically on the same thread writes each output completely to its
/// temporary file (or, for devices, FIFOs and standard output, an anonymous one) and keeps it
/// there; commit() copies the device/FIFO/standard-output ones into place, then renames the
/// others over their targets, in the order they were written. A transaction destroyed without
/// commit() (an exception, a failed output) removes every staged file and every folder made
/// by create_output_folder(), leaving existing files as they were. Transactions nest: an inner
/// one commits into place directly.
class OutputTransaction {
 public:
  OutputTransaction();
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  /// Writes to exactly `path` (e.g. "-") go to standard output (file descriptor 1) at commit.
  void send_to_standard_output(const std::string& path);
  /// Puts every staged output in place. Throws IoError naming the output that failed; the
  /// outputs not yet in place are then discarded (renames are atomic each, so a failure of
  /// rename(2) itself between two of them leaves the earlier ones in place).
  void commit();

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

/// Creates the folder `dir` and its missing parents (like std::filesystem::create_directories).
/// Inside an OutputTransaction, the folders it created are removed again (when empty) if the
/// transaction is discarded or the process is stopped by a signal.
void create_output_folder(const std::string& dir);

/// For programs: makes SIGINT, SIGTERM, SIGHUP, SIGQUIT and SIGPIPE (those whose action is the
/// default) first remove every temporary file and folder msmesh is writing, then take their
/// default action; and ignores SIGXFSZ, so that exceeding a file-size limit (`ulimit -f`)
/// becomes an IoError ("file size limit exceeded") instead of killing the process. A library
/// must not change signal handling behind its host's back, so nothing calls this implicitly.
void install_output_signal_handlers();

}  // namespace msmesh
