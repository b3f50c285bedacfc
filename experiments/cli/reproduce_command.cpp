// `rice reproduce`: the main job (reproduce.hpp), each step run through `rice` itself.
#include <CLI/CLI.hpp>

#include "experiments/cli/command_family.hpp"
#include "experiments/cli/reproduce.hpp"

namespace rice::experiments {
namespace {

class ReproduceCommand : public CommandFamily {
 public:
  ReproduceCommand(CLI::App& app, std::function<int(const std::vector<std::string>&)> rice) : rice_(std::move(rice)) {
    CLI::App* c = app.add_subcommand("reproduce", "every figure, table and study into out/, with out/index.md");
    c->add_option("--out", out_, "output folder")->capture_default_str();
    c->add_flag("--full", settings_.full, "the paper's settings where a command has them (long)");
    c->add_flag("--force", settings_.force, "rerun the steps that are up to date too");
    c->add_option("--only", settings_.only, "run only these steps (their folders' names)");
    c->add_option("--scenes", settings_.scenes, "the folder of the shipped scene files")->capture_default_str();
    add(c, [this] { experiments::validate(settings_); }, [this] { reproduce_command(settings_, out_, rice_); });
  }

 private:
  std::function<int(const std::vector<std::string>&)> rice_;
  ReproduceSettings settings_;
  std::string out_ = "out";
};

}  // namespace

std::unique_ptr<CommandFamily> add_reproduce_command(CLI::App& app,
                                                     std::function<int(const std::vector<std::string>&)> rice) {
  return std::make_unique<ReproduceCommand>(app, std::move(rice));
}

}  // namespace rice::experiments
