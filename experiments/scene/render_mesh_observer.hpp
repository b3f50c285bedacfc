// Each frame's deformed render meshes ([effects] render_meshes), frames/frame_NNNN.ply: every
// grain's render mesh through its embedding in its simulation mesh, all in one mesh. Large;
// off by default, and then it costs nothing.
#pragma once

#include <filesystem>

#include "experiments/scene/observer.hpp"

namespace rice::experiments {

class RenderMeshObserver : public Observer {
 public:
  explicit RenderMeshObserver(const std::filesystem::path& folder) : folder_(folder / "frames") {}
  void begin(const World& world) override;
  void observe(const World& world, const Stepper& stepper, int frame, double wall_seconds) override;

 private:
  std::filesystem::path folder_;
};

}  // namespace rice::experiments
