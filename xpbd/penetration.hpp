// How deep bodies' collision spheres overlap at the current positions: between spheres of
// different bodies, and of a sphere into a collider. A diagnostic for tests and scene
// drivers (the contact solver's own statistics see only the contacts of awake bodies).
#pragma once

#include <algorithm>

#include "xpbd/model.hpp"

namespace rice::xpbd {

struct Penetration {
  double between_bodies = 0.0;  ///< largest r_a + r_b − |c_a − c_b| over sphere pairs [m]
  double into_colliders = 0.0;  ///< largest r − d(c) over spheres and colliders [m]
  double deepest() const { return std::max(between_bodies, into_colliders); }
};

/// Over all bodies (asleep too), with each collider at its pose at `time`; body pairs come
/// from the broad phase over their sphere boxes, so the cost is that of one broad phase.
Penetration deepest_penetration(const Model& model, double time);

}  // namespace rice::xpbd
