// Every output of a run, through the msmesh program (cli/output_plan.h, msmesh/atomic_file.h;
// docs/robustness.md, "Outputs"): never over an input or another output, special files written
// to and never replaced, all or nothing, signals and file-size limits, standard output.
// Each test checks the exit status, the message and the files (bytes, permissions, listing).
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "cli_helpers.h"
#include "msmesh/io.h"

namespace {

using namespace msmesh;
using msmesh::test::read_bytes;
using msmesh::test::run_cli;
using msmesh::test::run_command;
using msmesh::test::TempDir;
using msmesh::test::write_bytes;
namespace fs = std::filesystem;

std::string q(const std::string& s) { return "'" + s + "'"; }

/// What a folder holds, recursively: per entry its type, permission bits and bytes (or link).
struct Entry {
  char type = '?';
  unsigned mode = 0;
  std::string content;
  bool operator==(const Entry& o) const { return type == o.type && mode == o.mode && content == o.content; }
};
using Snapshot = std::map<std::string, Entry>;

Snapshot snapshot(const fs::path& dir) {
  Snapshot s;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    struct stat st;
    ::lstat(e.path().c_str(), &st);
    Entry x;
    x.mode = st.st_mode & 07777;
    if (S_ISLNK(st.st_mode)) {
      x.type = 'l';
      x.content = fs::read_symlink(e.path()).string();
    } else if (S_ISDIR(st.st_mode)) {
      x.type = 'd';
    } else if (S_ISFIFO(st.st_mode)) {
      x.type = 'p';
    } else {
      x.type = 'f';
      x.content = read_bytes(e.path().string());
    }
    s[fs::relative(e.path(), dir).string()] = x;
  }
  return s;
}

std::string names(const Snapshot& s) {
  std::string out;
  for (const auto& [name, e] : s) out += name + " ";
  return out;
}

/// A small mesh file in `d` and a previous result beside it.
struct Scene {
  TempDir d;
  std::string in = d.file("in.obj"), prev = d.file("prev.obj");
  Scene() {
    write_mesh(in, test::grid(6, 0.2));
    write_bytes(prev, "previous result\n");
  }
};

void expect_refused(const std::string& args, int status, const std::string& message, const fs::path& dir) {
  const Snapshot before = snapshot(dir);
  const auto run = run_cli(args);
  EXPECT_EQ(run.status, status) << args << "\n" << run.out;
  EXPECT_NE(run.out.find(message), std::string::npos) << args << "\n" << run.out;
  const Snapshot after = snapshot(dir);
  EXPECT_TRUE(after == before) << args << "\nbefore: " << names(before) << "\nafter:  " << names(after);
}

// ---------------------------------------------------------------------------------------------
// Class 1: no output over an input, no two outputs the same file.

TEST(OutputsNeverOverwriteInputs, SideOutputsOverTheInputAreRefused) {
  Scene s;
  const std::string in = q(s.in), out = q(s.d.file("out.obj"));
  for (const std::string& args : std::vector<std::string>{
           "denoise " + in + " -o " + out + " --save-field " + in,
           "denoise " + in + " -o " + out + " --report " + in,
           "denoise " + in + " -o " + out + " --report " + in + " --in-place",  // --in-place is for -o only
           "holes " + in + " -o " + out + " --map " + in,
           "segment " + in + " -o " + q(s.d.file("o.ply")) + " --labels " + in,
           "segment " + in + " -o " + q(s.d.file("o.ply")) + " --report " + in,
           "inpaint " + in + " -o " + out + " --report " + in,
       })
    expect_refused(args, 2, "refusing to overwrite the input file '" + s.in + "'", s.d.path());
}

TEST(OutputsNeverOverwriteInputs, OtherSpellingsLinksAndHardLinksOfTheInputAreRefused) {
  Scene s;
  fs::create_directory(s.d.path() / "sub");
  fs::create_symlink(s.in, s.d.path() / "link.obj");
  fs::create_symlink("../in.obj", s.d.path() / "sub" / "rel.obj");
  fs::create_hard_link(s.in, s.d.path() / "hard.obj");
  fs::create_symlink(s.in, s.d.path() / "picture.png");  // a .png name that is the mesh
  const std::string in = q(s.in);
  for (const std::string& spelling :
       std::vector<std::string>{s.d.file("./in.obj"), s.d.file("sub/../in.obj"), s.d.file("link.obj"),
                                s.d.file("sub/rel.obj"), s.d.file("hard.obj")}) {
    expect_refused("noise " + in + " -o " + q(spelling), 2, "refusing to overwrite the input file", s.d.path());
    expect_refused("repair " + in + " -o " + q(spelling), 2, "pass --in-place to allow it", s.d.path());
    expect_refused("denoise " + in + " -o " + q(s.d.file("o.obj")) + " --save-field " + q(spelling), 2,
                   "with --save-field", s.d.path());
  }
  expect_refused("features " + in + " -o " + q(s.d.file("hard.obj")), 2, "refusing to overwrite", s.d.path());
  expect_refused("render " + in + " -o " + q(s.d.file("picture.png")), 2, "refusing to overwrite", s.d.path());
}

TEST(OutputsNeverOverwriteInputs, TruthAndOtherInputsAreNeverOverwrittenEvenInPlace) {
  Scene s;
  const std::string gt = s.d.file("gt.obj"), labels = s.d.file("labels.txt");
  write_mesh(gt, test::grid(6));
  write_bytes(labels, std::string(72, '0') + "\n");
  fs::create_symlink(labels, s.d.path() / "labels.png");
  fs::create_symlink(gt, s.d.path() / "gt.png");
  const std::string in = q(s.in);
  expect_refused("denoise " + in + " -o " + q(gt) + " --truth " + q(gt), 2, "'" + gt + "' (--truth) with -o",
                 s.d.path());
  expect_refused("denoise " + in + " -o " + q(gt) + " --truth " + q(gt) + " --in-place", 2, "(--truth)", s.d.path());
  expect_refused("inpaint " + in + " -o " + q(s.d.file("o.obj")) + " --truth " + q(gt) + " --report " + q(gt), 2,
                 "(--truth) with --report", s.d.path());
  expect_refused("render " + in + " --color labels --labels " + q(labels) + " -o " + q(s.d.file("labels.png")), 2,
                 "(--labels) with -o", s.d.path());
  expect_refused("compare " + in + " " + q(gt) + " -o " + q(s.d.file("gt.png")), 2, "refusing to overwrite",
                 s.d.path());
}

TEST(OutputsNeverOverwriteInputs, InPlaceAllowsOnlyMinusOOverTheMainInput) {
  Scene s;
  const std::string before = read_bytes(s.in);
  auto run = run_cli("noise " + q(s.in) + " -o " + q(s.d.file("./in.obj")) + " --sigma 0.1 -q --in-place");
  EXPECT_EQ(run.status, 0) << run.out;
  EXPECT_NE(read_bytes(s.in), before);
  expect_refused("denoise " + q(s.in) + " -o " + q(s.d.file("o.obj")) + " --save-field " + q(s.in) + " --in-place", 2,
                 "with --save-field", s.d.path());
  EXPECT_EQ(s.d.listing(), (std::vector<std::string>{"in.obj", "prev.obj"}));
}

TEST(OutputsNeverOverwriteInputs, TwoOutputsOfOneRunMustBeDifferentFiles) {
  Scene s;
  const std::string in = q(s.in);
  fs::create_hard_link(s.prev, s.d.path() / "prev_hard.obj");
  for (const std::string& args : std::vector<std::string>{
           "segment " + in + " -o " + q(s.d.file("o.ply")) + " --labels " + q(s.d.file("o.ply")),
           "segment " + in + " -o " + q(s.d.file("o.ply")) + " --labels " + q(s.d.file("./o.ply")),
           "denoise " + in + " -o " + q(s.prev) + " --report " + q(s.d.file("prev_hard.obj")),
           "denoise " + in + " -o " + q(s.d.file("o.obj")) + " --save-field f.txt --report f.txt",
           "holes " + in + " -o " + q(s.d.file("h.obj")) + " --map " + q(s.d.file("h.obj")),
           "segment " + in + " -o " + q(s.d.file("o.ply")) + " --labels - --report -",
       })
    expect_refused(args, 2, "two outputs are the same file", s.d.path());
  // A character device such as /dev/null may take several outputs.
  const auto run =
      run_cli("denoise " + in + " -o " + q(s.d.file("o.obj")) + " --save-field /dev/null --report /dev/null -q");
  EXPECT_EQ(run.status, 0) << run.out;
}

TEST(OutputsNeverOverwriteInputs, PartFilesAreNeitherInputsNorOtherOutputs) {
  Scene s;
  const fs::path parts = s.d.path() / "parts";
  fs::create_directory(parts);
  const std::string part_in = (parts / "part_000.obj").string();
  write_mesh(part_in, test::grid(6, 0.2));
  expect_refused("segment " + q(part_in) + " -o " + q(s.d.file("o.ply")) + " --parts " + q(parts.string()), 2,
                 "writes part_NNN.obj files there", s.d.path());
  fs::remove(part_in);
  fs::create_symlink(s.in, parts / "part_002.obj");  // an old part that is a link to the input
  expect_refused("segment " + q(s.in) + " -o " + q(s.d.file("o.ply")) + " --parts " + q(parts.string()), 2,
                 "the input file '" + s.in + "' (as ", s.d.path());
  fs::remove(parts / "part_002.obj");
  expect_refused("segment " + q(s.in) + " -o " + q(s.d.file("o.ply")) + " --parts " + q(parts.string()) + " --labels " +
                     q((parts / "part_001.obj").string()),
                 2, "--labels", s.d.path());
  expect_refused("segment " + q(s.in) + " -o " + q(s.d.file("o.ply")) + " --parts " + q(s.d.file("o.ply")), 2,
                 "two outputs are the same file", s.d.path());
}

// ---------------------------------------------------------------------------------------------
// Class 2: devices, FIFOs, "-", symbolic links, permissions.

TEST(SpecialOutputs, DeviceIsWrittenToNeverReplaced) {
  Scene s;
  struct stat before, after;
  ASSERT_EQ(::stat("/dev/null", &before), 0);
  for (const std::string& args :
       std::vector<std::string>{"render " + q(s.in) + " -o /dev/null -q",
                                "denoise " + q(s.in) + " -o " + q(s.d.file("o.obj")) + " --report /dev/null -q",
                                "segment " + q(s.in) + " -o " + q(s.d.file("o.ply")) + " --labels /dev/null -q"}) {
    const auto run = run_cli(args);
    EXPECT_EQ(run.status, 0) << args << "\n" << run.out;
  }
  ASSERT_EQ(::stat("/dev/null", &after), 0);
  EXPECT_TRUE(S_ISCHR(after.st_mode));
  EXPECT_EQ(after.st_rdev, before.st_rdev);
  EXPECT_EQ(after.st_ino, before.st_ino);
  // A mesh format still comes from the name: /dev/null has none.
  expect_refused("denoise " + q(s.in) + " -o /dev/null", 2, "unknown mesh format", s.d.path());
}

TEST(SpecialOutputs, FifoIsWrittenToNeverReplaced) {
  Scene s;
  const std::string fifo = s.d.file("pipe");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& args : std::vector<std::string>{
           "render " + q(s.in) + " -o " + q(fifo) + " -q",
           "segment " + q(s.in) + " -o " + q(s.d.file("o.ply")) + " --labels " + q(fifo) + " -q"}) {
    std::string received;
    std::thread reader([&] { received = read_bytes(fifo); });  // opening blocks until msmesh writes
    const auto run = run_cli(args);
    const int release = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);  // a reader still waiting: EOF
    if (release >= 0) ::close(release);
    reader.join();
    EXPECT_EQ(run.status, 0) << args << "\n" << run.out;
    EXPECT_FALSE(received.empty()) << args;
    struct stat st;
    ASSERT_EQ(::lstat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode)) << args;
    if (args.rfind("render", 0) == 0) {
      EXPECT_EQ(received.substr(0, 4), "\x89PNG");
    } else {
      EXPECT_EQ(std::count(received.begin(), received.end(), '\n'), 72);  // one label per face
    }
  }
}

TEST(SpecialOutputs, DashIsStandardOutputForPicturesAndTextNotForMeshes) {
  Scene s;
  const std::string data = s.d.file("stdout.bin"), err = s.d.file("stderr.txt");
  auto run =
      run_command("(" + std::string(MSMESH_CLI_PATH) + " render " + q(s.in) + " -o - 2>" + q(err) + ") > " + q(data));
  EXPECT_EQ(run.status, 0) << read_bytes(err);
  EXPECT_EQ(read_bytes(data).substr(0, 8), "\x89PNG\r\n\x1a\n");
  EXPECT_NE(read_bytes(err).find("rendered"), std::string::npos) << read_bytes(err);  // the summary: on stderr
  run = run_command("(" + std::string(MSMESH_CLI_PATH) + " segment " + q(s.in) + " -o " + q(s.d.file("o.ply")) +
                    " --labels - --json 2>" + q(err) + ") > " + q(data));
  EXPECT_EQ(run.status, 0) << read_bytes(err);
  const std::string labels = read_bytes(data);
  EXPECT_EQ(std::count(labels.begin(), labels.end(), '\n'), 72) << labels;
  EXPECT_NE(read_bytes(err).find("\"segments\""), std::string::npos) << read_bytes(err);
  // Another name of standard output (/dev/stdout, the file it is redirected to) is written the
  // same way: the data alone, the summary on stderr.
  run = run_command("(" + std::string(MSMESH_CLI_PATH) + " render " + q(s.in) + " -o /dev/stdout 2>" + q(err) + ") > " +
                    q(data));
  EXPECT_EQ(run.status, 0) << read_bytes(err);
  EXPECT_EQ(read_bytes(data).substr(0, 8), "\x89PNG\r\n\x1a\n");
  EXPECT_NE(read_bytes(err).find("rendered"), std::string::npos) << read_bytes(err);
  const std::string mesh = s.d.file("n.obj");
  run = run_command("(" + std::string(MSMESH_CLI_PATH) + " noise " + q(s.in) + " -o " + q(mesh) + " 2>" + q(err) +
                    ") > " + q(mesh));
  EXPECT_EQ(run.status, 0) << read_bytes(err);
  EXPECT_EQ(read_mesh(mesh).F.rows(), 72);
  fs::remove(mesh);
  fs::remove(data);
  fs::remove(err);
  fs::remove(s.d.file("o.ply"));
  for (const std::string& args :
       std::vector<std::string>{"denoise " + q(s.in) + " -o -", "features " + q(s.in) + " -o -",
                                "segment " + q(s.in) + " -o -", std::string("shape cube -o -")})
    expect_refused(args, 2, "cannot be written to standard output", s.d.path());
  const std::string both = "segment " + q(s.in) + " -o " + q(s.d.file("o.ply")) + " --labels /dev/stdout --report -";
  const Snapshot before = snapshot(s.d.path());
  run = run_command("(" + std::string(MSMESH_CLI_PATH) + " " + both + " | cat)");  // standard output: a pipe
  EXPECT_EQ(run.status, 0) << run.out;  // the status of cat; the message says what msmesh did
  EXPECT_NE(run.out.find("two outputs are the same file: --labels '/dev/stdout' and --report '-'"), std::string::npos)
      << run.out;
  EXPECT_TRUE(snapshot(s.d.path()) == before);
}

TEST(SpecialOutputs, SymbolicLinkOutputWritesItsTargetAndStays) {
  Scene s;
  fs::create_directory(s.d.path() / "store");
  fs::create_symlink("store/result.obj", s.d.path() / "latest.obj");  // dangling: the target is made
  fs::create_symlink(s.prev, s.d.path() / "prev_link.obj");
  auto run = run_cli("noise " + q(s.in) + " -o " + q(s.d.file("latest.obj")) + " -q");
  ASSERT_EQ(run.status, 0) << run.out;
  run = run_cli("noise " + q(s.in) + " -o " + q(s.d.file("prev_link.obj")) + " -q");
  ASSERT_EQ(run.status, 0) << run.out;
  EXPECT_TRUE(fs::is_symlink(s.d.path() / "latest.obj"));
  EXPECT_TRUE(fs::is_symlink(s.d.path() / "prev_link.obj"));
  EXPECT_EQ(fs::read_symlink(s.d.path() / "latest.obj"), "store/result.obj");
  EXPECT_EQ(read_mesh(s.d.file("store/result.obj")).F.rows(), 72);
  EXPECT_EQ(read_mesh(s.prev).F.rows(), 72);  // the link's target was replaced
  EXPECT_EQ(s.d.listing(), (std::vector<std::string>{"in.obj", "latest.obj", "prev.obj", "prev_link.obj", "store"}));
}

TEST(SpecialOutputs, ExistingOutputKeepsItsPermissions) {
  Scene s;
  for (const unsigned mode : {0600u, 0640u, 0444u}) {
    ::chmod(s.prev.c_str(), mode);
    const std::string report = s.d.file("r.html");
    write_bytes(report, "old");
    ::chmod(report.c_str(), mode);
    const auto run =
        run_cli("denoise " + q(s.in) + " -o " + q(s.prev) + " --report " + q(report) + " -q --normal-iterations 2");
    ASSERT_EQ(run.status, 0) << run.out;
    struct stat st;
    ASSERT_EQ(::stat(s.prev.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, mode);
    ASSERT_EQ(::stat(report.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, mode);
    EXPECT_NE(read_bytes(report), "old");
  }
  // Through the library alike.
  ::chmod(s.prev.c_str(), 0600);
  write_text_file(s.prev, "new\n");
  struct stat st;
  ASSERT_EQ(::stat(s.prev.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
}

// ---------------------------------------------------------------------------------------------
// Class 3: a failed run writes nothing; everything is checked before any work.

TEST(AllOrNothing, OutputNamesAndFoldersAreCheckedBeforeAnyWork) {
  Scene s;
  fs::create_directory(s.d.path() / "folder");
  const std::string in = q(s.in);
  const std::string long_name = s.d.file(std::string(260, 'n') + ".obj");
  struct Case {
    std::string args;
    int status;
    std::string message;
  };
  const Case cases[] = {
      {"denoise " + in + " -o " + q(s.d.file("x.xyz")), 2, "-o " + s.d.file("x.xyz") + ": unknown mesh format '.xyz'"},
      {"shape sphere --resolution 400 -o " + q(s.d.file("x.xyz.gz")), 2, "unknown mesh format '.xyz' under .gz"},
      {"denoise " + in + " -o " + q(s.prev) + " --report " + q(s.d.file("missing/r.html")), 1,
       "the folder '" + s.d.file("missing") + "' does not exist"},
      {"denoise " + in + " -o " + q(s.prev) + " --save-field " + q(s.d.file("prev.obj/f.txt")), 1, "is not a folder"},
      {"segment " + in + " -o " + q(s.d.file("seg.obj")), 2, "must be a .ply file"},
      {"features " + in + " -o " + q(s.d.file("lines.off")), 2, "polylines can be written to .obj or .ply only"},
      {"render " + in + " -o " + q(s.d.file("picture.jpg")), 2, "the picture is a PNG"},
      {"holes " + in + " -o " + q(s.prev) + " --map " + q(s.d.file("folder")) + "/", 1, "not a file name"},
      {"holes " + in + " -o " + q(s.prev) + " --map " + q(s.d.file("folder")), 1, "is a directory"},
      {"noise " + in + " -o " + q(long_name), 1, "file name too long (264 bytes; at most 255)"},
      {"segment " + in + " -o " + q(s.d.file("o.ply")) + " --parts " + q(s.prev), 1, "exists and is not a folder"},
  };
  for (const Case& c : cases) expect_refused(c.args, c.status, c.message, s.d.path());
  if (::geteuid() != 0) {  // root may write anywhere
    ::chmod((s.d.path() / "folder").c_str(), 0555);
    expect_refused("noise " + in + " -o " + q(s.d.file("folder/o.obj")), 1, "cannot write in the folder", s.d.path());
    ::chmod((s.d.path() / "folder").c_str(), 0755);
  }
}

TEST(AllOrNothing, FailedRunLeavesEveryExistingFileAsItWasAndNoNewFile) {
  Scene s;
  const std::string in = q(s.in);
  expect_refused("denoise " + in + " -o " + q(s.prev) + " --method bilateral --save-field " + q(s.d.file("f.txt")), 2,
                 "--save-field needs --method nmstv or mstv", s.d.path());
  expect_refused("denoise " + in + " -o " + q(s.prev) + " --truth " + q(s.d.file("missing.obj")), 1, "missing.obj",
                 s.d.path());
  expect_refused("render " + in + " -o " + q(s.d.file("p.png")) + " --color labels --labels " + q(s.prev), 1,
                 "prev.obj", s.d.path());
  expect_refused(
      "segment " + in + " -o " + q(s.d.file("o.ply")) + " --parts " + q(s.d.file("new/parts")) + " --labels /dev/full",
      1, "/dev/full: write failed: no space left on device", s.d.path());  // no parts folder left
}

TEST(AllOrNothing, FailureAfterSomeOutputsWereWrittenCommitsNone) {
  Scene s;
  const std::string in = q(s.in);
  // The mesh is written first, then the report fails: the mesh is not put in place either.
  expect_refused("denoise " + in + " -o " + q(s.prev) + " --report /dev/full --normal-iterations 2", 1,
                 "/dev/full: write failed", s.d.path());
  expect_refused("holes " + in + " -o " + q(s.prev) + " --map /dev/full", 1, "/dev/full: write failed", s.d.path());
  // A file-size limit the small mesh fits under and the HTML report (with its viewer) does not.
  const std::string cmd = "bash -c 'ulimit -f 200; exec " + std::string(MSMESH_CLI_PATH) + " denoise " + s.in + " -o " +
                          s.prev + " --report " + s.d.file("r.html") + " --normal-iterations 2'";
  const Snapshot before = snapshot(s.d.path());
  const auto run = run_command(cmd);
  EXPECT_EQ(run.status, 1) << run.out;
  EXPECT_NE(run.out.find("r.html: write failed: file size limit exceeded"), std::string::npos) << run.out;
  EXPECT_TRUE(snapshot(s.d.path()) == before) << names(snapshot(s.d.path()));
}

// ---------------------------------------------------------------------------------------------
// Class 4: signals, file-size limits, long names.

/// Starts msmesh with `args` (output discarded) with the default action for every signal.
pid_t spawn_cli(const std::vector<std::string>& args) {
  std::vector<std::string> all{MSMESH_CLI_PATH};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid == 0) {  // only async-signal-safe calls until exec
    const int null = ::open("/dev/null", O_RDWR);
    ::dup2(null, 1);
    ::dup2(null, 2);
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) ::signal(sig, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

bool has_temporary_file(const fs::path& dir) {
  std::error_code ec;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    if (e.path().filename().string().find(".tmp-") != std::string::npos) return true;
  return false;
}

/// Waits for `pid` for up to `seconds`; its wait status, or -1 (then it is killed).
int wait_for(pid_t pid, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (::waitpid(pid, &status, WNOHANG) == pid) return status;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  return -1;
}

TEST(Signals, SignalWhileOutputsArePendingRemovesEveryTemporaryFile) {
  // The outputs are staged, then the run blocks opening a FIFO nobody reads: a reliable moment
  // at which temporary files (the mesh, the part files) and a new folder exist.
  for (const int sig : {SIGTERM, SIGINT, SIGHUP}) {
    Scene s;
    const std::string fifo = s.d.file("pipe");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const Snapshot before = snapshot(s.d.path());
    const pid_t pid =
        spawn_cli({"segment", s.in, "-o", s.d.file("o.ply"), "--labels", fifo, "--parts", s.d.file("parts")});
    ASSERT_GT(pid, 0);
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!has_temporary_file(s.d.path()) && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    ASSERT_TRUE(has_temporary_file(s.d.path())) << "no temporary file appeared";
    std::this_thread::sleep_for(std::chrono::milliseconds(100));  // let the part files come too
    ::kill(pid, sig);
    const int status = wait_for(pid, 30);
    ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
    EXPECT_EQ(WTERMSIG(status), sig);
    EXPECT_TRUE(snapshot(s.d.path()) == before) << strsignal(sig) << ": " << names(snapshot(s.d.path()));
  }
}

TEST(Signals, SignalDuringALargeWriteRemovesTheTemporaryFile) {
  TempDir d;
  const std::string out = d.file("sphere.ply");
  for (int attempt = 0; attempt < 3; ++attempt) {
    const pid_t pid = spawn_cli({"shape", "sphere", "--resolution", "400", "--ascii", "-o", out});
    ASSERT_GT(pid, 0);
    bool seen = false;
    int status = 0;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < end) {
      if (has_temporary_file(d.path())) {
        seen = true;
        break;
      }
      if (::waitpid(pid, &status, WNOHANG) == pid) break;  // finished before we saw it
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    if (!seen) {
      if (wait_for(pid, 30) == -1) FAIL() << "msmesh did not finish";
      fs::remove(out);
      continue;
    }
    ::kill(pid, SIGTERM);
    status = wait_for(pid, 30);
    ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
    EXPECT_EQ(WTERMSIG(status), SIGTERM);
    EXPECT_TRUE(d.listing().empty()) << names(snapshot(d.path()));
    return;
  }
  GTEST_SKIP() << "the write was too quick to catch its temporary file three times";
}

TEST(Signals, FileSizeLimitIsAClearErrorAndLeavesNothing) {
  Scene s;
  for (const std::string& args : std::vector<std::string>{"shape sphere --resolution 60 -o " + s.d.file("sphere.ply"),
                                                          "noise " + s.in + " -o " + s.prev + " --sigma 0.1",
                                                          "render " + s.in + " -o " + s.d.file("p.png")}) {
    const Snapshot before = snapshot(s.d.path());
    const auto run = run_command("bash -c 'ulimit -f 1; exec " + std::string(MSMESH_CLI_PATH) + " " + args + "'");
    EXPECT_EQ(run.status, 1) << args << "\n" << run.out;
    EXPECT_NE(run.out.find("write failed: file size limit exceeded"), std::string::npos) << args << "\n" << run.out;
    EXPECT_TRUE(snapshot(s.d.path()) == before) << args << ": " << names(snapshot(s.d.path()));
  }
}

TEST(Signals, LongOutputNamesGetShortTemporaryNames) {
  Scene s;
  for (const std::size_t length : {235u, 245u, 251u}) {  // + ".obj": up to the 255-byte limit
    const std::string stem(length, 'm');
    const std::string out = s.d.file(stem + ".obj"), field = s.d.file(stem + ".txt");
    const auto run = run_cli("denoise " + q(s.in) + " -o " + q(out) + " --save-field " + q(field) + " -q");
    EXPECT_EQ(run.status, 0) << length << ": " << run.out;
    EXPECT_EQ(read_mesh(out).F.rows(), 72);
    EXPECT_FALSE(read_bytes(field).empty());
    EXPECT_FALSE(has_temporary_file(s.d.path()));
    fs::remove(out);
    fs::remove(field);
  }
  EXPECT_EQ(s.d.listing(), (std::vector<std::string>{"in.obj", "prev.obj"}));
}

// ---------------------------------------------------------------------------------------------
// Class 7 (standard output): a full or closed standard output is an error.

TEST(StandardOutput, FullOrClosedStandardOutputFailsTheRun) {
  Scene s;
  const std::string M = MSMESH_CLI_PATH;
  for (const std::string& redirect : std::vector<std::string>{"> /dev/full", ">&-"}) {
    for (const std::string& args :
         std::vector<std::string>{std::string("shape --list"), "info " + q(s.in), "params --preset cad", "--help",
                                  "render " + q(s.in) + " -o -"}) {
      const auto run = run_command("(" + M + " " + args + " " + redirect + ")");  // stderr still captured
      EXPECT_EQ(run.status, 1) << args << " " << redirect << "\n" << run.out;
      EXPECT_NE(run.out.find("msmesh: error: cannot write to standard output: "), std::string::npos)
          << args << " " << redirect << "\n"
          << run.out;
    }
  }
  // Nothing printed (-q): nothing lost, exit 0; and the summary never lands in an output file
  // that took the closed descriptor's number.
  auto run = run_command("(" + M + " noise " + q(s.in) + " -o " + q(s.d.file("n.obj")) + " -q >&-)");
  EXPECT_EQ(run.status, 0) << run.out;
  run = run_command("(" + M + " noise " + q(s.in) + " -o " + q(s.d.file("n.obj")) + " >&-)");
  EXPECT_EQ(run.status, 1) << run.out;
  EXPECT_EQ(read_mesh(s.d.file("n.obj")).F.rows(), 72);
  EXPECT_EQ(read_bytes(s.d.file("n.obj")).find("noise:"), std::string::npos);
}

}  // namespace
