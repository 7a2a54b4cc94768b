// The processor time a thread has used, for `cutcom run --stage-times` (issue "Performance":
// the reader, the engine and the writer run on threads of their own, and the slowest of them
// sets the pace; the process's own times cannot tell them apart).
#pragma once

#include <ctime>

namespace cutcom {

// Seconds of processor time of the calling thread since it started (0 where the system cannot tell).
inline double thread_cpu_seconds() {
  timespec t{};
  if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t) != 0) return 0;
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) * 1e-9;
}

}  // namespace cutcom
