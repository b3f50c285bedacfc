// Progress of long loops ("label k/N, s left"): on a terminal one line rewritten in place; into
// a log (stderr not a terminal: a workflow step's log, CI) a line every 30 s and, after any,
// one when the loop is done, so short loops write nothing. Also the activity an interrupted
// run names; wall-clock seconds.
#pragma once

#include <chrono>
#include <mutex>
#include <string>

namespace rice::experiments {

/// Progress of a long loop: lines "label k/N, ETA" on stderr (see above), and the activity
/// reported if the run is interrupted (interrupt.hpp). Thread-safe.
class Progress {
 public:
  /// `log_seconds`: the time between two lines into a log. `done_before`: items done before this
  /// process began (a resumed run), left out of the pace the time left is estimated from.
  Progress(std::string label, int total, double log_seconds = 30.0, int done_before = 0);
  void update(int done);
  void finish();

 private:
  std::string label_;
  int total_;
  int done_before_;
  int done_;
  double log_seconds_;
  bool terminal_;
  bool logged_ = false;  ///< into a log: a line was written
  std::chrono::steady_clock::time_point start_, last_line_;
  std::mutex mutex_;
};

/// Seconds since `start` on the steady clock.
double seconds_since(std::chrono::steady_clock::time_point start);

}  // namespace rice::experiments
