// The fuzzers' inputs as regression tests (fuzz/, scripts/fuzz): every kept crash input
// (tests/data/fuzz_regressions/<format>/) must be refused with IoError / InvalidInput or read
// as a valid mesh, never crash; every seed of the corpus (fuzz/corpus/<format>/, valid small
// meshes written by fuzz/make_corpus.py) must read as a valid mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../fuzz/mesh_check.h"
#include "msmesh/errors.h"
#include "msmesh/io.h"

namespace fs = std::filesystem;

namespace {

const fs::path kSource = MSMESH_SOURCE_DIR;  // not __FILE__: ccache may make it relative
const char* const kFormats[] = {"obj", "off", "ply", "stl"};

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file() && e.path().extension() != ".md") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST(FuzzRegressions, CrashInputsAreRefusedOrReadValid) {
  int count = 0;
  for (const char* fmt : kFormats) {
    for (const fs::path& p : files_in(kSource / "tests/data/fuzz_regressions" / fmt)) {
      SCOPED_TRACE(p.string());
      ++count;
      try {
        const msmesh::Mesh m = msmesh::read_mesh_from_memory(bytes_of(p), fmt, p.string());
        EXPECT_EQ(msmesh::fuzz::mesh_problem(m), "");
      } catch (const msmesh::IoError& e) {
        EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
      } catch (const msmesh::InvalidInput&) {
      }
    }
  }
  RecordProperty("inputs", count);
}

TEST(FuzzRegressions, SeedCorpusReadsValid) {
  int count = 0;
  for (const char* fmt : kFormats) {
    const auto files = files_in(kSource / "fuzz/corpus" / fmt);
    EXPECT_GE(files.size(), 4u) << "no seed corpus for " << fmt << " (python3 fuzz/make_corpus.py)";
    for (const fs::path& p : files) {
      SCOPED_TRACE(p.string());
      ++count;
      try {
        const msmesh::Mesh m = msmesh::read_mesh_from_memory(bytes_of(p), fmt, p.string());
        EXPECT_EQ(msmesh::fuzz::mesh_problem(m), "");
        EXPECT_GE(m.F.rows(), 2);
      } catch (const msmesh::Error& e) {
        ADD_FAILURE() << e.what();
      }
    }
  }
  EXPECT_GT(count, 20);
}
