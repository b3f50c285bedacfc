// Sleep bookkeeping; see sleeping.hpp.
#include "xpbd/sleeping.hpp"

#include <algorithm>
#include <cmath>

namespace rice::xpbd {

StepStart record_step_start(const Model& model) {
  StepStart start{model.particles.x, {}, {}};
  for (const RigidBody& rigid : model.rigid_bodies) {
    start.rigid_centres.push_back(rigid.x);
    start.rigid_orientations.push_back(rigid.q());
  }
  return start;
}

double body_step_speed(const Model& model, const Body& body, const StepStart& start, double dt) {
  if (body.kind == BodyKind::kRigid) {
    const RigidBody& rigid = model.rigid_bodies[body.rigid_body];
    const double cosine = std::min(1.0, std::abs(rigid.q().dot(start.rigid_orientations[body.rigid_body])));
    const double angle = 2.0 * std::acos(cosine);
    return ((rigid.x - start.rigid_centres[body.rigid_body]).norm() + angle * reach(body)) / dt;
  }
  double moved = 0.0;
  for (int i = body.first_particle; i < body.first_particle + body.particle_count; ++i)
    moved = std::max(moved, (model.particles.x.row(i) - start.particles.row(i)).norm());
  return moved / dt;
}

void update_sleep(Model& model, const StepStart& start, double dt) {
  const SleepSettings& settings = model.sleep;
  for (Body& body : model.bodies) {
    if (body.asleep) continue;
    body.moving = body_step_speed(model, body, start, dt) >= settings.speed;
    body.quiet_steps = body.moving ? 0 : body.quiet_steps + 1;
    if (body.quiet_steps < settings.steps) continue;
    body.asleep = true;
    if (body.kind == BodyKind::kRigid) {
      model.rigid_bodies[body.rigid_body].v.setZero();
      model.rigid_bodies[body.rigid_body].omega.setZero();
    } else {
      model.particles.v.middleRows(body.first_particle, body.particle_count).setZero();
    }
  }
}

}  // namespace rice::xpbd
