// Paper Table 1 side by side; see table1.hpp.
#include "experiments/figures/table1.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/scene/scene_file.hpp"
#include "experiments/scene/scene_run.hpp"

namespace rice::experiments {
namespace {

/// A row of the paper's Table 1: its figure, grains and times (i9-9900X, Quadro P2200).
struct PaperRow {
  const char* scene;
  int figure;
  int grains;
  double simulation_seconds;  ///< 180 frames
  double render_seconds;      ///< 3840 × 2160, 800 samples
};

constexpr double hms(int h, int m, int s) { return 3600.0 * h + 60.0 * m + s; }

constexpr PaperRow kPaper[] = {
    {"shari", 14, 270, hms(2, 5, 23), hms(0, 42, 48)},
    {"chawan", 15, 800, hms(4, 26, 22), hms(1, 25, 26)},
    {"onigiri", 16, 793, hms(4, 53, 42), hms(2, 20, 5)},
    {"bunny", 17, 3600, hms(12, 32, 50), hms(3, 54, 8)},
};

/// What the scene simulates: body model, the effects that are on, colliders and emitter.
std::string simulated_effects(const Scene& p) {
  const bool fill = p.emitter.kind == EmitterKind::kFill;
  std::string text = p.grains.body == xpbd::BodyKind::kRigid ? "rigid grains" : "soft grains";
  if (p.effects.static_friction > 0.0) text += "; friction";
  if (p.effects.cohesion) text += "; cohesion (" + cell(p.grains.soak_minutes) + " min soak)";
  if (p.grains.body == xpbd::BodyKind::kSoft && p.effects.damping) text += "; damping";
  if (p.effects.sleeping) text += "; sleeping";
  text += p.container.kind == Container::kChawan ? "; chawan" : "; plate";
  if (fill) text += "; grains dropped into a mould";
  const size_t kinematic = p.colliders.size() + p.mesh_colliders.size() - (fill ? 1 : 0);
  if (kinematic > 0) text += "; " + std::to_string(kinematic) + " more collider(s)";
  for (const MeshCollider& m : p.mesh_colliders)
    if (std::isfinite(m.collider.removal_time)) text += "; mould taken away at " + cell(m.collider.removal_time) + " s";
  return text;
}

/// What the render shows (no commas: a CSV field).
std::string rendered_effects(const SceneRender& r) {
  return "CDRF at the soak's water content; sun " + cell(r.sun_irradiance) + "; sky " + cell(r.sky_radiance) +
         (r.ground ? "; ground" : "");
}

std::string ratio(double paper, double ours) { return ours > 0.0 ? fixed(paper / ours, 0) + "x" : "n/a"; }

/// One scene's runs: its own (soft grains by default) and, for the rigid column, with rigid
/// grains.
struct RowRuns {
  SceneResult scene, rigid;
  double full_render_seconds = NAN;
};

RowRuns run_row(const Table1Settings& s, const PaperRow& row, const Scene& scene, const std::filesystem::path& folder) {
  const std::filesystem::path file = s.scenes / (std::string(row.scene) + ".toml");
  const std::filesystem::path run = folder / row.scene;
  RowRuns runs;
  runs.scene = run_scene_command(file, s.overrides, run);
  if (s.full) {
    SceneRender paper_setting = *scene.render;
    paper_setting.width = 3840, paper_setting.height = 2160, paper_setting.samples_per_pixel = 800;
    const auto start = std::chrono::steady_clock::now();
    render_command(scene_render_settings(paper_setting, scene, run), run / "render_full");
    runs.full_render_seconds = seconds_since(start);
  }
  if (scene.grains.body != xpbd::BodyKind::kRigid) {
    std::vector<std::string> rigid = s.overrides;
    rigid.push_back("grains.body=\"rigid\"");
    runs.rigid = run_scene_command(file, rigid, folder / (std::string(row.scene) + "_rigid"));
  } else {
    runs.rigid = runs.scene;
  }
  return runs;
}

std::string markdown_row(const PaperRow& row, const Scene& scene, const RowRuns& runs, bool full,
                         const std::string& preview) {
  const double simulation = runs.scene.simulation_seconds;
  return "| " + std::to_string(row.figure) + " | " + row.scene + " | " + std::to_string(scene.grains.count) + " (" +
         std::to_string(runs.scene.released) + " in) | " + std::to_string(scene.solver.frames) + " | " +
         fixed(simulation, 1) + " s | " + fixed(runs.rigid.simulation_seconds, 1) + " s | " +
         fixed(row.simulation_seconds, 0) + " s | " + ratio(row.simulation_seconds, simulation) + " | " +
         fixed(runs.scene.render_seconds, 1) + " s (" + preview + ") | " +
         (full ? fixed(runs.full_render_seconds, 0) + " s" : "not run (--full)") + " | " +
         fixed(row.render_seconds, 0) + " s | " + (full ? ratio(row.render_seconds, runs.full_render_seconds) : "n/a") +
         " |\n";
}

}  // namespace

void table1_command(const Table1Settings& s, const std::filesystem::path& folder) {
  // Every scene reads before any runs.
  std::vector<Scene> scenes;
  for (const PaperRow& row : kPaper) {
    scenes.push_back(read_scene_file(s.scenes / (std::string(row.scene) + ".toml"), s.overrides));
    validate(scenes.back());
    if (!scenes.back().render) throw SceneError(std::string(row.scene) + ".toml: table 1 needs its [render] section");
  }
  make_output_folder(folder);
  CsvTable table({"figure", "scene", "grains", "grains_in", "paper_grains", "frames", "simulation_s",
                  "rigid_simulation_s", "paper_simulation_s", "simulation_speedup", "preview", "render_preview_s",
                  "render_full_s", "paper_render_s", "render_speedup", "simulated", "rendered"});
  std::string markdown =
      "| Fig. | scene | grains | frames | simulation | rigid grains | paper | speed-up | render (preview) | render "
      "3840×2160, 800 spp | paper | speed-up |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  std::string effects;
  for (size_t k = 0; k < scenes.size(); ++k) {
    const PaperRow& row = kPaper[k];
    const Scene& scene = scenes[k];
    std::printf("table 1: %s (%d grains, %d frames)\n", row.scene, scene.grains.count, scene.solver.frames);
    const RowRuns runs = run_row(s, row, scene, folder);
    const std::string preview = std::to_string(scene.render->width) + "x" + std::to_string(scene.render->height) + " " +
                                std::to_string(scene.render->samples_per_pixel) + " spp";
    const double simulation = runs.scene.simulation_seconds;
    table.add_row({cell(row.figure), row.scene, cell(scene.grains.count), cell(runs.scene.released), cell(row.grains),
                   cell(scene.solver.frames), cell(simulation), cell(runs.rigid.simulation_seconds),
                   cell(row.simulation_seconds), cell(row.simulation_seconds / simulation), preview,
                   cell(runs.scene.render_seconds), s.full ? cell(runs.full_render_seconds) : "n/a",
                   cell(row.render_seconds), s.full ? cell(row.render_seconds / runs.full_render_seconds) : "n/a",
                   simulated_effects(scene), rendered_effects(*scene.render)});
    markdown += markdown_row(row, scene, runs, s.full, preview);
    effects += "- " + std::string(row.scene) + ": " + simulated_effects(scene) + "; rendered: " +
               rendered_effects(*scene.render) + "\n";
  }
  write_file_atomically(folder / "table1.csv", table.text());
  markdown += "\nWall times on this machine against the paper's (i9-9900X, Quadro P2200; 180 frames); the target "
              "is a 100x speed-up of the simulation. `simulation` runs the scene as it ships, `rigid grains` the "
              "same scene with grains.body = \"rigid\" (its own folder, SCENE_rigid); `grains` says how many of them "
              "the emitter placed. A render's time is the whole `rice render` (loading, the CDRF table, the "
              "scene's BVH and the samples). Each scene's folder holds its run, its render and run_info.txt.\n\n" +
              effects;
  write_file_atomically(folder / "table1.md", markdown);
  std::printf("%s", markdown.c_str());
}

}  // namespace rice::experiments
