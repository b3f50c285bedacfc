// A scene run: a short loop over named parts. The scene (scene.hpp, read by scene_file.hpp)
// gives the world builder (world_builder.hpp) its grains, bodies and colliders; the emitter
// (emitter.hpp) releases the grains over time; the stepper (stepper.hpp) advances the world a
// frame at a time; the observers (observer.hpp) write what each frame and the end show. The
// parts are listed in scene_parts.cpp. `rice run SCENE.toml --out DIR [--set section.key=value
// ...]` runs a scene file this way, with a copy of the scene it ran and its [render] image.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "experiments/render/render_command.hpp"
#include "experiments/scene/emitter.hpp"
#include "experiments/scene/scene.hpp"
#include "experiments/scene/scene_result.hpp"
#include "experiments/scene/world.hpp"

namespace rice::experiments {

/// How a run starts.
struct RunStart {
  bool resume = false;             ///< from the folder's checkpoint (checkpoint.hpp), or from frame 1
  std::uint64_t scene_digest = 0;  ///< of the scene's text as run, which its checkpoints carry
};

class SceneRun {
 public:
  /// Checks the scene (std::invalid_argument naming the key), builds its world and lays out
  /// its emitter (std::invalid_argument where it cannot); writes nothing.
  explicit SceneRun(const Scene& scene);
  ~SceneRun();

  /// Steps every frame into `folder` (created), or those after its checkpoint when resuming:
  /// the observers' files and checkpoints, then run_info.txt (and the checkpoint goes).
  /// Throws std::runtime_error when resuming from a checkpoint that is missing or refused.
  SceneResult run(const std::filesystem::path& folder, const RunStart& start = {});

 private:
  Scene scene_;
  std::unique_ptr<Emitter> emitter_;
  World world_;
  std::chrono::steady_clock::time_point start_;
};

/// SceneRun(scene).run(folder).
SceneResult run_scene(const Scene& scene, const std::filesystem::path& folder);

/// `rice run`'s flags.
struct RunCommandOptions {
  bool resume = false;  ///< after the folder's checkpoint, or from frame 1
  bool render = true;   ///< the scene's [render] section, if it has one
};

/// `rice run`: reads the scene file (a SceneError, and nothing written, when it is bad), then
/// runs it into `folder` with a copy of the file (scene.toml, the overrides listed at its end)
/// and renders its [render] section, as `options` say.
SceneResult run_scene_command(const std::filesystem::path& scene_file, const std::vector<std::string>& overrides,
                              const std::filesystem::path& folder, const RunCommandOptions& options = {});

/// `rice render --run` settings for the last frame of a scene's run in `run`: the image and
/// camera of `render`, the grains' CDRF at the scene's water content.
RenderCommandSettings scene_render_settings(const SceneRender& render, const Scene& scene,
                                            const std::filesystem::path& run);

}  // namespace rice::experiments
