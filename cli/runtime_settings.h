// What the msmesh program sets for itself before it starts working (main.cpp restarts itself
// with these unless the user chose otherwise) and what `msmesh batch` undoes for the Python
// processes it starts (cmd_batch.cpp).
#pragma once

namespace msmesh::cli {

/// glibc's malloc: freed memory kept for reuse (main.cpp says why).
inline constexpr const char* kMallocTunables =
    "glibc.malloc.mmap_threshold=33554432:glibc.malloc.top_pad=67108864:glibc.malloc.trim_threshold=1073741824";

/// libgomp's spin before a waiting thread sleeps, when the cores are idle at the start.
inline constexpr const char* kIdleSpinCount = "2000";

}  // namespace msmesh::cli
