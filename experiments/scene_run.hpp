// `rice run SCENE.toml --out DIR [--set section.key=value ...]`: runs a scene file
// (scene_file.hpp) into a folder, with a copy of the scene it ran.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "experiments/pour_scene.hpp"

namespace rice::experiments {

/// Reads the scene (a SceneError, and nothing written, when it is bad), then runs it into
/// `folder` with a copy of the scene file, the overrides listed at its end.
PourResult run_scene_command(const std::filesystem::path& scene_file, const std::vector<std::string>& overrides,
                       const std::filesystem::path& folder);

}  // namespace rice::experiments
