#include "msmesh/threads.h"

#include <string>

#include "msmesh/errors.h"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace msmesh {

namespace {

#ifdef _OPENMP
// The default, as the runtime had it before any change from here (OMP_NUM_THREADS, else the
// number of cores); read once, on first use.
int default_threads() {
  static const int initial = omp_get_max_threads();
  return initial;
}
#endif

}  // namespace

void set_threads(int n) {
  if (n < 0 || n > 4096)
    throw InvalidInput("threads: " + std::to_string(n) + " is out of range; valid: 1 to 4096, or 0 for the default");
#ifdef _OPENMP
  const int fallback = default_threads();
  omp_set_num_threads(n == 0 ? fallback : n);
#endif
}

int threads() {
#ifdef _OPENMP
  default_threads();
  return omp_get_max_threads();
#else
  return 1;
#endif
}

}  // namespace msmesh
