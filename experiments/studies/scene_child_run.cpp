// Scene runs in processes of their own; see scene_child_run.hpp.
#include "experiments/studies/scene_child_run.hpp"

#include <stdexcept>

#include "experiments/io/child_process.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/run_info.hpp"

namespace rice::experiments {

void run_scene_child(const SceneChildRun& run, const std::filesystem::path& out, const std::string& what) {
  std::vector<std::string> argv{std::filesystem::read_symlink("/proc/self/exe").string()};
  if (run.threads > 0) argv.insert(argv.end(), {"--threads", std::to_string(run.threads)});
  argv.insert(argv.end(), {"run", std::filesystem::absolute(run.scene).string(), "--no-render", "--out", out.string()});
  for (const std::string& set : run.overrides) argv.insert(argv.end(), {"--set", set});
  const ProgramRun child = run_program(out.parent_path(), argv);
  stop_point();
  if (!child.succeeded) throw std::runtime_error(what + " failed: " + child.err);
}

double info_number(const std::filesystem::path& run, const std::string& key) {
  const std::string value = run_info_value(run / "run_info.txt", key);
  if (value.empty()) throw std::runtime_error((run / "run_info.txt").string() + ": no " + key);
  return std::stod(value);
}

}  // namespace rice::experiments
