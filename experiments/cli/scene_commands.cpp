// `rice run SCENE.toml` (a scene file, scene/scene_run.hpp) and `rice scene-keys` (every key a
// scene file may hold, as Markdown: docs/scene-keys.md).
#include <CLI/CLI.hpp>

#include <iostream>

#include "experiments/cli/command_family.hpp"
#include "experiments/scene/scene_file.hpp"
#include "experiments/scene/scene_keys.hpp"
#include "experiments/scene/scene_run.hpp"

namespace rice::experiments {
namespace {

class SceneCommands : public CommandFamily {
 public:
  explicit SceneCommands(CLI::App& app) {
    CLI::App* run = app.add_subcommand("run", "runs a scene file (experiments/scenes/*.toml)");
    run->add_option("scene", scene_, "the scene's TOML file")->required();
    run->add_option("--out", out_, "output folder")->capture_default_str();
    run->add_option("--set", overrides_, "section.key=value: overrides a key of the file (repeatable)");
    run->add_flag("--resume", options_.resume,
                  "continue from the last checkpoint in --out (the same scene file and --set overrides)");
    run->add_flag("!--no-render", options_.render, "skip the scene's [render] section");
    add(run, [this] { experiments::validate(read_scene_file(scene_, overrides_)); },
        [this] { run_scene_command(scene_, overrides_, out_, options_); });
    CLI::App* keys = app.add_subcommand("scene-keys", "every key a scene file may hold, as Markdown (docs/scene-keys.md)");
    add(keys, nullptr, [] { std::cout << scene_keys_markdown(); });
  }

 private:
  std::string scene_, out_ = "out/scene";
  std::vector<std::string> overrides_;
  RunCommandOptions options_;
};

}  // namespace

std::unique_ptr<CommandFamily> add_scene_commands(CLI::App& app) { return std::make_unique<SceneCommands>(app); }

}  // namespace rice::experiments
