// The pile cut half way up, in a container with a room (paper Fig. 16 b, a mould's fill; Fig.
// 15, the chawan): which grains are in it (in the mould's room, or within the bowl's rim; those
// that fell out, maybe far, stay out of the picture), the cut through their render meshes
// half way from the room's floor to the pile's top (pile_top: a few grains lifted above the
// pile do not set it) (section.png), and the packing fraction:
// the share of the room in that plane that grains cover (the room: the pixels outside the
// container's solid that connect to the one under the grains' mean centre). On a plate there
// is no room, and every figure is n/a.
#pragma once

#include <filesystem>

#include "experiments/scene/observer.hpp"
#include "experiments/scene/scene.hpp"

namespace rice::experiments {

/// The pose in which a mould's room counts its grains: its last before it is taken away (a
/// mould may be turned over first, as the bunny's is), or at the end of its keyframes.
xpbd::ColliderKeyframe room_pose(const xpbd::Collider& room);

class SectionObserver : public Observer {
 public:
  SectionObserver(const std::filesystem::path& folder, const Scene& scene);
  void end(const World& world, const Stepper& stepper, SceneReport& report) override;

 private:
  /// The collider whose room holds the grains (model.colliders index); -1 on a plate.
  int room_collider(const World& world) const;
  void cut(const World& world, const xpbd::Collider& room, const std::vector<int>& inside, SceneResult& result) const;

  std::filesystem::path folder_;
  bool fill_, plate_;
  int mould_;  ///< the fill's, among the scene's mesh colliders
};

}  // namespace rice::experiments
