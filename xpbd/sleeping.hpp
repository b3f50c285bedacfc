// Sleeping: a body whose points all moved slower than SleepSettings::speed for
// SleepSettings::steps consecutive steps sleeps. A sleeping body is not integrated, its tets
// are not solved, it has infinite mass in contact (body.hpp), and no contacts are made
// between two sleeping bodies or between a sleeping body and a collider at rest. The contact
// broad phase wakes it when a moving body's box or a moving collider comes near it. A body may
// also be put to sleep by hand (asleep = true) to park it until a scene releases it; that
// works with SleepSettings::enabled off too.
#pragma once

#include "xpbd/model.hpp"

namespace rice::xpbd {

/// Largest speed of any point of the body: |v| + |ω| r_max (rigid) or its particles' (soft).
double body_speed(const Model& model, const Body& body);

/// After a step: counts each body's quiet steps and puts to sleep, with zero velocities,
/// those quiet for SleepSettings::steps.
void update_sleep(Model& model);

/// Wakes a sleeping body.
inline void wake(Body& body) {
  body.asleep = false;
  body.quiet_steps = 0;
}

}  // namespace rice::xpbd
