// `rice run SCENE.toml --out DIR [--set section.key=value ...]`: runs a scene file
// (scene_file.hpp) into a folder, with a copy of the scene it ran.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "experiments/scene/pour_scene.hpp"
#include "experiments/render/render_command.hpp"
#include "experiments/scene/scene_file.hpp"

namespace rice::experiments {

struct SceneResult {
  PourResult pour;
  double render_seconds = 0.0;  ///< the [render] section's image (0: the scene has none)
};

/// Reads the scene (a SceneError, and nothing written, when it is bad), then runs it into
/// `folder` with a copy of the scene file, the overrides listed at its end.
SceneResult run_scene_command(const std::filesystem::path& scene_file, const std::vector<std::string>& overrides,
                              const std::filesystem::path& folder);

/// `rice render --pour` settings for the last frame of a scene's run in `run`: the image and
/// camera of `render`, the grains' CDRF at the scene's water content.
RenderCommandSettings scene_render_settings(const SceneRender& render, const PourSettings& pour,
                                            const std::filesystem::path& run);

}  // namespace rice::experiments
