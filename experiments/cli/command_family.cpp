// A family of `rice` subcommands; see command_family.hpp.
#include "experiments/cli/command_family.hpp"

#include <CLI/CLI.hpp>

namespace rice::experiments {

void CommandFamily::validate() const {
  for (const Command& c : commands_)
    if (*c.app && c.validate) c.validate();
}

void CommandFamily::run() const {
  for (const Command& c : commands_)
    if (*c.app) c.run();
}

void CommandFamily::add(CLI::App* command, std::function<void()> validate, std::function<void()> run) {
  commands_.push_back({command, std::move(validate), std::move(run)});
}

}  // namespace rice::experiments
