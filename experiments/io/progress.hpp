// Progress of long loops on a terminal ("label k/N, s left"; quiet when stderr is not a
// terminal, as in CI), reported as the activity an interrupted run names; wall-clock seconds.
#pragma once

#include <chrono>
#include <mutex>
#include <string>

namespace rice::experiments {

/// Progress of a long loop: lines "label k/N, ETA" on stderr when stderr is a terminal, and
/// the activity reported if the run is interrupted (interrupt.hpp). Thread-safe.
class Progress {
 public:
  Progress(std::string label, int total);
  void update(int done);
  void finish();

 private:
  std::string label_;
  int total_;
  int done_ = 0;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
};

/// Seconds since `start` on the steady clock.
double seconds_since(std::chrono::steady_clock::time_point start);

}  // namespace rice::experiments
