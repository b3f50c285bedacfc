// Whether a model's state is sound: positions finite and no soft tet inverted. A diagnostic
// for tests and scene drivers (stats.csv's columns each frame, the hard cases of `rice study
// hard-cases`), not read in the solver's loop.
#pragma once

#include <limits>

#include "xpbd/model.hpp"

namespace rice::xpbd {

/// Every particle's position and every rigid body's pose and velocities are finite.
bool state_finite(const Model& model);

/// How the elastic tets' volumes stand: how many are flat or turned inside out (det F ≤ 0) and
/// the smallest det F = V / V_rest, 1 at rest (NaN without elastic tets). A tet pressed nearly
/// flat is a near miss that the count alone does not show.
struct TetVolumeRatios {
  int inverted = 0;
  double smallest = std::numeric_limits<double>::quiet_NaN();
};
TetVolumeRatios tet_volume_ratios(const Model& model);

/// The elastic tets whose signed volume is ≤ 0 (det F ≤ 0: flat or turned inside out).
inline int inverted_tets(const Model& model) { return tet_volume_ratios(model).inverted; }

}  // namespace rice::xpbd
