// The `rice` command line; see command_line.hpp.
#include "experiments/cli/command_line.hpp"

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include <iostream>
#include <string>

#include "experiments/cli/option_checks.hpp"
#include "experiments/io/interrupt.hpp"

namespace rice::experiments {
namespace {

// The chosen command's words ("study oscillator", "figure 11"), for messages.
std::string command_name(const CLI::App& app) {
  std::string name;
  for (const CLI::App* command = &app; !command->get_subcommands().empty();) {
    command = command->get_subcommands().front();
    if (!name.empty()) name += ' ';
    name += command->get_name();
  }
  return name;
}

}  // namespace

CommandLine::CommandLine()
    : app_(std::make_unique<CLI::App>("rice: a testbed for simulating and rendering freshly cooked rice")) {
  app_->require_subcommand(1);
  app_->add_option("--threads", threads_, "worker threads (0: all cores)")->check(number_in(0, 1024));
  families_.push_back(add_study_commands(*app_));
  families_.push_back(add_grain_commands(*app_));
  families_.push_back(add_render_commands(*app_));
  families_.push_back(add_figure_commands(*app_));
  families_.push_back(add_scene_commands(*app_));
}

CommandLine::~CommandLine() = default;

CLI::App& CommandLine::app() { return *app_; }

int CommandLine::threads() const { return threads_; }

void CommandLine::validate() const {
  for (const auto& family : families_) family->validate();
}

void CommandLine::run() const {
  for (const auto& family : families_) family->run();
}

int run_command_line(int argc, char** argv) {
  install_interrupt_handlers();
  CommandLine command_line;
  CLI::App& app = command_line.app();
  try {
    app.parse(argc, argv);
    std::unique_ptr<tbb::global_control> limit;
    if (command_line.threads() > 0)
      limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    command_line.threads());
    command_line.validate();
    command_line.run();
    stop_point();  // a Ctrl-C in a phase without stop points (writing, plotting) still stops
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const Interrupted& e) {
    const std::string doing = activity();  // empty where no progress was reported yet
    std::cerr << "rice: " << e.what() << " during " << (doing.empty() ? command_name(app) : doing)
              << "; the files written so far are complete\n";
    return 128 + e.signal();
  } catch (const std::exception& e) {
    std::cerr << "rice: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

}  // namespace rice::experiments
