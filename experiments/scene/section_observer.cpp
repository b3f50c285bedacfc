// The pile's section and packing; see section_observer.hpp.
#include "experiments/scene/section_observer.hpp"

#include <cmath>
#include <vector>

#include "experiments/io/csv_table.hpp"
#include "experiments/io/png_image.hpp"
#include "experiments/pile/pile_measures.hpp"
#include "experiments/pile/pile_section.hpp"

namespace rice::experiments {
namespace {

/// φ of the collider's room at p, in room_pose (> 0 inside the room).
double room_at(const xpbd::Collider& room, const xpbd::Vec3& p) {
  const xpbd::ColliderKeyframe pose = room_pose(room);
  return xpbd::posed_signed_distance(room, pose, xpbd::to_local(pose, p)).distance;
}

}  // namespace

xpbd::ColliderKeyframe room_pose(const xpbd::Collider& room) {
  return xpbd::collider_pose(room, room.removal_time);  // past the last keyframe: the last
}

SectionObserver::SectionObserver(const std::filesystem::path& folder, const Scene& scene)
    : folder_(folder),
      fill_(scene.emitter.kind == EmitterKind::kFill),
      plate_(scene.container.kind == Container::kPlate),
      mould_(scene.emitter.mould) {}

int SectionObserver::room_collider(const World& world) const {
  return fill_ ? world.first_mesh_collider + mould_ : plate_ ? -1 : 0;
}

void SectionObserver::cut(const World& world, const xpbd::Collider& room, const std::vector<int>& inside,
                          SceneResult& result) const {
  const double floor = fill_ ? 0.0 : world.bowl.height - world.bowl.inner_depth;
  std::vector<xpbd::Vec3> centres;
  for (int g : inside) centres.push_back(world.centre(g));
  result.section_height = 0.5 * (floor + pile_top(centres));
  // One render mesh at a time (~0.9 MB a grain): all of them at once were most of a run's peak
  // memory (720 of 790 MiB for 800 grains). The first pass finds the picture's bounds and the
  // grains the cut crosses, the second cuts those, made again.
  std::vector<int> crossed;
  Eigen::Vector2d lower = Eigen::Vector2d::Constant(INFINITY), upper = -lower, mean = Eigen::Vector2d::Zero();
  for (int g : inside) {
    const grains::SurfaceMesh mesh = world.render_mesh(g);
    lower = lower.cwiseMin(mesh.V.leftCols<2>().colwise().minCoeff().transpose());
    upper = upper.cwiseMax(mesh.V.leftCols<2>().colwise().maxCoeff().transpose());
    mean += world.centre(g).head<2>() / static_cast<double>(inside.size());
    const double z0 = mesh.V.col(2).minCoeff(), z1 = mesh.V.col(2).maxCoeff();
    if (z0 <= result.section_height && result.section_height <= z1) crossed.push_back(g);
  }
  if (!fill_) {  // the whole bowl in the picture
    lower = lower.cwiseMin(Eigen::Vector2d::Constant(-world.bowl.rim_radius));
    upper = upper.cwiseMax(Eigen::Vector2d::Constant(world.bowl.rim_radius));
  }
  PileSection section = empty_section(lower, upper, 1e-4);
  for (int g : crossed) add_to_section(section, world.render_mesh(g), result.section_height);
  const auto in_room = [&](const Eigen::Vector2d& p) {
    return room_at(room, xpbd::Vec3(p.x(), p.y(), result.section_height)) > 0.0;
  };
  const std::vector<char> region = region_around(section, in_room, mean);
  result.packing_fraction = packing_fraction(section, region);
  write_png(folder_ / "section.png", section_image(section, region));
}

void SectionObserver::end(const World& world, const Stepper&, SceneReport& report) {
  const int c = room_collider(world);
  RunInfoEntries& info = report.info;
  if (c < 0) {
    for (const char* key : {"grains_in_container", "section_height_m", "packing_fraction_in_room_at_section"})
      info.push_back({key, "n/a"});
    return;
  }
  const xpbd::Collider& room = world.model.colliders[c];
  std::vector<int> inside;
  for (int g = 0; g < world.released; ++g) {
    const xpbd::Vec3 centre = world.centre(g);
    if (fill_ ? room_at(room, centre) > 0.0 : centre.head<2>().norm() < world.bowl.rim_radius) inside.push_back(g);
  }
  SceneResult& r = report.result;
  r.in_container = static_cast<int>(inside.size());
  if (!inside.empty()) cut(world, room, inside, r);
  info.push_back({"grains_in_container", cell(r.in_container)});
  info.push_back({"section_height_m", cell(r.section_height)});
  info.push_back({"packing_fraction_in_room_at_section", cell(r.packing_fraction)});
}

}  // namespace rice::experiments
