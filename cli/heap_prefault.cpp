#include "heap_prefault.h"

#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "msmesh/memory.h"
#include "runtime_settings.h"

namespace msmesh::cli {

namespace {

#ifndef MADV_POPULATE_WRITE
constexpr int kMadvPopulateWrite = 23;  // Linux 5.14's value
#else
constexpr int kMadvPopulateWrite = MADV_POPULATE_WRITE;
#endif

// Below malloc's mmap threshold (runtime_settings.h: 32 MB), so every chunk comes from the heap.
constexpr std::size_t kChunk = std::size_t(4) << 20;

void populate(void* chunk, std::size_t page) {
  const auto begin = reinterpret_cast<std::uintptr_t>(chunk);
  const std::uintptr_t lo = (begin + page - 1) / page * page, hi = (begin + kChunk) / page * page;
  if (madvise(reinterpret_cast<void*>(lo), hi - lo, kMadvPopulateWrite) == 0) return;
  for (std::uintptr_t p = lo; p < hi; p += page) *reinterpret_cast<volatile char*>(p) = 0;
}

}  // namespace

void prefault_heap(double bytes) {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (!tunables || std::strcmp(tunables, kMallocTunables) != 0 || !(bytes > 0)) return;
  // The pages stay with the process: with little memory to spare they would make the library's
  // own check_memory see less than there is.
  const std::uint64_t available = available_memory_bytes();
  if (available > 0 && double(available) < kPrefaultSpareFactor * bytes / kPrefaultShare) return;
  const std::size_t n = static_cast<std::size_t>(std::min(bytes, double(kMaxPrefaultBytes)) / double(kChunk));
  const long page = sysconf(_SC_PAGESIZE);
  if (n == 0 || page <= 0) return;
  std::vector<void*> chunks(n, nullptr);
  for (void*& c : chunks) c = std::malloc(kChunk);
#pragma omp parallel for schedule(dynamic) num_threads(2)
  for (long i = 0; i < static_cast<long>(n); ++i)
    if (chunks[static_cast<std::size_t>(i)])
      populate(chunks[static_cast<std::size_t>(i)], static_cast<std::size_t>(page));
  for (std::size_t i = n; i-- > 0;) std::free(chunks[i]);
}

}  // namespace msmesh::cli
