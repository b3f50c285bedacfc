// `rice run`; see scene_run.hpp.
#include "experiments/scene_run.hpp"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "experiments/output.hpp"
#include "experiments/scene_file.hpp"

namespace rice::experiments {

PourResult run_scene_command(const std::filesystem::path& scene_file, const std::vector<std::string>& overrides,
                       const std::filesystem::path& folder) {
  std::ifstream in(scene_file, std::ios::binary);
  if (!in) throw SceneError(scene_file.string() + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  const SceneDescription scene = parse_scene(text.str(), scene_file.string(), overrides);
  validate(scene.pour);
  make_output_folder(folder);
  std::string copy = text.str();
  if (!overrides.empty()) {
    copy += "\n# overridden on the command line (rice run --set):\n";
    for (const std::string& o : overrides) copy += "#   " + o + "\n";
  }
  write_file_atomically(folder / "scene.toml", copy);
  std::printf("scene %s: %s\n", scene.name.c_str(), scene.description.c_str());
  return pour_command(scene.pour, folder);
}

}  // namespace rice::experiments
