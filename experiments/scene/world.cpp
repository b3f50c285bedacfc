// A scene run's world; see world.hpp.
#include "experiments/scene/world.hpp"

#include <algorithm>
#include <cmath>

#include "grains/embedding.hpp"
#include "xpbd/sleeping.hpp"

namespace rice::experiments {

void World::release(int g, const xpbd::Vec3& offset, const xpbd::Vec3& velocity) {
  const xpbd::Vec3 move = offset - parking(g);
  xpbd::Body& body = model.bodies[g];
  if (body.kind == xpbd::BodyKind::kRigid) {
    xpbd::RigidBody& rigid = model.rigid_bodies[body.rigid_body];
    rigid.x += move;
    rigid.v = velocity;
    rigid.remember_pose();
  } else {
    model.particles.x.middleRows(body.first_particle, body.particle_count).rowwise() += move.transpose();
    model.particles.v.middleRows(body.first_particle, body.particle_count).rowwise() = velocity.transpose();
  }
  xpbd::wake(body);
}

xpbd::Vec3 World::centre(int g) const { return xpbd::body_centre(model, model.bodies[g]); }

xpbd::Vec3 World::velocity(int g) const {
  const xpbd::Body& body = model.bodies[g];
  if (body.kind == xpbd::BodyKind::kRigid) return model.rigid_bodies[body.rigid_body].v;
  return model.particles.v.middleRows(body.first_particle, body.particle_count).colwise().mean().transpose();
}

double World::top() const {
  double highest = -INFINITY;
  for (int g = 0; g < released; ++g) highest = std::max(highest, centre(g).z());
  return highest;
}

std::vector<xpbd::Vec3> World::released_centres() const {
  std::vector<xpbd::Vec3> centres;
  for (int g = 0; g < released; ++g) centres.push_back(centre(g));
  return centres;
}

grains::SurfaceMesh World::render_mesh(int g) const {
  const grains::Grain& grain = variants[instances[g].variant].grain;
  const xpbd::Body& body = model.bodies[g];
  grains::Vertices simulation;
  if (body.kind == xpbd::BodyKind::kRigid) {
    // world = q (p₀ − c₀) + c, q the rotation since the start
    const xpbd::RigidBody& rigid = model.rigid_bodies[body.rigid_body];
    const xpbd::Quat q = rigid.q() * initial_orientation[body.rigid_body].conjugate();
    simulation = ((rest_vertices[g].rowwise() - initial_centre[g].transpose()) * q.toRotationMatrix().transpose())
                     .rowwise() +
                 rigid.x.transpose();
  } else {
    simulation = model.particles.x.middleRows(body.first_particle, body.particle_count);
  }
  return {grains::apply_embedding(grain.embedding, simulation, grain.simulation.T), grain.render.F};
}

}  // namespace rice::experiments
