// Foreseeable memory needs are checked before large allocations, so that a mesh too large for
// the machine fails with a clear error instead of being killed by the OOM killer.
#pragma once
#include <cstdint>
#include <string>

namespace msmesh {

/// Bytes of memory available to this process: MemAvailable from /proc/meminfo (else
/// sysconf's available pages), capped by the environment variable MSMESH_MEMORY_LIMIT
/// (bytes; suffixes K, M, G allowed) when it is set. 0 when unknown.
std::uint64_t available_memory_bytes();

/// Throws InvalidInput "<what>: needs about X of memory, but only Y is available (...)"
/// when `bytes` exceeds available_memory_bytes(). Does nothing when the amount is unknown.
void check_memory(double bytes, const std::string& what);

}  // namespace msmesh
