// Trajectory error norms; see trajectory_error.hpp.
#include "fem_reference/trajectory_error.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rice::fem {

double rms_distance(const Positions& a, const Positions& b) {
  if (a.rows() != b.rows())
    throw std::invalid_argument("rms_distance: " + std::to_string(a.rows()) + " against " +
                                std::to_string(b.rows()) + " particles");
  if (a.rows() == 0) return 0.0;
  return std::sqrt((a - b).squaredNorm() / static_cast<double>(a.rows()));
}

void TrajectoryError::add_frame(const Positions& a, const Positions& b) {
  const double frame = rms_distance(a, b);
  sum_of_squares_ += frame * frame;
  max_frame_rms_ = std::max(max_frame_rms_, frame);
  ++frames_;
}

double TrajectoryError::rms() const {
  return frames_ > 0 ? std::sqrt(sum_of_squares_ / frames_) : 0.0;
}

}  // namespace rice::fem
