// The renderer studies' plate of grains; see grain_plate.hpp.
#include "experiments/render/grain_plate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "experiments/render/scene_pieces.hpp"
#include "grains/cultivar.hpp"
#include "grains/grain_generator.hpp"

namespace rice::experiments {

GrainVariants add_grain_variants(shading::RenderScene& scene, std::uint64_t seed) {
  grains::GrainRecipe recipe;
  recipe.cultivar = grains::cultivar_by_name("japonica");
  GrainVariants v;
  for (int k = 0; k < 4; ++k) {
    const grains::Grain grain = grains::make_grain(recipe, seed * 101 + k, 1.0);
    v.prototypes.push_back(add_grain_prototype(scene, grain.render.V, grain.render.F));
    v.meshes.push_back(grain.render.V);
    v.length = std::max(v.length, (grain.render.V.colwise().maxCoeff() - grain.render.V.colwise().minCoeff()).maxCoeff());
  }
  return v;
}

shading::Lights study_lights(float sun_angular_radius) {
  shading::Lights lights;
  lights.suns.push_back({.direction = Eigen::Vector3f(0.3f, 0.5f, 0.8f),
                         .angular_radius = sun_angular_radius,
                         .irradiance = shading::Color::Constant(3.0f)});
  lights.environment.constant = shading::Color::Constant(0.3f);
  return lights;
}

void build_grain_plate(GrainPlate& plate, int grains, std::uint64_t seed, float sun_angular_radius) {
  const GrainVariants variants = add_grain_variants(plate.scene, seed);
  const std::vector<int>& prototypes = variants.prototypes;
  const double length = variants.length;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int columns = static_cast<int>(std::ceil(std::sqrt(grains * 1.5)));
  const double pitch = 1.05 * length;
  for (int g = 0; g < grains; ++g) {
    const double x = (g % columns - 0.5 * (columns - 1)) * pitch, y = (g / columns) * 0.6 * pitch;
    const Eigen::Affine3d place = Eigen::Translation3d(x + 0.05 * pitch * unit(rng), y, 1.1e-3) *
                                  Eigen::AngleAxisd(0.4 * (unit(rng) - 0.5), Eigen::Vector3d::UnitZ());
    plate.grain_instances.push_back(plate.scene.add_instance(prototypes[g % prototypes.size()], place, 0));
  }
  add_ground(plate.scene, -0.1, -0.1, 0.1, 0.1, 0.0, 1);
  plate.scene.commit();
  plate.lights = study_lights(sun_angular_radius);
  const double rows = std::ceil(static_cast<double>(grains) / columns);
  const Eigen::Vector3d centre(0.0, 0.5 * (rows - 1) * 0.6 * pitch, 1e-3);
  plate.camera.target = centre;
  plate.camera.vertical_fov_degrees = 30.0;
  // The grid fills the image's width (its horizontal half-angle at 4:3 is 19.7°).
  const double reach = 0.42 * columns * pitch / std::tan(15.0 * std::numbers::pi / 180.0);
  plate.camera.position = centre + reach * Eigen::Vector3d(0.0, -std::cos(0.7), std::sin(0.7));
}

}  // namespace rice::experiments
