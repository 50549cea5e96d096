// Timing for the side-by-side benchmarks: the best of interleaved runs, and one memory policy for
// every library of a run.
#ifndef HALFWING_BENCH_TIMING_HPP
#define HALFWING_BENCH_TIMING_HPP

#include <malloc.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <climits>
#include <limits>
#include <type_traits>

namespace bench {

using Clock = std::chrono::steady_clock;

inline double elapsed_ms(Clock::time_point start, Clock::time_point stop) {
  return std::chrono::duration<double, std::milli>(stop - start).count();
}

/// Wall-clock time of one run of `work`, in milliseconds. When `work` returns a structure (a
/// build), the clock stops before the structure is destroyed.
template <class Work>
double time_once(Work& work) {
  const auto start = Clock::now();
  if constexpr (std::is_void_v<decltype(work())>) {
    work();
    return elapsed_ms(start, Clock::now());
  } else {
    const auto built = work();
    return elapsed_ms(start, Clock::now());
  }
}

/// The best of `repeats` runs of each of `contenders`, in milliseconds. The runs take turns, one
/// of each contender per round: on a shared machine a busy or a quiet minute then falls on all of
/// them alike instead of on whichever ran in it (with back-to-back blocks, two runs minutes apart
/// gave the torus normals 0.42x and 0.61x). Each timed run follows an untimed one of the same
/// contender, so that it finds its own data in the caches, as in back-to-back runs, and not the
/// previous contender's (on the 86k-face armadillo that alone doubled halfwing's normals time).
template <class... Work>
std::array<double, sizeof...(Work)> best_ms(int repeats, Work... contenders) {
  std::array<double, sizeof...(Work)> best;
  best.fill(std::numeric_limits<double>::infinity());
  for (int i = 0; i < repeats; ++i) {
    std::size_t k = 0;
    ((time_once(contenders), best[k] = std::min(best[k], time_once(contenders)), ++k), ...);
  }
  return best;
}

/// Fixes glibc's allocation policy for the whole run, for every library alike. Cold: blocks from
/// 64 KiB up are mmapped and unmapped on free (the dynamic threshold is switched off by setting
/// it), so every build faults in fresh pages. Warm: nothing is mmapped and the heap is never
/// trimmed, so later builds reuse pages the earlier ones faulted in.
inline const char* set_memory_policy(bool warm) {
  if (warm) {
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, INT_MAX);
    return "warm (no mmap, heap never trimmed: repeated builds reuse faulted-in pages)";
  }
  mallopt(M_MMAP_THRESHOLD, 64 * 1024);
  mallopt(M_TRIM_THRESHOLD, 64 * 1024);
  return "cold (blocks >= 64 KiB mmapped and returned on free: every build faults in fresh pages)";
}

}  // namespace bench

#endif
