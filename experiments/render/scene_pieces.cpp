// The pieces of a rice render; see scene_pieces.hpp.
#include "experiments/render/scene_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "grains/water_content.hpp"
#include "shading/curvature.hpp"
#include "shading/smooth_normals.hpp"
#include "shading/thickness.hpp"

namespace rice::experiments {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

}  // namespace

shading::Material rice_material(double absorption_percent) {
  return {.kind = shading::MaterialKind::kRice,
          .albedo = shading::Color::Constant(static_cast<float>(grains::WaterContentModel::cdrf_albedo(absorption_percent))),
          .sigma0 = grains::WaterContentModel::scattering_sigma0(absorption_percent),
          .refractive_index = grains::WaterContentModel::optics(absorption_percent).refractive_index,
          .roughness = 0.25};
}

shading::Medium grain_medium(double absorption_percent) {
  const grains::GrainOptics optics = grains::WaterContentModel::optics(absorption_percent);
  return {optics.reduced_scattering, optics.absorption, 0.0, optics.refractive_index};
}

GrainShading grain_shading(const shading::MeshVertices& V, const shading::MeshTriangles& F, double shading_radius) {
  return {.curvature = shading::smoothed_vertex_values(V, F, shading::vertex_mean_curvature(V, F),
                                                       curvature_radius(shading_radius)),
          .thickness = shading::vertex_thickness(V, F),
          .normals = shading::smoothed_vertex_normals(V, F, shading_radius)};
}

int add_grain_prototype(shading::RenderScene& scene, const shading::MeshVertices& V, const shading::MeshTriangles& F,
                        const GrainShading& shading, shading::RenderScene::Reuse reuse) {
  const int prototype = scene.add_prototype(V, F, shading.curvature, reuse);
  scene.set_thickness(prototype, shading.thickness);
  scene.set_shading_normals(prototype, shading.normals);
  return prototype;
}

int add_grain_prototype(shading::RenderScene& scene, const shading::MeshVertices& V, const shading::MeshTriangles& F,
                        double shading_radius) {
  return add_grain_prototype(scene, V, F, grain_shading(V, F, shading_radius));
}

void add_ground(shading::RenderScene& scene, double x0, double y0, double x1, double y1, double z, int material) {
  shading::MeshVertices V(4, 3);
  V << x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z;
  shading::MeshTriangles F(2, 3);
  F << 0, 1, 2, 0, 2, 3;
  scene.add_instance(scene.add_prototype(V, F), Eigen::Affine3d::Identity(), material);
}

Eigen::Vector3d direction_from(double elevation_degrees, double azimuth_degrees) {
  const double e = elevation_degrees * kDegree, a = azimuth_degrees * kDegree;
  return {std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e)};
}

}  // namespace rice::experiments
