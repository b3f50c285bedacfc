// What surrounds the grains in a render; see render_stage.hpp.
#include "experiments/render/render_stage.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "experiments/io/render_images.hpp"
#include "experiments/render/framing_box.hpp"
#include "experiments/render/scene_pieces.hpp"
#include "experiments/render/studio_lighting.hpp"
#include "experiments/render/translucency_tables.hpp"
#include "grains/mesh_io.hpp"

namespace rice::experiments {
namespace {

/// The sun, the area lights and the sky (an image, or uniform).
shading::Lights lights_of(const RenderCommandSettings& s) {
  constexpr double kDegree = std::numbers::pi / 180.0;
  shading::Lights lights;
  if (s.sun_irradiance > 0.0) {
    lights.suns.push_back({.direction = direction_from(s.sun_elevation_degrees, s.sun_azimuth_degrees).cast<float>(),
                           .angular_radius = static_cast<float>(0.5 * s.sun_diameter_degrees * kDegree),
                           .irradiance = shading::Color::Constant(static_cast<float>(s.sun_irradiance))});
  }
  lights.quads = s.area_lights;
  if (!s.sky_image.empty()) {
    shading::Image sky = read_exr(s.sky_image);
    lights.environment.width = sky.width;
    lights.environment.height = sky.height;
    lights.environment.image = std::move(sky.pixels);
  } else {
    lights.environment.constant = shading::Color::Constant(static_cast<float>(s.sky_radiance));
  }
  return lights;
}

/// The material index of a collider's material name (materials_of).
int collider_material(const std::string& name) {
  const std::vector<std::string>& names = collider_material_names();
  return 5 + static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
}

}  // namespace

std::vector<shading::Material> materials_of(double absorption_percent, RenderIntegrator integrator) {
  return {integrator == RenderIntegrator::kTranslucent ? translucent_rice_material(absorption_percent)
                                                       : rice_material(absorption_percent),
          {.kind = shading::MaterialKind::kDiffuse, .albedo = shading::Color::Constant(0.35f)},
          {.kind = shading::MaterialKind::kGlazed, .albedo = shading::Color(0.12f, 0.1f, 0.09f), .roughness = 0.08},
          {.kind = shading::MaterialKind::kDiffuse, .albedo = shading::Color(0.42f, 0.37f, 0.31f)},
          {.kind = shading::MaterialKind::kDiffuse, .albedo = shading::Color(0.3f, 0.29f, 0.27f)},
          {.kind = shading::MaterialKind::kGlazed, .albedo = shading::Color(0.75f, 0.75f, 0.73f), .roughness = 0.3},
          {.kind = shading::MaterialKind::kDiffuse, .albedo = shading::Color(0.55f, 0.4f, 0.25f)},
          // Iron's reflectance at normal incidence (Real-Time Rendering, 4th ed., Table 9.2),
          // brushed: a rough isotropic lobe.
          {.kind = shading::MaterialKind::kMetal, .albedo = shading::Color(0.56f, 0.57f, 0.58f), .roughness = 0.25},
          {.kind = shading::MaterialKind::kGlazed, .albedo = shading::Color(0.8f, 0.79f, 0.76f), .roughness = 0.05}};
}

Eigen::AlignedBox3d add_bowl(shading::RenderScene& scene, const RenderCommandSettings& s,
                             const Eigen::AlignedBox3d& grains_box) {
  Eigen::AlignedBox3d box = grains_box;
  if (!s.run.empty() && std::filesystem::exists(s.run / "chawan.obj")) {
    const grains::SurfaceMesh bowl = grains::read_surface_mesh(s.run / "chawan.obj");
    scene.add_instance(scene.add_prototype(bowl.V, bowl.F), Eigen::Affine3d::Identity(), 2);
    for (Eigen::Index v = 0; v < bowl.V.rows(); ++v) box.extend(bowl.V.row(v).transpose());
  }
  return box;
}

void add_colliders(shading::RenderScene& scene, const std::vector<ColliderDrawing>& colliders, double time,
                   const Eigen::Vector3d& eye) {
  for (const ColliderDrawing& c : colliders) {
    if (!xpbd::collider_present(c.motion, time)) continue;
    const Eigen::Affine3d place = collider_placement(c, time);
    const grains::SurfaceMesh mesh = c.hollow ? cutaway_walls(c.mesh, place.inverse() * eye) : c.mesh;
    if (mesh.F.rows() == 0) continue;
    scene.add_instance(scene.add_prototype(mesh.V, mesh.F), place, collider_material(c.material));
  }
}

Stage stage_for(const RenderCommandSettings& s, const Eigen::AlignedBox3d& subject) {
  const double aspect = static_cast<double>(s.render.width) / s.render.height;
  Stage stage{s.camera ? *s.camera : framing_camera(subject, 35.0, -60.0, 30.0, aspect), subject, {}};
  stage.lights = s.lighting == Lighting::kStudio ? studio_lights(subject, stage.camera.position, s.studio) : lights_of(s);
  return stage;
}

void add_set(shading::RenderScene& scene, const RenderCommandSettings& s, const Stage& stage) {
  if (!s.ground) return;
  if (s.lighting == Lighting::kStudio) return add_studio_set(scene, stage.subject, stage.camera.position, 3, 4);
  const Eigen::AlignedBox3d& box = stage.subject;
  const double half = 2.0 * box.diagonal().head<2>().maxCoeff() + 1e-3, z = box.min().z() - 1e-6;
  const Eigen::Vector2d c = box.center().head<2>();
  add_ground(scene, c.x() - half, c.y() - half, c.x() + half, c.y() + half, z, 1);
}

}  // namespace rice::experiments
