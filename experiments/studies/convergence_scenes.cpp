// Scenes of the convergence study; see convergence_scenes.hpp.
#include "experiments/studies/convergence_scenes.hpp"

namespace rice::experiments {

const char* scene_name(ConvergenceScene scene) {
  return scene == ConvergenceScene::kHangingCantilever ? "hanging-cantilever" : "twisted-bar";
}

const char* body_model_name(BodyModel model) {
  return model == BodyModel::kNeoHookean ? "neo-hookean" : "springs";
}

const char* damping_name(Damping damping) {
  return damping == Damping::kNone ? "none" : damping == Damping::kConstraint ? "constraint" : "strain-rate";
}

xpbd::Model make_scene(ConvergenceScene scene, BodyModel body, const BarSettings& bar, int resolution, Damping damping,
                       double tau) {
  const double rayleigh_time = damping == Damping::kConstraint ? tau : 0.0;
  const double strain_rate_time = damping == Damping::kStrainRate ? tau : 0.0;
  using xpbd::Vec3;
  const xpbd::TetMesh mesh = xpbd::make_box_tet_mesh(Vec3(bar.length, bar.width, bar.width),
                                                     5 * resolution, resolution, resolution);
  xpbd::Model model;
  model.particles = xpbd::make_particles(mesh, bar.density);
  const xpbd::LameParameters lame = xpbd::lame_from_young_poisson(bar.young, bar.poisson);
  if (body == BodyModel::kNeoHookean) {
    xpbd::add_neo_hookean_tets(model, mesh, lame, rayleigh_time, strain_rate_time);
  } else {
    xpbd::add_edge_springs(model, mesh, bar.young, rayleigh_time);
    xpbd::add_tet_volumes(model, mesh, lame.lambda + 2.0 * lame.mu / 3.0, rayleigh_time);
  }
  xpbd::pin_particles(model, xpbd::vertices_at_min_x(mesh.V));
  if (scene == ConvergenceScene::kTwistedBar) {
    const Vec3 axis_point(0.0, 0.5 * bar.width, 0.5 * bar.width);
    for (int i = 0; i < model.particles.size(); ++i) {
      if (model.particles.w[i] == 0.0) continue;
      const Vec3 p = mesh.V.row(i).transpose() - axis_point;
      const double omega = bar.twist_rate * mesh.V(i, 0) / bar.length;
      model.particles.v.row(i) = (omega * Vec3::UnitX().cross(p)).transpose();
    }
  }
  return model;
}

}  // namespace rice::experiments
