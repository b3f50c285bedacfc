// Whether a model's state is sound: positions finite and no soft tet inverted. A diagnostic
// for tests and scene drivers (the hard cases of `rice study hard-cases`), read once at the
// end of a run, not in the solver's loop.
#pragma once

#include "xpbd/model.hpp"

namespace rice::xpbd {

/// Every particle's position and every rigid body's pose and velocities are finite.
bool state_finite(const Model& model);

/// The elastic tets whose signed volume is ≤ 0 (det F ≤ 0: flat or turned inside out).
int inverted_tets(const Model& model);

}  // namespace rice::xpbd
