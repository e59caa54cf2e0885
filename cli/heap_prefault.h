// Faulting in, ahead of the work, the heap memory a run will use: on a virtual machine a fresh
// page's first touch is a fault that costs several microseconds (10 µs on this project's VM on
// 2026-12-05), paid one page at a time, mostly in the serial parts of a run; taken here in bulk
// on both cores instead (docs/performance.md, "Issue 20, fourteenth round").
#pragma once
#include <cstddef>

namespace msmesh::cli {

/// Allocates about `bytes` of the heap in chunks, faults them in on two threads
/// (madvise(MADV_POPULATE_WRITE), or a write per page where the kernel has no such advice), and
/// frees them: malloc then hands those pages out again. Only while the program's own malloc
/// settings (runtime_settings.h) are in effect, which keep freed memory rather than return it,
/// and when the memory available is at least kPrefaultSpareFactor times the run's estimate
/// (bytes / kPrefaultShare); otherwise, and for less than a chunk, nothing. At most
/// kMaxPrefaultBytes.
void prefault_heap(double bytes);

/// The share of the memory estimate (msmesh/memory.h) that is faulted in: what the runs measured
/// take from the heap at least (the rest is the program, the input and arrays above malloc's
/// mmap threshold, which bypass the heap).
inline constexpr double kPrefaultShare = 0.6;

/// Spare memory wanted, in multiples of the run's estimate, before anything is faulted in.
inline constexpr double kPrefaultSpareFactor = 2.0;

/// Half of the malloc settings' trim threshold: a free chunk larger than that would be handed
/// back to the system at once.
inline constexpr std::size_t kMaxPrefaultBytes = std::size_t(512) << 20;

}  // namespace msmesh::cli
