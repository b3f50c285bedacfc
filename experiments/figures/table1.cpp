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

/// A column of the table: every scene run again with these overrides after the user's.
struct Column {
  const char* name;    ///< the markdown header
  const char* suffix;  ///< the run's folder is SCENE + suffix
  std::vector<std::string> overrides;
};

/// The scene as it ships (soft grains by XPBD, the paper's method), the measured alternative
/// (vertex block descent at 10 substeps and 5 sweeps a frame, on the Pareto front of `rice
/// study scene-convergence`), and rigid grains.
const std::vector<Column>& columns() {
  static const std::vector<Column> kColumns = {
      {"soft by XPBD (as shipped)", "", {}},
      {"soft by VBD 10x5", "_vbd", {"grains.body=\"soft\"", "solver.method=\"vbd\"", "solver.substeps=10",
                                  "solver.iterations=5"}},
      {"rigid", "_rigid", {"grains.body=\"rigid\""}},
  };
  return kColumns;
}

/// One scene's runs, a column each, and its render at the paper's setting.
struct RowRuns {
  std::vector<SceneResult> columns;
  double full_render_seconds = NAN;
};

RowRuns run_row(const Table1Settings& s, const PaperRow& row, const Scene& scene, const std::filesystem::path& folder) {
  const std::filesystem::path file = s.scenes / (std::string(row.scene) + ".toml");
  RowRuns runs;
  for (const Column& c : columns()) {
    std::vector<std::string> overrides = s.overrides;
    overrides.insert(overrides.end(), c.overrides.begin(), c.overrides.end());
    std::printf("table 1: %s, %s\n", row.scene, c.name);
    runs.columns.push_back(run_scene_command(file, overrides, folder / (std::string(row.scene) + c.suffix)));
  }
  if (s.full) {
    SceneRender paper_setting = *scene.render;
    paper_setting.width = 3840, paper_setting.height = 2160, paper_setting.samples_per_pixel = 800;
    const auto start = std::chrono::steady_clock::now();
    render_command(scene_render_settings(paper_setting, scene, folder / row.scene), folder / row.scene / "render_full");
    runs.full_render_seconds = seconds_since(start);
  }
  return runs;
}

std::string markdown_header() {
  std::string header = "| Fig. | scene | grains | frames |", rule = "|---|---|---|---|";
  for (const Column& c : columns()) header += std::string(" ") + c.name + " |", rule += "---|";
  header += " paper | speed-up | render (preview) | render 3840×2160, 800 spp | paper | speed-up |\n";
  return header + rule + "---|---|---|---|---|---|\n";
}

std::string markdown_row(const PaperRow& row, const Scene& scene, const RowRuns& runs, bool full,
                         const std::string& preview) {
  const SceneResult& shipped = runs.columns.front();
  std::string line = "| " + std::to_string(row.figure) + " | " + row.scene + " | " +
                     std::to_string(scene.grains.count) + " (" + std::to_string(shipped.released) + " in) | " +
                     std::to_string(scene.solver.frames) + " |";
  for (const SceneResult& r : runs.columns) line += " " + fixed(r.simulation_seconds, 1) + " s |";
  return line + " " + fixed(row.simulation_seconds, 0) + " s | " + ratio(row.simulation_seconds, shipped.simulation_seconds) +
         " | " + fixed(shipped.render_seconds, 1) + " s (" + preview + ") | " +
         (full ? fixed(runs.full_render_seconds, 0) + " s" : "not run (--full)") + " | " +
         fixed(row.render_seconds, 0) + " s | " + (full ? ratio(row.render_seconds, runs.full_render_seconds) : "n/a") +
         " |\n";
}

/// How a run ended: grains placed and awake, whether the shape stood, how tight the pile is.
std::vector<std::string> outcome_cells(const SceneResult& r) {
  return {cell(r.released), cell(r.awake), cell(r.simulation_seconds), cell(r.top_before_removal), cell(r.top),
          cell(r.packing_fraction), cell(r.penetration.deepest()), cell(r.kinetic_energy)};
}

std::string outcome_markdown(const char* scene, const Column& c, const SceneResult& r) {
  const double held = r.top / r.top_before_removal;
  return std::string("| ") + scene + " | " + c.name + " | " + fixed(r.simulation_seconds, 1) + " s | " +
         std::to_string(r.released) + " | " + std::to_string(r.awake) + " | " +
         (std::isfinite(held) ? fixed(1e3 * r.top_before_removal, 2) + " → " + fixed(1e3 * r.top, 2) + " mm (" +
                                    fixed(100.0 * held, 1) + "%)"
                              : fixed(1e3 * r.top, 2) + " mm") +
         " | " + fixed(r.packing_fraction, 2) + " | " + fixed(1e3 * r.penetration.deepest(), 3) + " mm |\n";
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
                  "vbd_simulation_s", "rigid_simulation_s", "paper_simulation_s", "simulation_speedup", "preview",
                  "render_preview_s", "render_full_s", "paper_render_s", "render_speedup", "simulated", "rendered"});
  CsvTable outcomes({"scene", "column", "grains_in", "awake", "simulation_s", "top_before_removal_m", "top_m",
                     "packing_fraction", "deepest_overlap_m", "kinetic_energy_j"});
  std::string markdown = markdown_header();
  std::string ended = "\n| scene | run | time | grains in | awake at the end | top centre before the mould goes → at "
                      "the end | packing | deepest overlap |\n|---|---|---|---|---|---|---|---|\n";
  std::string effects;
  for (size_t k = 0; k < scenes.size(); ++k) {
    const PaperRow& row = kPaper[k];
    const Scene& scene = scenes[k];
    std::printf("table 1: %s (%d grains, %d frames)\n", row.scene, scene.grains.count, scene.solver.frames);
    const RowRuns runs = run_row(s, row, scene, folder);
    const SceneResult& shipped = runs.columns.front();
    const std::string preview = std::to_string(scene.render->width) + "x" + std::to_string(scene.render->height) + " " +
                                std::to_string(scene.render->samples_per_pixel) + " spp";
    table.add_row({cell(row.figure), row.scene, cell(scene.grains.count), cell(shipped.released), cell(row.grains),
                   cell(scene.solver.frames), cell(shipped.simulation_seconds),
                   cell(runs.columns[1].simulation_seconds), cell(runs.columns[2].simulation_seconds),
                   cell(row.simulation_seconds), cell(row.simulation_seconds / shipped.simulation_seconds), preview,
                   cell(shipped.render_seconds), s.full ? cell(runs.full_render_seconds) : "n/a",
                   cell(row.render_seconds), s.full ? cell(row.render_seconds / runs.full_render_seconds) : "n/a",
                   simulated_effects(scene), rendered_effects(*scene.render)});
    for (size_t c = 0; c < columns().size(); ++c) {
      std::vector<std::string> cells = {row.scene, columns()[c].name};
      for (std::string& v : outcome_cells(runs.columns[c])) cells.push_back(std::move(v));
      outcomes.add_row(cells);
      ended += outcome_markdown(row.scene, columns()[c], runs.columns[c]);
    }
    markdown += markdown_row(row, scene, runs, s.full, preview);
    effects += "- " + std::string(row.scene) + ": " + simulated_effects(scene) + "; rendered: " +
               rendered_effects(*scene.render) + "\n";
  }
  write_file_atomically(folder / "table1.csv", table.text());
  write_file_atomically(folder / "table1_runs.csv", outcomes.text());
  markdown += "\nWall times on this machine against the paper's (i9-9900X, Quadro P2200; 180 frames); the target "
              "is a 100x speed-up of the simulation, and the speed-up is the scene's as it ships. The vertex block "
              "descent and rigid columns run the same scene with the overrides grains.body = \"soft\", "
              "solver.method = \"vbd\", solver.substeps = 10, solver.iterations = 5 (folder SCENE_vbd) and "
              "grains.body = \"rigid\" (SCENE_rigid); `grains` says how many the emitter placed. A render's time is "
              "the whole `rice render` (loading, the CDRF table, the scene's BVH and the samples). Each run's folder "
              "holds its frames, its render and run_info.txt; table1_runs.csv has how each run ended.\n" +
              ended + "\n" + effects;
  write_file_atomically(folder / "table1.md", markdown);
  std::printf("%s", markdown.c_str());
}

}  // namespace rice::experiments
