// How many threads the library's parallel loops use.
#pragma once

namespace msmesh {

/// Sets how many threads the parallel loops and the two-way splits of the sparse
/// factorisations and solves use in the calls this thread makes from now on (OpenMP's
/// setting for the calling thread, as omp_set_num_threads). n ≥ 1; n = 0 restores the
/// default (OMP_NUM_THREADS, else every core). Results are the same bits for any n.
/// Throws InvalidInput when n < 0 or n > 4096. Without OpenMP everything runs on one thread
/// and this only checks n.
void set_threads(int n);

/// The number of threads the next parallel loop started from this thread will use.
int threads();

}  // namespace msmesh
