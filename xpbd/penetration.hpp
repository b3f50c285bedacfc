// How deep bodies' collision spheres overlap at the current positions: between spheres of
// different bodies, and of a sphere into a collider. A diagnostic for tests and scene
// drivers (the contact solver's own statistics see only the contacts of awake bodies).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "xpbd/broad_phase.hpp"
#include "xpbd/model.hpp"

namespace rice::xpbd {

struct Penetration {
  double between_bodies = 0.0;  ///< largest r_a + r_b − |c_a − c_b| over sphere pairs [m]
  double into_colliders = 0.0;  ///< largest r − d(c) over spheres and colliders [m]
  double deepest() const { return std::max(between_bodies, into_colliders); }
};

/// A body's collision spheres where they are now (sphere_centre, sphere_radius) and the box
/// holding them.
struct PlacedSpheres {
  std::vector<Vec3> centres;
  std::vector<double> radii;
  Box box{Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
};

/// Every body's (asleep too), in body order.
std::vector<PlacedSpheres> placed_spheres(const Model& model);

/// Over all bodies (asleep too), with each collider at its pose at `time`; body pairs come
/// from the broad phase over their sphere boxes, so the cost is that of one broad phase.
Penetration deepest_penetration(const Model& model, double time);

}  // namespace rice::xpbd
