// The `rice` command line: every subcommand and option, each number with the range it must
// lie in, so that a bad number (NaN, an infinity, out of range) is refused before any work
// with a message that names the option. Each family of subcommands is registered in its own
// file (command_family.hpp). The option sweep test (tests/experiments/cli) walks every option
// of every subcommand through it.
#pragma once

#include <memory>
#include <vector>

#include "experiments/cli/command_family.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace rice::experiments {

/// The whole `rice` command: parses, checks, runs; returns the exit code (0; 1 on an error,
/// with its message on stderr; 130 or 143 after Ctrl-C or SIGTERM, saying where it stopped,
/// even when the signal came after the last stop point of the run).
int run_command_line(int argc, char** argv);

class CommandLine {
 public:
  CommandLine();
  ~CommandLine();

  CLI::App& app();

  /// --threads (0: all cores).
  int threads() const;

  /// After a successful parse: the checks that involve several options or read an input
  /// file, for the chosen command. Throws std::invalid_argument naming the setting at fault,
  /// or std::runtime_error naming an input file that cannot be read; does no work and writes
  /// nothing. (Single options out of range are refused by the parse itself, naming them.)
  void validate() const;

  /// Runs the chosen command (each command validates its settings before it writes).
  void run() const;

 private:
  std::unique_ptr<CLI::App> app_;
  int threads_ = 0;
  std::vector<std::unique_ptr<CommandFamily>> families_;
};

}  // namespace rice::experiments
