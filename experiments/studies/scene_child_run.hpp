// A scene run in a process of its own (`rice run SCENE --no-render --out DIR --set ...`), for
// the studies that measure whole runs (scale, hard cases): its peak resident memory is its
// own, and what it measured is read back from its run_info.txt and stats.csv.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rice::experiments {

struct SceneChildRun {
  std::filesystem::path scene;
  std::vector<std::string> overrides;  ///< "section.key=value", as --set takes them
  int threads = 0;                     ///< 0: the machine's
};

/// Runs it into `out` (the current rice binary, in `out`'s parent folder); throws
/// std::runtime_error saying `what` failed, with the child's error output.
void run_scene_child(const SceneChildRun& run, const std::filesystem::path& out, const std::string& what);

/// A number of the run's run_info.txt; throws std::runtime_error naming the file when missing.
double info_number(const std::filesystem::path& run, const std::string& key);

}  // namespace rice::experiments
