// Progress lines; see progress.hpp.
#include "experiments/io/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <utility>

#include "experiments/io/interrupt.hpp"

namespace rice::experiments {

Progress::Progress(std::string label, int total)
    : label_(std::move(label)), total_(total), enabled_(isatty(fileno(stderr)) != 0),
      start_(std::chrono::steady_clock::now()) {
  set_activity(label_ + " 0/" + std::to_string(total_) + " done");
}

void Progress::update(int done) {
  const std::lock_guard lock(mutex_);
  done_ = std::max(done_, done);
  set_activity(label_ + " " + std::to_string(done_) + "/" + std::to_string(total_) + " done");
  // Items finish out of order on several threads: the count shown never goes back.
  if (enabled_ && done_ > 0) {
    const double left = seconds_since(start_) / done_ * (total_ - done_);
    std::fprintf(stderr, "\r%s %d/%d, %.0f s left   ", label_.c_str(), done_, total_, left);
  }
}

void Progress::finish() {
  if (enabled_) std::fprintf(stderr, "\r%s done in %.1f s          \n", label_.c_str(), seconds_since(start_));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace rice::experiments
