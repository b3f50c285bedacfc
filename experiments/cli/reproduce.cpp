// The main job as one command; see reproduce.hpp.
#include "experiments/cli/reproduce.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/content_digest.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"

namespace rice::experiments {
namespace {

std::string command_text(const std::vector<std::string>& arguments) {
  std::string text = "rice";
  for (const std::string& a : arguments) text += " " + a;
  return text;
}

/// A digest of the files at `input` (a file, or a folder's files in path order) and their
/// paths (content_digest.hpp).
std::string digest_of(const std::filesystem::path& input) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  if (std::filesystem::is_directory(input, error)) {
    for (auto it = std::filesystem::recursive_directory_iterator(input, error);
         !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error))
      if (it->is_regular_file()) files.push_back(it->path());
    std::sort(files.begin(), files.end());
  } else {
    files.push_back(input);
  }
  std::uint64_t hash = kDigestBasis;
  const auto mix = [&](const std::string& bytes) { hash = content_digest(bytes, hash); };
  for (const auto& file : files) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    mix(file.string() + (in ? "\n" : " (missing)\n"));
    mix(bytes.str());
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

/// What makes a step's output current: its command, the binary that ran it and its inputs.
std::string stamp_of(const ReproduceStep& step) {
  std::error_code error;
  const auto binary = std::filesystem::read_symlink("/proc/self/exe", error);
  const auto time = error ? std::filesystem::file_time_type{} : std::filesystem::last_write_time(binary, error);
  std::string stamp = command_text(step.arguments) + "\nbinary " + binary.string() + " " +
                      std::to_string(time.time_since_epoch().count()) + "\n";
  for (const auto& input : step.inputs) stamp += "input " + input.string() + " " + digest_of(input) + "\n";
  return stamp;
}

std::filesystem::path stamp_path(const ReproduceStep& step) { return step.folder / "reproduce.stamp"; }

bool up_to_date(const ReproduceStep& step) {
  std::ifstream in(stamp_path(step));
  std::stringstream text;
  text << in.rdbuf();
  return in && text.str() == stamp_of(step);
}

/// The step's files of one extension, sorted, relative to `out`.
std::vector<std::filesystem::path> files_of(const std::filesystem::path& folder, const std::filesystem::path& out,
                                            const std::string& extension) {
  std::vector<std::filesystem::path> found;
  std::error_code error;
  for (auto it = std::filesystem::recursive_directory_iterator(folder, error);
       !error && it != std::filesystem::recursive_directory_iterator(); it.increment(error)) {
    const auto& path = it->path();
    // Not a run's frames (frames/frame_NNNN.csv) nor a video's (frame_NNNN.png).
    if (path.extension() == extension && path.string().find("/frames/") == std::string::npos &&
        !path.filename().string().starts_with("frame_"))
      found.push_back(std::filesystem::relative(path, out));
  }
  std::sort(found.begin(), found.end());
  return found;
}

// Each step: its title, its command (--out added by reproduce_steps), its folder, the step it
// reads and the files it reads.

/// The solvers' studies, the grains' figures and the heaps.
std::vector<ReproduceStep> solver_and_grain_steps(const std::filesystem::path& scenes) {
  // 400 grains poured slowly from high up onto a plate, with and without cohesion.
  const std::vector<std::string> heap{"run", (scenes / "heap.toml").string(), "--set", "grains.count=400", "--set",
                                      "solver.frames=180", "--set", "emitter.seconds=3.5", "--set", "emitter.height_m=0.05"};
  std::vector<std::string> heap_dry = heap;
  heap_dry.insert(heap_dry.end(), {"--set", "effects.cohesion=false"});
  return {
      {"XPBD stiffness: compliance against the analytic stiffness", {"study", "xpbd-stiffness"}, "xpbd-stiffness", "",
       {}},
      {"Damped oscillator: XPBD and the reference against the analytic decay", {"study", "oscillator"}, "oscillator",
       "", {}},
      {"Convergence: XPBD, XPBD with primal correction and VBD against backward Euler", {"study", "convergence"},
       "convergence", "", {}},
      {"Fig. 8: japonica grains of different sizes", {"figure", "8"}, "figure8", "", {}},
      {"Fig. 9: three cultivars and their dimensions", {"figure", "9"}, "figure9", "", {}},
      {"Fig. 11: water absorption and damping against soak time", {"figure", "11"}, "figure11", "", {}},
      {"A grain library (10 japonica grains)", {"grains", "--cultivar", "japonica", "--count", "10"}, "grains", "", {}},
      {"A heap on a plate, with cohesion", heap, "heap", "", {scenes / "heap.toml"}},
      {"A heap on a plate, without cohesion", heap_dry, "heap-dry", "", {scenes / "heap.toml"}},
      {"Pour: penetration and time against substeps", {"study", "pour-substeps"}, "pour-substeps", "", {}},
      {"One grain: error and time against substeps, XPBD and VBD", {"study", "grain-substeps"}, "grain-substeps", "",
       {}},
      {"Grain meshes: XPBD's stable substep against tet quality", {"study", "tet-quality"}, "tet-quality", "", {}},
      {"Contact: Hertz, a grain on the ground, two grains pressed together", {"study", "contact"}, "contact", "", {}},
      {"Scene scale: a soft shari by XPBD and VBD against a converged run",
       {"study", "scene-convergence", "--scene", (scenes / "shari.toml").string()},
       "scene-convergence",
       "",
       {scenes / "shari.toml"}},
  };
}

/// The shading fits, the paper's scenes (figure 10, table 1), the pressed clump, the rice
/// cooker, the full-size chawan, the hard cases and the scale study.
std::vector<ReproduceStep> shading_fit_and_scene_steps(const std::filesystem::path& out, bool full,
                                                       const std::filesystem::path& scenes) {
  return {
      {"CDRF: the fit against the random-walk reference", {"study", "cdrf"}, "cdrf", "", {}},
      {"The translucent model: light through the grain fitted per water content (shading/data/translucency.csv)",
       {"study", "translucency"}, "translucency", "", {}},
      {"Fig. 10: a block of grains dropped from a cup after three soak times",
       {"figure", "10", "--scene", (scenes / "drop_cup.toml").string()},
       "figure10",
       "",
       {scenes / "drop_cup.toml", scenes / "meshes" / "drop_cup.obj"}},
      {"Table 1 and Figs. 14-17: shari, chawan, onigiri, bunny",
       full ? std::vector<std::string>{"table", "1", "--scenes", scenes.string(), "--full"}
            : std::vector<std::string>{"table", "1", "--scenes", scenes.string()},
       "table1",
       "",
       {scenes}},
      {"A box pressing a clump of grains (scene file)",
       {"run", (scenes / "press.toml").string()},
       "press",
       "",
       {scenes / "press.toml"}},
      {"Soft grains' curvature: the rest curvature against the deformed one, on the pressed clump",
       {"study", "soft-curvature", "--run", (out / "press").string()},
       "soft-curvature",
       "press",
       {}},
      {"A rice cooker: grains settled in its pot, a portion lifted out by a paddle (a tenth; all with --full)",
       full ? std::vector<std::string>{"run", (scenes / "rice_cooker.toml").string()}
            : std::vector<std::string>{"run", (scenes / "rice_cooker.toml").string(), "--set", "grains.count=3400"},
       "rice-cooker",
       "",
       {scenes / "rice_cooker.toml", scenes / "meshes"}},
      {"A real serving: 3000 soft grains heaped in a chawan 12 cm across",
       {"run", (scenes / "chawan_serving.toml").string()},
       "chawan-serving",
       "",
       {scenes / "chawan_serving.toml"}},
      {"Hard cases: the bunny pressed to 80% and released, a clump dropped into the cooker (a tenth; all with --full)",
       full ? std::vector<std::string>{"study", "hard-cases", "--scenes", scenes.string()}
            : std::vector<std::string>{"study", "hard-cases", "--scenes", scenes.string(), "--bunny-grains", "360",
                                       "--cooker-grains", "3400"},
       "hard-cases",
       "",
       {scenes / "cases", scenes / "meshes"}},
      {"Scale: time and memory per grain for clumps of 100 to 3000 grains (to 34,000 with --full)",
       full ? std::vector<std::string>{"study", "scale", "--scene", (scenes / "drop.toml").string()}
            : std::vector<std::string>{"study", "scale", "--scene", (scenes / "drop.toml").string(), "--counts", "100",
                                       "300", "1000", "3000"},
       "scale",
       "",
       {scenes / "drop.toml"}},
  };
}

/// Figure 13, the rendering studies and the renders of table 1's runs: the chawan's last
/// frame, its 4K cost and every paper scene's video.
std::vector<ReproduceStep> rendering_steps(const std::filesystem::path& out) {
  std::vector<ReproduceStep> steps{
      {"Fig. 13: grains soaked for five times: the CDRF, the translucent model, the path tracer", {"figure", "13"},
       "figure13", "", {}},
      {"Rendering: error against time for the samplers and every model against the path tracer", {"study", "render"},
       "render-study", "", {}},
      {"Rendering: the path tracer's depth, and the CDRF against it", {"study", "path-depth"}, "path-depth", "", {}},
      {"The chawan's last frame, 960 x 540 at 64 spp (docs/images/chawan.png)",
       {"render", "--run", (out / "table1" / "chawan").string(), "--width", "960", "--height", "540", "--spp", "64",
        "--eye", "0", "-0.075", "0.085", "--look-at", "0", "0", "0.022", "--fov", "35"},
       "render-chawan", "table1", {}},
      {"Rendering: the chawan's last frame at 3840 x 2160, its equal-error sample count and each model's time",
       {"study", "frame-cost", "--run", (out / "table1" / "chawan").string()}, "frame-cost", "table1", {}},
  };
  // Every frame of each paper scene's run, as a video and a contact sheet. A soft grain within
  // 0.2 mm of its rigid fit, under a pixel here, is drawn as an instance of its variant: as its
  // own mesh, 500 of the chawan's 800 grains made a frame 5 s, not 1 s.
  for (const std::string scene : {"shari", "chawan", "onigiri", "bunny"})
    steps.push_back({"Video: the " + scene + " run, every frame at 480 x 270, 8 spp (render.mp4)",
                     {"render", "--run", (out / "table1" / scene).string(), "--every-frame", "--video", "--width",
                      "480", "--height", "270", "--spp", "8", "--soft-instance-tolerance", "2e-4"},
                     "video-" + scene, "table1", {}});
  return steps;
}

}  // namespace

std::vector<ReproduceStep> reproduce_steps(const std::filesystem::path& out, bool full,
                                           const std::filesystem::path& scenes) {
  std::vector<ReproduceStep> steps = solver_and_grain_steps(scenes);
  for (const auto& part : {shading_fit_and_scene_steps(out, full, scenes), rendering_steps(out)})
    steps.insert(steps.end(), part.begin(), part.end());
  for (ReproduceStep& step : steps) {
    step.folder = out / step.folder;
    step.arguments.push_back("--out");
    step.arguments.push_back(step.folder.string());
  }
  return steps;
}

void validate(const ReproduceSettings& settings) {
  const auto steps = reproduce_steps("out", settings.full, settings.scenes);
  for (const std::string& name : settings.only)
    if (std::none_of(steps.begin(), steps.end(), [&](const ReproduceStep& s) { return s.folder.filename() == name; })) {
      std::string names;
      for (const ReproduceStep& s : steps) names += (names.empty() ? "" : ", ") + s.folder.filename().string();
      throw std::invalid_argument("reproduce: no step '" + name + "'; steps: " + names);
    }
}

void reproduce_command(const ReproduceSettings& settings, const std::filesystem::path& out,
                       const std::function<int(const std::vector<std::string>&)>& rice) {
  validate(settings);
  std::filesystem::create_directories(out);
  const auto steps = reproduce_steps(out, settings.full, settings.scenes);
  std::vector<std::string> status(steps.size(), "not run (--only)");
  for (size_t k = 0; k < steps.size(); ++k) {
    const ReproduceStep& step = steps[k];
    const std::string name = step.folder.filename().string();
    if (!settings.only.empty() && std::find(settings.only.begin(), settings.only.end(), name) == settings.only.end())
      continue;
    const bool input_changed = !step.after.empty() && std::any_of(steps.begin(), steps.end(), [&](const ReproduceStep& s) {
      return s.folder.filename() == step.after && status[&s - steps.data()].starts_with("ran");
    });
    if (!settings.force && !input_changed && up_to_date(step)) {
      status[k] = "up to date (skipped)";
      std::printf("reproduce %zu/%zu %s: up to date\n", k + 1, steps.size(), name.c_str());
      continue;
    }
    std::printf("reproduce %zu/%zu %s: %s\n", k + 1, steps.size(), name.c_str(), command_text(step.arguments).c_str());
    std::fflush(stdout);
    const auto start = std::chrono::steady_clock::now();
    const int exit_status = rice(step.arguments);
    if (exit_status != 0)
      throw std::runtime_error("reproduce: step '" + name + "' failed (exit status " + std::to_string(exit_status) +
                               "): " + command_text(step.arguments));
    status[k] = "ran in " + fixed(seconds_since(start), 1) + " s";
    write_file_atomically(stamp_path(step), stamp_of(step));
  }
  // The index: each step's command, status, figures and tables, from what its folder holds.
  std::string index = "# Results\n\nMade by `rice reproduce" + std::string(settings.full ? " --full" : "") +
                      "`; each step's folder holds its run_info.txt. Re-running skips the steps that are up to "
                      "date.\n";
  for (size_t k = 0; k < steps.size(); ++k) {
    const ReproduceStep& step = steps[k];
    index += "\n## " + step.title + "\n\n`" + command_text(step.arguments) + "` — " + status[k] + "\n\n";
    for (const auto& markdown : files_of(step.folder, out, ".md")) {
      std::ifstream in(out / markdown);
      std::stringstream text;
      text << in.rdbuf();
      index += text.str() + "\n";
    }
    for (const auto& image : files_of(step.folder, out, ".png")) index += "![" + image.string() + "](" + image.string() + ")\n";
    for (const auto& video : files_of(step.folder, out, ".mp4"))
      index += "\nVideo: [" + video.string() + "](" + video.string() + ")\n";
    const auto tables = files_of(step.folder, out, ".csv");
    if (!tables.empty()) {
      index += "\nData:";
      for (const auto& table : tables) index += " [" + table.string() + "](" + table.string() + ")";
      index += "\n";
    }
  }
  write_file_atomically(out / "index.md", index);
  std::printf("reproduce: %s\n", (out / "index.md").string().c_str());
}

}  // namespace rice::experiments
