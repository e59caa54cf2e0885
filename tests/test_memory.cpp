// memory.h: available_memory_bytes (MemAvailable, capped by MSMESH_MEMORY_LIMIT with its K/M/G
// suffixes) and check_memory's refusal naming what needed the memory and where the limit came
// from. Through `msmesh denoise`: cli/test_limits_cli.cpp.
#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

#include "msmesh/errors.h"
#include "msmesh/memory.h"

using namespace msmesh;

namespace {

/// Sets MSMESH_MEMORY_LIMIT for its lifetime (unset when `value` is empty), then restores it.
class MemoryLimit {
 public:
  explicit MemoryLimit(const std::string& value) {
    if (const char* old = std::getenv("MSMESH_MEMORY_LIMIT")) old_ = old;
    if (value.empty())
      ::unsetenv("MSMESH_MEMORY_LIMIT");
    else
      ::setenv("MSMESH_MEMORY_LIMIT", value.c_str(), 1);
  }
  ~MemoryLimit() {
    if (old_)
      ::setenv("MSMESH_MEMORY_LIMIT", old_->c_str(), 1);
    else
      ::unsetenv("MSMESH_MEMORY_LIMIT");
  }
  MemoryLimit(const MemoryLimit&) = delete;
  MemoryLimit& operator=(const MemoryLimit&) = delete;

 private:
  std::optional<std::string> old_;
};

}  // namespace

TEST(Limits, ForeseeableAllocationBeyondAvailableMemoryFailsCleanly) {
  const MemoryLimit unset("");
  EXPECT_GT(available_memory_bytes(), 0u);
  EXPECT_NO_THROW(check_memory(1000, "small"));
  try {
    check_memory(1e18, "denoise of huge.ply");
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("denoise of huge.ply: needs about"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("MemAvailable in /proc/meminfo"), std::string::npos) << e.what();
  }
}

TEST(Memory, EnvironmentLimitInBytesOrWithSuffixes) {
  const std::pair<const char*, std::uint64_t> cases[] = {
      {"100000", 100000}, {"2K", 2048}, {"3m", 3u << 20}, {"1.5k", 1536}, {"1G", 1u << 30}};
  for (const auto& [value, bytes] : cases) {
    const MemoryLimit limit(value);
    // The limit only ever lowers what the system has (1 GB may be more than this machine has).
    if (bytes < (1u << 30))
      EXPECT_EQ(available_memory_bytes(), bytes) << value;
    else
      EXPECT_LE(available_memory_bytes(), bytes) << value;
  }
}

TEST(Memory, UnreadableEnvironmentLimitIsAnError) {
  // A typo must not silently lift the limit (issue 16, class 6).
  for (const char* value : {"many", "0", "-5", "4X", " 5M", "nan"}) {  // "" means unset here
    const MemoryLimit limit(value);
    try {
      available_memory_bytes();
      ADD_FAILURE() << "'" << value << "' accepted";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("is not a memory size"), std::string::npos) << e.what();
    }
  }
}

TEST(Memory, CheckRefusesOnlyMoreThanTheLimitAndNamesItsSource) {
  const MemoryLimit limit("2M");
  EXPECT_NO_THROW(check_memory(2u << 20, "exactly the limit"));
  EXPECT_NO_THROW(check_memory(0, "nothing"));
  try {
    check_memory(5e6, "denoising m.ply");
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()),
              "denoising m.ply: needs about 5.0 MB of memory, but only 2.1 MB is available (limit set by "
              "MSMESH_MEMORY_LIMIT)");
  }
  EXPECT_THROW(check_memory((2u << 20) + 1.0, "one byte more"), InvalidInput);
}
