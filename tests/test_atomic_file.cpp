// Atomic file output (msmesh/atomic_file.h): an exception while writing keeps the old file and
// leaves no temporary file; a folder is refused; permissions, links, devices, long names; an
// OutputTransaction commits all its outputs or none. (Every writer goes through it: see also
// IoWrite.FailedWriteLeavesNoFile and IoWrite.NoTemporaryFilesAreLeftBehind in
// test_write_mesh.cpp.)
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "msmesh/atomic_file.h"
#include "msmesh/errors.h"
#include "test_helpers.h"

using namespace msmesh;
using msmesh::test::read_bytes;
using msmesh::test::TempDir;

TEST(IoWrite, ExceptionWhileWritingKeepsTheOldFile) {
  TempDir dir;
  const std::string path = dir.file("keep.txt");
  write_text_file(path, "old");
  EXPECT_THROW(write_file_atomically(path,
                                     [](std::ostream& out) {
                                       out << "partial";
                                       throw InvalidInput("stop");
                                     }),
               InvalidInput);
  EXPECT_EQ(read_bytes(path), "old");
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"keep.txt"});
  EXPECT_THROW(write_text_file(dir.path().string(), "x"), IoError);  // a folder
}

TEST(IoWrite, KeepsPermissionsFollowsLinksAndWritesIntoDevices) {
  TempDir dir;
  const std::string path = dir.file("private.txt");
  write_text_file(path, "old");
  ::chmod(path.c_str(), 0600);
  write_text_file(path, "new");
  struct stat st;
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  std::filesystem::create_symlink("private.txt", dir.path() / "link.txt");
  write_text_file(dir.file("link.txt"), "through the link");
  EXPECT_TRUE(std::filesystem::is_symlink(dir.path() / "link.txt"));
  EXPECT_EQ(read_bytes(path), "through the link");
  EXPECT_EQ(resolve_output_path(dir.file("link.txt")), dir.file("private.txt"));
  write_text_file("/dev/null", "discarded");
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  const std::string long_name = dir.file(std::string(251, 'x') + ".txt");  // 255 bytes
  write_text_file(long_name, "fits");
  EXPECT_EQ(read_bytes(long_name), "fits");
  EXPECT_EQ(dir.listing().size(), 3u);  // private.txt, link.txt, the long one: no temporary file
}

TEST(OutputTransaction, DiscardedLeavesEveryFileAsItWasAndNoNewOne) {
  TempDir dir;
  write_text_file(dir.file("old.txt"), "old");
  {
    OutputTransaction tx;
    write_text_file(dir.file("old.txt"), "replaced?");
    write_text_file(dir.file("new.txt"), "new?");
    create_output_folder(dir.file("made/inner"));
    write_text_file(dir.file("made/inner/part.txt"), "part?");
    EXPECT_EQ(read_bytes(dir.file("old.txt")), "old");  // staged, not in place
    EXPECT_FALSE(std::filesystem::exists(dir.file("new.txt")));
  }  // no commit: an exception, a failed output
  EXPECT_EQ(read_bytes(dir.file("old.txt")), "old");
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"old.txt"});
}

TEST(OutputTransaction, CommitPutsEveryOutputInPlaceAndNests) {
  TempDir dir;
  write_text_file(dir.file("a.txt"), "old");
  OutputTransaction tx;
  write_text_file(dir.file("a.txt"), "a");
  {
    OutputTransaction inner;
    write_text_file(dir.file("inner.txt"), "inner");
    inner.commit();
  }
  EXPECT_EQ(read_bytes(dir.file("inner.txt")), "inner");  // the inner one is committed at once
  create_output_folder(dir.file("parts"));
  write_text_file(dir.file("parts/p.txt"), "p");
  EXPECT_EQ(read_bytes(dir.file("a.txt")), "old");
  tx.commit();
  EXPECT_EQ(read_bytes(dir.file("a.txt")), "a");
  EXPECT_EQ(read_bytes(dir.file("parts/p.txt")), "p");
  EXPECT_EQ(dir.listing(), (std::vector<std::string>{"a.txt", "inner.txt", "parts"}));
}
