// Sleep bookkeeping; see sleeping.hpp.
#include "xpbd/sleeping.hpp"

#include <algorithm>

namespace rice::xpbd {

double body_speed(const Model& model, const Body& body) {
  if (body.kind == BodyKind::kRigid) {
    const RigidBody& rigid = model.rigid_bodies[body.rigid_body];
    double reach = 0.0;
    for (int s = 0; s < body.sphere_count(); ++s) reach = std::max(reach, body.local_centres[s].norm() + body.radii[s]);
    return rigid.v.norm() + rigid.omega.norm() * reach;
  }
  double speed = 0.0;
  for (int i = body.first_particle; i < body.first_particle + body.particle_count; ++i)
    speed = std::max(speed, model.particles.v.row(i).norm());
  return speed;
}

void update_sleep(Model& model) {
  const SleepSettings& settings = model.sleep;
  for (Body& body : model.bodies) {
    if (body.asleep) continue;
    body.quiet_steps = body_speed(model, body) < settings.speed ? body.quiet_steps + 1 : 0;
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
