// The chunks of whole lines of plain_text.h.
#include "plain_text.h"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace msmesh::io_detail {

std::vector<std::string_view> line_chunks(std::string_view data, std::size_t min_bytes) {
  // The thread count only when there could be two chunks (see for_each_chunk).
  const std::size_t most = data.size() / std::max<std::size_t>(min_bytes, 1);
  int threads = 1;
#ifdef _OPENMP
  if (most >= 2) threads = omp_get_max_threads();
#endif
  const std::size_t n =
      std::max<std::size_t>(1, std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), most));
  // Chunk k starts after the first '\n' at or beyond k / n of the data.
  std::vector<std::string_view> chunks;
  const char* const end = data.data() + data.size();
  const char* from = data.data();
  for (std::size_t k = 1; k <= n; ++k) {
    const char* to = end;
    if (k < n) {
      const char* at = std::max(from, data.data() + data.size() / n * k);
      const void* nl = at < end ? std::memchr(at, '\n', static_cast<std::size_t>(end - at)) : nullptr;
      to = nl ? static_cast<const char*>(nl) + 1 : end;
    }
    chunks.emplace_back(from, static_cast<std::size_t>(to - from));
    from = to;
  }
  return chunks;
}

}  // namespace msmesh::io_detail
