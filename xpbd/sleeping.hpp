// Sleeping: a body whose points all moved slower than SleepSettings::speed for
// SleepSettings::steps consecutive steps sleeps. A sleeping body is not integrated, its tets
// are not solved, it has infinite mass in contact (body.hpp), and no contacts are made
// between two sleeping bodies or between a sleeping body and a collider at rest. The contact
// broad phase wakes it when a moving body's box or a moving collider comes near it. A body may
// also be put to sleep by hand (asleep = true) to park it until a scene releases it; that
// works with SleepSettings::enabled off too.
//
// Speeds are displacements over the whole step divided by its length, not the velocities of
// the last substep: a resting pile's grains move back and forth by a micrometre within a
// step, which at 0.4 ms substeps reads as 2.4 mm/s, while over a frame they move under
// 0.6 mm/s (measured on 800 grains in the chawan, where no grain fell asleep by velocity).
// Only a body that moved over the last step wakes its neighbours: one just woken does not, or
// waking spreads through a resting pile (750 of 800 grains stayed awake that way).
#pragma once

#include <vector>

#include "xpbd/model.hpp"

namespace rice::xpbd {

/// Where every particle and rigid body was at the start of a step.
struct StepStart {
  Positions particles;
  std::vector<Vec3> rigid_centres;
  std::vector<Quat> rigid_orientations;
};
StepStart record_step_start(const Model& model);

/// The largest speed of any point of the body over the step of length dt that began at
/// `start`: |Δx|/dt + θ r_max/dt (rigid, θ the angle turned) or max |Δx_i|/dt (soft).
double body_step_speed(const Model& model, const Body& body, const StepStart& start, double dt);

/// After a step: counts each body's quiet steps and puts to sleep, with zero velocities,
/// those quiet for SleepSettings::steps.
void update_sleep(Model& model, const StepStart& start, double dt);

/// Wakes a sleeping body.
inline void wake(Body& body) {
  body.asleep = false;
  body.quiet_steps = 0;
}

}  // namespace rice::xpbd
