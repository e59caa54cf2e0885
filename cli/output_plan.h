// The files one run of a subcommand reads and writes, declared before any work and checked
// together (docs/robustness.md, "Outputs"):
//  - no output is the same file as an input (whatever the spelling: ./x, a symbolic link, a
//    hard link) — except -o over the main input with --in-place — and no two outputs are the
//    same file (also the DIR/part_NNN.obj files of a parts folder);
//  - every output can be written: a known format, an existing writable folder, a name that
//    fits, not a folder or a socket; a device or FIFO is written to, never replaced; "-" is
//    standard output where the content has a fixed format (PNG, HTML, text);
//  - all or nothing: from begin() on, every file written goes to a temporary file and they are
//    all put in place by commit() (msmesh::OutputTransaction); a failure before it leaves every
//    existing file as it was and no new file.
#pragma once
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "msmesh/atomic_file.h"

namespace msmesh::cli {

/// What an output holds, which decides the names it accepts.
enum class OutputKind {
  Mesh,       ///< .obj, .off, .ply or .stl (format from the extension; not "-")
  PlyMesh,    ///< .ply only (segment -o: one colour per face)
  Polylines,  ///< .obj or .ply (features -o)
  Png,        ///< a PNG picture: a .png name, a device, a FIFO or "-"
  Text,       ///< any name or "-" (labels, vertex maps, edge fields, HTML reports)
};

class OutputPlan {
 public:
  OutputPlan() = default;
  ~OutputPlan();
  OutputPlan(const OutputPlan&) = delete;
  OutputPlan& operator=(const OutputPlan&) = delete;

  /// A file the run reads; `option` names it in messages ("input", "--truth"). The first one
  /// declared is the main input (the one --in-place may overwrite). Ignored when empty.
  OutputPlan& input(const std::string& path, const std::string& option = "input");
  /// A file the run writes through `option` ("-o", "--save-field"); ignored when empty.
  OutputPlan& output(const std::string& path, OutputKind kind, const std::string& option);
  /// The folder `option` writes part_NNN.obj files into (created when missing).
  OutputPlan& parts_folder(const std::string& dir, const std::string& option);
  /// With --in-place, the output -o may be the main input.
  OutputPlan& in_place(bool allowed);

  /// Checks every declared file as described above and starts the transaction: throws
  /// UsageError (a wrong name, two files that are one) or IoError (a folder that is missing or
  /// not writable) before anything is read or written. While outputs go to standard output,
  /// what the run prints (summaries, --json) goes to standard error.
  void begin();
  /// Puts every output written since begin() in place (OutputTransaction::commit).
  void commit();

 private:
  struct File {
    std::string path, option;
    OutputKind kind = OutputKind::Text;
  };
  /// No output is an input (but -o the main input with --in-place) or another output.
  void check_distinct() const;

  std::vector<File> inputs_, outputs_;
  std::vector<File> parts_;
  bool in_place_ = false;
  std::unique_ptr<OutputTransaction> transaction_;
  std::streambuf* saved_cout_ = nullptr;
};

}  // namespace msmesh::cli
