// What the program sets for itself before it works (cli/runtime_settings.h: malloc's and
// OpenMP's settings, taken by restarting itself; cli/heap_prefault.h: heap memory faulted in
// ahead of a denoise) changes how fast it runs, never what it writes.
#include <gtest/gtest.h>

#include <string>

#include "cli_helpers.h"
#include "msmesh/io.h"

using namespace msmesh;

// A mesh large enough that a denoise faults in heap memory first (19,200 faces: ~11 MB, a
// few chunks), denoised with the program's settings and without them (MSMESH_NO_RESTART: no
// restart, so neither the malloc settings nor, since it needs them, the prefault): the same
// bytes.
TEST(RuntimeSettings, TheResultIsTheSameWithoutThem) {
  test::TempDir dir;
  const std::string in = dir.file("in.obj"), a = dir.file("a.ply"), b = dir.file("b.ply");
  const Mesh m = test::noisy_cube(40);
  ASSERT_GE(m.F.rows(), 19200);
  write_mesh(in, m);
  const test::CliRun with = test::run_cli("denoise '" + in + "' -o '" + a + "' -q");
  ASSERT_EQ(with.status, 0) << with.out;
  const test::CliRun without =
      test::run_command("env MSMESH_NO_RESTART=1 GLIBC_TUNABLES= " + std::string(MSMESH_CLI_PATH) + " denoise '" + in +
                        "' -o '" + b + "' -q");
  ASSERT_EQ(without.status, 0) << without.out;
  EXPECT_FALSE(test::read_bytes(a).empty());
  EXPECT_EQ(test::read_bytes(a), test::read_bytes(b));
}
