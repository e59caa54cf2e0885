#include "output_plan.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <optional>

#include "msmesh/errors.h"
#include "msmesh/mesh_format.h"
#include "usage_error.h"

namespace msmesh::cli {
namespace {

namespace fs = std::filesystem;

constexpr const char* kStandardOutput = "-";

std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

/// A file as the file system knows it: device and inode, or, for a file that does not exist
/// yet, those of its folder and its name. Character devices (/dev/null, a terminal) may be
/// named by several files of a run.
struct Identity {
  dev_t dev = 0;
  ino_t ino = 0;
  std::string name;  ///< empty for an existing file
  bool char_device = false;
  bool operator==(const Identity& o) const { return dev == o.dev && ino == o.ino && name == o.name; }
};

std::optional<Identity> from_stat(const struct stat& st) {
  Identity id;
  id.dev = st.st_dev;
  id.ino = st.st_ino;
  id.char_device = S_ISCHR(st.st_mode);
  return id;
}

/// An existing file (links followed), or nothing.
std::optional<Identity> existing_identity(const std::string& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  return from_stat(st);
}

/// The file an output lands in, existing or not ("-": whatever standard output is).
std::optional<Identity> output_identity(const std::string& path) {
  struct stat st;
  if (path == kStandardOutput) return ::fstat(STDOUT_FILENO, &st) == 0 ? from_stat(st) : std::nullopt;
  const fs::path target = resolve_output_path(path);
  if (::stat(target.c_str(), &st) == 0) return from_stat(st);
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (::stat(folder.c_str(), &st) != 0) return std::nullopt;
  std::optional<Identity> id = from_stat(st);
  id->name = target.filename().string();
  id->char_device = false;
  return id;
}

bool is_part_file_name(const std::string& name) {  // part_NNN.obj, as segment --parts writes them
  if (name.size() < 12 || name.rfind("part_", 0) != 0 || name.substr(name.size() - 4) != ".obj") return false;
  const std::string digits = name.substr(5, name.size() - 9);
  return std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c); });
}

bool is_special(const struct stat& st) { return S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) || S_ISFIFO(st.st_mode); }

/// A device, a FIFO or a /proc/self/fd link: written to directly, so any name does.
bool is_special_output(const std::string& path) {
  const std::string target = resolve_output_path(path);
  struct stat st;
  return ::stat(target.c_str(), &st) == 0 && (is_special(st) || target.rfind("/proc/", 0) == 0);
}

/// The name fits the kind of output (before any work: `-o x.glb` is refused at once).
void check_name(const std::string& path, OutputKind kind, const std::string& option) {
  const std::string ext = lower_extension(path);
  if (path == kStandardOutput) {
    if (kind == OutputKind::Png || kind == OutputKind::Text) return;
    throw UsageError(option +
                     " -: a mesh cannot be written to standard output (its format comes from the file "
                     "extension); name a file such as out.ply");
  }
  switch (kind) {
    case OutputKind::Mesh:
      try {
        mesh_format_from_path(path);
      } catch (const IoError& e) {
        throw UsageError(option + " " + e.what());
      }
      return;
    case OutputKind::PlyMesh:
      if (ext != ".ply")
        throw UsageError(option + " " + in_quotes(path) + ": must be a .ply file (it carries one colour per face)");
      return;
    case OutputKind::Polylines:
      if (ext != ".obj" && ext != ".ply")
        throw UsageError(option + " " + in_quotes(path) + ": polylines can be written to .obj or .ply only");
      return;
    case OutputKind::Png:
      if (ext != ".png" && !is_special_output(path))
        throw UsageError(option + " " + in_quotes(path) + ": the picture is a PNG; name the file .png");
      return;
    case OutputKind::Text:
      return;
  }
}

/// `folder` exists, is a folder and new files can be made in it.
void check_folder(const std::string& path, const fs::path& folder) {
  struct stat st;
  if (::stat(folder.c_str(), &st) != 0)
    throw IoError(path + ": the folder " + in_quotes(folder.string()) +
                  (errno == ENOENT ? std::string(" does not exist") : ": " + std::string(std::strerror(errno))));
  if (!S_ISDIR(st.st_mode)) throw IoError(path + ": " + in_quotes(folder.string()) + " is not a folder");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw IoError(path + ": cannot write in the folder " + in_quotes(folder.string()) + ": " + std::strerror(errno));
}

/// The output can be written: a writable folder (for a new or regular file), a writable device
/// or FIFO, a name within the limits; not a folder or a socket.
void check_writable(const std::string& path) {
  if (path == kStandardOutput) return;
  const fs::path target = resolve_output_path(path);
  const std::string name = target.filename().string();
  if (name.empty()) throw IoError(path + ": not a file name");
  if (name.size() > NAME_MAX)
    throw IoError(path + ": file name too long (" + std::to_string(name.size()) + " bytes; at most " +
                  std::to_string(NAME_MAX) + ")");
  if (target.string().size() >= PATH_MAX) throw IoError(path + ": path too long");
  struct stat st;
  if (::stat(target.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) throw IoError(path + ": is a directory");
    if (S_ISSOCK(st.st_mode)) throw IoError(path + ": is a socket; cannot write a file there");
    if (is_special(st) || target.string().rfind("/proc/", 0) == 0) {
      if (::access(target.c_str(), W_OK) != 0) throw IoError(path + ": cannot write: " + std::strerror(errno));
      return;
    }
  } else if (errno != ENOENT && errno != ENOTDIR) {  // ENOTDIR: the folder check says which
    throw IoError(path + ": " + std::strerror(errno));
  }
  check_folder(path, target.has_parent_path() ? target.parent_path() : fs::path("."));
}

/// A parts folder can be made (or is a writable folder).
void check_parts_folder(const std::string& dir) {
  fs::path p = fs::path(dir).lexically_normal();
  if (!p.has_filename() && p.has_parent_path()) p = p.parent_path();
  struct stat st;
  if (::stat(p.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode)) throw IoError(dir + ": exists and is not a folder");
    if (::access(p.c_str(), W_OK | X_OK) != 0)
      throw IoError(dir + ": cannot write in the folder: " + std::string(std::strerror(errno)));
    return;
  }
  fs::path ancestor = p;  // created with its missing parents: the nearest existing one must take them
  do {
    ancestor = ancestor.has_parent_path() ? ancestor.parent_path() : fs::path(".");
  } while (::stat(ancestor.c_str(), &st) != 0 && ancestor != ancestor.parent_path() && ancestor != ".");
  check_folder(dir, ancestor);
}

}  // namespace

OutputPlan::~OutputPlan() {
  if (saved_cout_) std::cout.rdbuf(saved_cout_);
}

OutputPlan& OutputPlan::input(const std::string& path, const std::string& option) {
  if (!path.empty()) inputs_.push_back({path, option, OutputKind::Text});
  return *this;
}

OutputPlan& OutputPlan::output(const std::string& path, OutputKind kind, const std::string& option) {
  if (!path.empty()) outputs_.push_back({path, option, kind});
  return *this;
}

OutputPlan& OutputPlan::parts_folder(const std::string& dir, const std::string& option) {
  if (!dir.empty()) parts_.push_back({dir, option, OutputKind::Mesh});
  return *this;
}

OutputPlan& OutputPlan::in_place(bool allowed) {
  in_place_ = allowed;
  return *this;
}

void OutputPlan::check_distinct() const {
  std::vector<std::optional<Identity>> in_ids, out_ids;
  for (const File& i : inputs_) in_ids.push_back(existing_identity(i.path));
  for (const File& o : outputs_) out_ids.push_back(output_identity(o.path));
  auto input_name = [](const File& i) {
    return "the input file " + in_quotes(i.path) + (i.option == "input" ? std::string() : " (" + i.option + ")");
  };
  for (size_t j = 0; j < outputs_.size(); ++j) {
    const File& o = outputs_[j];
    for (size_t k = 0; k < j; ++k)
      if ((o.path == kStandardOutput && outputs_[k].path == kStandardOutput) ||
          (out_ids[j] && out_ids[k] && !out_ids[j]->char_device && *out_ids[j] == *out_ids[k]))
        throw UsageError("two outputs are the same file: " + outputs_[k].option + " " + in_quotes(outputs_[k].path) +
                         " and " + o.option + " " + in_quotes(o.path) + "; give each output its own file");
    if (!out_ids[j] || out_ids[j]->char_device) continue;
    for (size_t k = 0; k < inputs_.size(); ++k) {
      if (!in_ids[k] || !(*in_ids[k] == *out_ids[j])) continue;
      const bool may = k == 0 && o.option == "-o";
      if (may && in_place_) continue;
      throw UsageError("refusing to overwrite " + input_name(inputs_[k]) + " with " + o.option + " " +
                       in_quotes(o.path) + (may ? " (pass --in-place to allow it)" : ""));
    }
  }
  for (const File& parts : parts_) {
    const std::optional<Identity> folder = existing_identity(parts.path);
    // A part file must be neither an input nor another output: by name (an output named
    // DIR/part_NNN.obj) and by identity (a part file already there that is, or links to, one).
    auto clash = [&](const std::string& what) {
      throw UsageError(parts.option + " " + in_quotes(parts.path) + " writes part_NNN.obj files there, and " + what +
                       " is one of them; choose another folder");
    };
    const std::optional<Identity> as_output = output_identity(parts.path);
    for (size_t j = 0; j < outputs_.size(); ++j) {
      if (outputs_[j].path == kStandardOutput) continue;
      if (as_output && out_ids[j] && *as_output == *out_ids[j])
        throw UsageError("two outputs are the same file: " + outputs_[j].option + " " + in_quotes(outputs_[j].path) +
                         " and " + parts.option + " " + in_quotes(parts.path));
      const fs::path target = resolve_output_path(outputs_[j].path);
      const std::optional<Identity> in_folder =
          existing_identity(target.has_parent_path() ? target.parent_path().string() : ".");
      if (folder && in_folder && *folder == *in_folder && is_part_file_name(target.filename().string()))
        clash(outputs_[j].option + " " + in_quotes(outputs_[j].path));
    }
    if (!folder) continue;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(parts.path, ec)) {
      if (!is_part_file_name(entry.path().filename().string())) continue;
      const std::optional<Identity> id = existing_identity(entry.path().string());
      if (!id || id->char_device) continue;
      for (size_t k = 0; k < inputs_.size(); ++k)
        if (in_ids[k] && *in_ids[k] == *id) clash(input_name(inputs_[k]) + " (as " + entry.path().string() + ")");
      for (size_t j = 0; j < outputs_.size(); ++j)
        if (out_ids[j] && *out_ids[j] == *id)
          clash(outputs_[j].option + " " + in_quotes(outputs_[j].path) + " (as " + entry.path().string() + ")");
    }
  }
}

void OutputPlan::begin() {
  // Usage first: names, then files that are one.
  for (const File& o : outputs_) check_name(o.path, o.kind, o.option);
  check_distinct();
  // Then the file system: every output can be written.
  for (const File& o : outputs_) check_writable(o.path);
  for (const File& parts : parts_) check_parts_folder(parts.path);

  transaction_ = std::make_unique<OutputTransaction>();
  // "-", and any other name of what standard output is (/dev/stdout, the file it was redirected
  // to), is written through descriptor 1 (at its offset: `>>` appends), and what the run
  // prints goes to standard error, so that the data stay alone there.
  const std::optional<Identity> standard_output = output_identity(kStandardOutput);
  bool to_stdout = false;
  for (const File& o : outputs_) {
    const std::optional<Identity> id = output_identity(o.path);
    if (o.path == kStandardOutput || (standard_output && id && *id == *standard_output)) {
      transaction_->send_to_standard_output(o.path);
      to_stdout = true;
    }
  }
  if (to_stdout) saved_cout_ = std::cout.rdbuf(std::cerr.rdbuf());
}

void OutputPlan::commit() {
  if (transaction_) transaction_->commit();
}

}  // namespace msmesh::cli
