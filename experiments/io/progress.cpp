// Progress lines; see progress.hpp.
#include "experiments/io/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <utility>

#include "experiments/io/interrupt.hpp"

namespace rice::experiments {

Progress::Progress(std::string label, int total, double log_seconds, int done_before)
    : label_(std::move(label)), total_(total), done_before_(done_before), done_(done_before), log_seconds_(log_seconds),
      terminal_(isatty(fileno(stderr)) != 0), start_(std::chrono::steady_clock::now()), last_line_(start_) {
  set_activity(label_ + " " + std::to_string(done_) + "/" + std::to_string(total_) + " done");
}

void Progress::update(int done) {
  const std::lock_guard lock(mutex_);
  done_ = std::max(done_, done);
  set_activity(label_ + " " + std::to_string(done_) + "/" + std::to_string(total_) + " done");
  // Items finish out of order on several threads: the count shown never goes back.
  if (done_ == done_before_) return;
  const double left = seconds_since(start_) / (done_ - done_before_) * (total_ - done_);
  if (terminal_) {
    std::fprintf(stderr, "\r%s %d/%d, %.0f s left   ", label_.c_str(), done_, total_, left);
  } else if (seconds_since(last_line_) >= log_seconds_) {
    std::fprintf(stderr, "%s %d/%d, %.0f s left\n", label_.c_str(), done_, total_, left);
    last_line_ = std::chrono::steady_clock::now();
    logged_ = true;
  }
}

void Progress::finish() {
  if (terminal_ || logged_)
    std::fprintf(stderr, "%s%s done in %.1f s          \n", terminal_ ? "\r" : "", label_.c_str(),
                 seconds_since(start_));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace rice::experiments
