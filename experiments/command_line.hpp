// The `rice` command line: every subcommand and option, each number with the range it must
// lie in, so that a bad number (NaN, an infinity, out of range) is refused before any work
// with a message that names the option. The option sweep test (tests/experiments) walks
// every option of every subcommand through it.
#pragma once

#include <memory>

namespace CLI {
class App;
}  // namespace CLI

namespace rice::experiments {

/// The whole `rice` command: parses, checks, runs; returns the exit code (0; 1 on an error,
/// with its message on stderr; 130 or 143 after Ctrl-C or SIGTERM, saying where it stopped).
int run_command_line(int argc, char** argv);

class CommandLine {
 public:
  CommandLine();
  ~CommandLine();

  CLI::App& app();

  /// --threads (0: all cores).
  int threads() const;

  /// After a successful parse: the checks that involve several options or read an input
  /// file, for the chosen command. Throws (CLI::ValidationError naming the option where one
  /// option is at fault, std::invalid_argument or std::runtime_error otherwise); does no work
  /// and writes nothing.
  void validate() const;

  /// Runs the chosen command (each command validates its settings before it writes).
  void run() const;

 private:
  struct Commands;
  std::unique_ptr<Commands> commands_;
};

}  // namespace rice::experiments
