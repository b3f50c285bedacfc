// A family of `rice` subcommands (`rice study ...`, `rice figure ...`), each family registered
// in its own file (*_commands.cpp): it adds its subcommands and their options to the app, and
// for each command how to check what the parse cannot (several options together, input files)
// and how to run it. After a parse, the family validates and runs the one command chosen.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace CLI {
class App;
}  // namespace CLI

namespace rice::experiments {

class CommandFamily {
 public:
  virtual ~CommandFamily() = default;

  /// The chosen command's checks: throws std::invalid_argument naming the setting at fault,
  /// or std::runtime_error naming an input file that cannot be read; writes nothing.
  void validate() const;
  /// Runs the chosen command, if it is one of this family's.
  void run() const;

 protected:
  void add(CLI::App* command, std::function<void()> validate, std::function<void()> run);

 private:
  struct Command {
    CLI::App* app;
    std::function<void()> validate, run;
  };
  std::vector<Command> commands_;
};

/// `rice study ...`: convergence, stiffness, contact, substeps, rendering and CDRF studies.
std::unique_ptr<CommandFamily> add_study_commands(CLI::App& app);
/// `rice figure 8|9|10|11|13` and `rice table 1`.
std::unique_ptr<CommandFamily> add_figure_commands(CLI::App& app);
/// `rice grains`: a library of procedural grains.
std::unique_ptr<CommandFamily> add_grain_commands(CLI::App& app);
/// `rice render`: meshes or a scene run's frame rendered with the CDRF.
std::unique_ptr<CommandFamily> add_render_commands(CLI::App& app);
/// `rice run SCENE.toml` and `rice scene-keys`.
std::unique_ptr<CommandFamily> add_scene_commands(CLI::App& app);

}  // namespace rice::experiments
