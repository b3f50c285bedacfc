// The files that redraw a run; see scene_geometry_observer.hpp.
#include "experiments/scene/scene_geometry_observer.hpp"

#include <cmath>
#include <sstream>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "grains/mesh_io.hpp"

namespace rice::experiments {
namespace {

/// Bowl outline for the plots: the inside wall's profile r(z) on both sides.
std::string bowl_outline(const grains::ChawanShape& s) {
  std::ostringstream out;
  out << "r,z\n";
  const double a = s.rim_radius - s.wall_thickness;
  for (int k = -40; k <= 40; ++k) {
    const double theta = M_PI / 2 * k / 40.0;
    out << cell(a * std::sin(theta)) << ',' << cell(s.height - s.inner_depth * std::cos(theta)) << '\n';
  }
  return out.str();
}

CsvTable placement_table(const World& world) {
  CsvTable placement({"grain", "variant", "swell", "qw", "qx", "qy", "qz", "drop_x", "drop_y", "drop_z", "centre_x",
                      "centre_y", "centre_z"});
  for (int g = 0; g < world.count(); ++g) {
    const grains::GrainInstance& instance = world.instances[g];
    const Eigen::Quaterniond& R = instance.rotation;
    const xpbd::Vec3& drop = world.drops[g];
    const xpbd::Vec3& c0 = world.initial_centre[g];
    placement.add_row({cell(g), cell(instance.variant), cell(instance.swell), cell(R.w()), cell(R.x()), cell(R.y()),
                       cell(R.z()), cell(drop.x()), cell(drop.y()), cell(drop.z()), cell(c0.x()), cell(c0.y()),
                       cell(c0.z())});
  }
  return placement;
}

}  // namespace

std::vector<ColliderDrawing> collider_drawings(const Scene& scene) {
  std::vector<ColliderDrawing> drawings;
  for (std::size_t k = 0; k < scene.colliders.size(); ++k)
    drawings.push_back({collider_surface(scene.colliders[k]), scene.collider_materials.at(k), scene.colliders[k]});
  for (const MeshCollider& m : scene.mesh_colliders) drawings.push_back({m.mesh, m.material, m.collider, m.hollow});
  return drawings;
}

void SceneGeometryObserver::begin(const World& world) {
  if (chawan_) {
    const grains::SurfaceMesh bowl = grains::make_chawan(world.bowl);
    write_file_atomically(folder_ / "chawan.obj", [&](std::ostream& out) { grains::write_obj(out, bowl); });
    write_file_atomically(folder_ / "bowl_outline.csv", bowl_outline(world.bowl));
  }
  make_output_folder(folder_ / "variants");
  for (size_t i = 0; i < world.variants.size(); ++i)
    write_file_atomically(folder_ / "variants" / ("variant_" + std::to_string(i) + ".ply"),
                          [&](std::ostream& out) { grains::write_ply(out, world.variants[i].grain.render); });
  if (!world.rigid())
    for (size_t i = 0; i < world.variants.size(); ++i)
      write_file_atomically(folder_ / "variants" / ("variant_" + std::to_string(i) + ".mesh"),
                            [&](std::ostream& out) { grains::write_medit(out, world.variants[i].grain.simulation); });
  write_file_atomically(folder_ / "grains.csv", placement_table(world).text());
  write_collider_drawings(colliders_, folder_);
}

}  // namespace rice::experiments
