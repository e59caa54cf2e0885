// Machine probe: how fast this machine's memory is right now, measured the same way every
// time, so that timings taken on different days (or on a busy virtual machine) can be told
// apart from changes in the code. Prints one JSON object:
//
//   build/bench/msmesh_probe [--quick]
//
//   triad_gb_s      a[i] = b[i] + 1.5 c[i] over 3 × 200 MB, one thread, best of 5 (bandwidth)
//   latency_ns_2mb  a dependent random walk through 2 MB (fits this machine's 4 MB L2)
//   latency_ns_16mb through 16 MB (the size of the Cone's vertex-update factor: L3 or memory)
//   latency_ns_64mb through 64 MB (memory)
//   compute_ns      one step of a dependent integer chain (the core's clock, not memory)
//   cpu_share       two threads spin for a while: the CPU time they got over twice the wall
//                   time (1.0: both cores ours; on a busy host the virtual CPUs stall and a
//                   two-thread denoise then takes longer in wall time than in CPU time)
//
// The sparse triangular solves and factorisations of a denoise read their factors from
// wherever the 16 MB line says; the conjugate-gradient path of large meshes streams at about
// the triad rate (docs/performance.md, "Machine state").
#include <time.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <thread>
#include <vector>

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

double triad_gb_s(size_t n, int repeats) {
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const double t0 = now();
    for (size_t i = 0; i < n; ++i) a[i] = b[i] + 1.5 * c[i];
    best = std::min(best, now() - t0);
    if (a[n / 2] != 4.0) std::abort();  // keeps the loop
  }
  return 3.0 * 8.0 * static_cast<double>(n) / best / 1e9;
}

// A single random cycle through `bytes` of 8-byte slots (Sattolo's algorithm), walked
// `steps` times: each load depends on the previous one, so this is the access latency.
double latency_ns(size_t bytes, size_t steps) {
  const size_t n = bytes / sizeof(uint64_t);
  std::vector<uint64_t> next(n);
  std::iota(next.begin(), next.end(), uint64_t{0});
  uint64_t state = 0x9E3779B97F4A7C15ULL;  // xorshift64*: quick and fixed
  const auto random_below = [&state](size_t bound) {
    state ^= state >> 12;
    state ^= state << 25;
    state ^= state >> 27;
    return static_cast<size_t>((state * 2685821657736338717ULL) >> 11) % bound;
  };
  for (size_t i = n - 1; i > 0; --i) std::swap(next[i], next[random_below(i)]);
  uint64_t x = 0;
  for (size_t i = 0; i < n; ++i) x = next[x];  // warm up: touch every slot once
  double best = 1e300;
  for (int r = 0; r < 3; ++r) {
    const double t0 = now();
    for (size_t i = 0; i < steps; ++i) x = next[x];
    best = std::min(best, now() - t0);
  }
  if (x >= n) std::abort();
  return best / static_cast<double>(steps) * 1e9;
}

double compute_ns(uint64_t steps) {
  volatile uint64_t seed = 7;
  uint64_t x = seed;
  const double t0 = now();
  for (uint64_t i = 0; i < steps; ++i) x = x * 6364136223846793005ULL + 1442695040888963407ULL;
  const double t = now() - t0;
  seed = x;
  return t / static_cast<double>(steps) * 1e9;
}

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double cpu_share(double seconds) {
  std::atomic<bool> stop{false};
  double cpu[2] = {0, 0};
  volatile uint64_t sink[2] = {0, 0};  // keeps the spinning loops
  const double t0 = now();
  std::vector<std::thread> threads;
  for (int t = 0; t < 2; ++t)
    threads.emplace_back([&, t] {
      const double c0 = thread_cpu_seconds();
      uint64_t x = 1;
      while (!stop.load(std::memory_order_relaxed))
        for (int i = 0; i < 10000; ++i) x = x * 6364136223846793005ULL + 1;
      sink[t] = x;
      cpu[t] = thread_cpu_seconds() - c0;
    });
  while (now() - t0 < seconds) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  stop = true;
  for (auto& th : threads) th.join();
  return (cpu[0] + cpu[1]) / (2.0 * (now() - t0));
}

}  // namespace

int main(int argc, char** argv) {
  bool quick = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) {
      quick = true;
    } else {
      std::fprintf(stderr, "usage: msmesh_probe [--quick]\n");
      return 2;
    }
  }
  const size_t steps = quick ? 200000 : 2000000;
  const double triad = triad_gb_s(quick ? (1u << 20) : 25000000u, quick ? 2 : 5);
  const double l2 = latency_ns(size_t{2} << 20, steps);
  const double l16 = latency_ns(size_t{16} << 20, steps);
  const double l64 = quick ? 0.0 : latency_ns(size_t{64} << 20, steps);
  const double cpu = compute_ns(quick ? 1000000 : 50000000);
  const double share = cpu_share(quick ? 0.1 : 1.0);
  std::printf(
      "{\"triad_gb_s\":%.2f,\"latency_ns_2mb\":%.1f,\"latency_ns_16mb\":%.1f,\"latency_ns_64mb\":%.1f,"
      "\"compute_ns\":%.3f,\"cpu_share\":%.3f,\"quick\":%s}\n",
      triad, l2, l16, l64, cpu, share, quick ? "true" : "false");
  return 0;
}
