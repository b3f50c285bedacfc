// Distances between two simulations of the same model (the error norms of the convergence
// study): RMS vertex distance per frame and over a whole trajectory.
#pragma once

#include "xpbd/types.hpp"

namespace rice::fem {

using xpbd::Positions;

/// sqrt(mean_i |a_i − b_i|²). Throws std::invalid_argument when the shapes differ.
double rms_distance(const Positions& a, const Positions& b);

/// Accumulates the RMS vertex distance over the frames of two trajectories:
/// sqrt(mean over frames and particles of |a_i − b_i|²), and the largest frame RMS.
class TrajectoryError {
 public:
  void add_frame(const Positions& a, const Positions& b);
  double rms() const;
  double max_frame_rms() const { return max_frame_rms_; }

 private:
  double sum_of_squares_ = 0.0;  ///< Σ over frames of the frame's mean squared distance
  double max_frame_rms_ = 0.0;
  int frames_ = 0;
};

}  // namespace rice::fem
