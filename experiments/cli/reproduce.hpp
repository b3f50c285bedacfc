// `rice reproduce` (the main job): every figure, table and study the testbed has, each by the
// `rice` command that makes it, into its own folder under `out`, and `out/index.md`, which
// shows each step's figures with its CSV files and the command that made them. A step whose
// folder holds a stamp of the same command, the same `rice` binary and the same contents of
// the scene files it reads is up to date and is skipped (`force` runs it anyway). `full`
// runs the paper's settings where a command has them (table 1's 3840 × 2160, 800 spp
// renders).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace rice::experiments {

struct ReproduceStep {
  std::string title;
  std::vector<std::string> arguments;  ///< the `rice` command line, with --out last
  std::filesystem::path folder;        ///< under `out`
  std::string after;                   ///< a step whose output this one reads: rerun when that one runs
  std::vector<std::filesystem::path> inputs;  ///< files or folders it reads: rerun when their contents change
};

/// The steps, in the order they run; `scenes` is the folder of the shipped scene files.
std::vector<ReproduceStep> reproduce_steps(const std::filesystem::path& out, bool full,
                                           const std::filesystem::path& scenes);

struct ReproduceSettings {
  bool full = false;
  bool force = false;
  std::vector<std::string> only;  ///< step folders' names to run (empty: every step)
  std::filesystem::path scenes = "experiments/scenes";
};

/// Throws std::invalid_argument for an `only` name that is no step's.
void validate(const ReproduceSettings& settings);

/// Runs the steps through `rice` (its exit status; 0 for success), skipping those up to date,
/// and writes out/index.md. Throws std::runtime_error naming the first step that fails.
void reproduce_command(const ReproduceSettings& settings, const std::filesystem::path& out,
                       const std::function<int(const std::vector<std::string>&)>& rice);

}  // namespace rice::experiments
