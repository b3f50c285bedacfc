// The process's peak resident memory so far, as the kernel counts it (getrusage's ru_maxrss):
// what a run needs of the machine, for run_info.txt and the scale study.
#pragma once

#include <sys/resource.h>

namespace rice::experiments {

/// [MiB] The most of this process that has been resident at once, since it started.
inline double peak_resident_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux gives KiB
}

}  // namespace rice::experiments
