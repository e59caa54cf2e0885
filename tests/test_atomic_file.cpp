// Atomic file output (msmesh/atomic_file.h): an exception while writing keeps the old file and
// leaves no temporary file; a folder is refused. (Every writer goes through it: see also
// IoWrite.FailedWriteLeavesNoFile and IoWrite.NoTemporaryFilesAreLeftBehind in
// test_write_mesh.cpp.)
#include <gtest/gtest.h>

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
