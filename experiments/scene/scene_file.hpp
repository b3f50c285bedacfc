// Scene files: a scene described in one TOML file (experiments/scenes/*.toml) and run by
// `rice run SCENE.toml --out DIR` (scene_run.hpp), without writing C++. Read strictly, before
// any work: a syntax error, a section or key that does not exist, a value of the wrong type or
// out of range stops the run with a SceneError whose message names the file, the line and the
// key and says what was expected. Every key, with its type, default, range and meaning, is in
// one table (scene_keys.hpp), which `rice scene-keys` prints as docs/scene-keys.md.
//
// Overrides (`--set section.key=value`, a TOML value) replace or add a key before reading, so
// a short variant of a scene is the same file with fewer grains or frames.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/scene/scene.hpp"

namespace rice::experiments {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads scene text; `source` names it in messages (a file path, whose folder mesh files are
/// found from). `overrides` are "section.key=value" strings applied before reading.
Scene parse_scene(std::string_view text, const std::string& source, const std::vector<std::string>& overrides = {});

/// The file's text (SceneError when it cannot be read).
std::string read_scene_text(const std::filesystem::path& path);

/// Reads a scene file (SceneError when it cannot be read).
Scene read_scene_file(const std::filesystem::path& path, const std::vector<std::string>& overrides = {});

}  // namespace rice::experiments
