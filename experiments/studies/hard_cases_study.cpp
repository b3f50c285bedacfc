// `rice study hard-cases`; see hard_cases_study.hpp.
#include "experiments/studies/hard_cases_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/numeric_csv.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/studies/scene_child_run.hpp"

namespace rice::experiments {
namespace {

constexpr double kLidHalfThickness = 0.01;  // cases/bunny_pressed.toml's lid [m]
constexpr double kLidParked = 0.15;         // its centre's height until it presses [m]

/// What a case's checked run measured (run_info.txt).
struct CaseOutcome {
  double placed = 0.0, frames = 0.0, simulation_s = 0.0, peak_mib = 0.0;
  bool finite = false;
  double inverted = 0.0, overlap = 0.0, thickness = 0.0;
  double pressed_ratio = NAN;  ///< the pile's lowest top under the lid over its settled top
  /// The deepest penetration of an awake contact (between grains, or into the lid, the mould or
  /// the plate) while the lid holds [m] (stats.csv's max_penetration_m).
  double overlap_pressed = NAN;
};

CaseOutcome read_outcome(const std::filesystem::path& run) {
  CaseOutcome c;
  c.placed = info_number(run, "grains_placed");
  c.frames = info_number(run, "frames");
  c.simulation_s = info_number(run, "simulation_wall_s");
  c.peak_mib = info_number(run, "peak_memory_mib");
  c.finite = run_info_value(run / "run_info.txt", "state_finite_at_end") == "yes";
  c.inverted = info_number(run, "inverted_tets_at_end");
  c.overlap = info_number(run, "penetration_between_grains_at_end_m");
  c.thickness = info_number(run, "grain_thickness_m");
  return c;
}

bool passed(const HardCasesStudySettings& s, const CaseOutcome& c) {
  return c.finite && c.inverted == 0.0 && c.overlap < s.overlap_limit * c.thickness;
}

/// The lid's keyframes (TOML): parked until `start`, its bottom down at `bottom` `press` seconds
/// later, held 0.5 s, back up 0.5 s after.
std::string lid_keyframes(double start, double bottom, double press) {
  const auto pose = [](double t, double z) {
    return "{ time_s = " + cell(t) + ", position_m = [0.0, 0.0, " + cell(z) + "] }";
  };
  const double pressed = bottom + kLidHalfThickness, held = start + press;
  return "[" + pose(0.0, kLidParked) + ", " + pose(start, kLidParked) + ", " + pose(held, pressed) + ", " +
         pose(held + 0.5, pressed) + ", " + pose(held + 1.0, kLidParked) + "]";
}

/// `overrides` and, when the study sets one, the grains' seed.
std::vector<std::string> with_seed(const HardCasesStudySettings& s, std::vector<std::string> overrides) {
  if (s.seed > 0) overrides.push_back("grains.seed=" + std::to_string(s.seed));
  return overrides;
}

/// The bunny's overrides: its grain count, fill and seed.
std::vector<std::string> bunny_overrides(const HardCasesStudySettings& s) {
  return with_seed(s, {"grains.count=" + std::to_string(s.bunny_grains), "emitter.seconds=" + cell(s.fill_seconds)});
}

/// The bunny: a run to the press's start for the settled height H (the top centre plus half a
/// grain's thickness), then the whole case with the lid's bottom down to fraction × H.
CaseOutcome bunny_pressed(const HardCasesStudySettings& s, const std::filesystem::path& folder) {
  const std::filesystem::path scene = s.scenes / "cases" / "bunny_pressed.toml";
  const double start = s.fill_seconds + 0.5, fps = 30.0;  // the case file's frame rate
  const auto frames_to = [fps](double t) { return "solver.frames=" + std::to_string(std::lround(t * fps)); };
  SceneChildRun run{scene, bunny_overrides(s), s.threads};
  run.overrides.push_back(frames_to(start));
  run_scene_child(run, folder / "bunny_settled", "hard cases: the bunny's settling");
  const double top = info_number(folder / "bunny_settled", "top_centre_at_end_m");
  const double height = top + 0.5 * info_number(folder / "bunny_settled", "grain_thickness_m");
  if (height + 0.02 > kLidParked - kLidHalfThickness)
    throw std::runtime_error("hard cases: the bunny's pile reaches the parked lid");

  const double held = start + s.press_seconds;  // the lid at its lowest from here, for 0.5 s
  run.overrides = bunny_overrides(s);
  run.overrides.push_back(frames_to(held + 3.0));
  const std::string lid = lid_keyframes(start, s.pressed_fraction * height, s.press_seconds);
  run.overrides.push_back("colliders.2.keyframes=" + lid);
  if (s.lid_force > 0.0) run.overrides.push_back("colliders.2.force_limit_n=" + cell(s.lid_force));
  run_scene_child(run, folder / "bunny_pressed", "hard cases: the bunny's press");
  CaseOutcome c = read_outcome(folder / "bunny_pressed");
  const NumericCsv stats = read_numeric_csv(folder / "bunny_pressed" / "stats.csv");
  double lowest = INFINITY;  // the top centre while the lid holds
  c.overlap_pressed = 0.0;
  for (const std::vector<double>& row : stats.rows) {
    const double t = row[stats.column("time_s")];
    if (t < held || t > held + 0.5) continue;
    lowest = std::min(lowest, row[stats.column("top_m")]);
    c.overlap_pressed = std::max(c.overlap_pressed, row[stats.column("max_penetration_m")]);
  }
  c.pressed_ratio = (lowest + height - top) / height;
  return c;
}

CaseOutcome cooker_drop(const HardCasesStudySettings& s, const std::filesystem::path& folder) {
  const SceneChildRun run{s.scenes / "cases" / "cooker_drop.toml",
                          with_seed(s, {"grains.count=" + std::to_string(s.cooker_grains),
                                        "solver.frames=" + std::to_string(s.cooker_frames)}),
                          s.threads};
  run_scene_child(run, folder / "cooker_drop", "hard cases: the cooker's drop");
  return read_outcome(folder / "cooker_drop");
}

void add_case(CsvTable& table, const HardCasesStudySettings& s, const std::string& name, int grains,
              const CaseOutcome& c) {
  const bool ok = passed(s, c);
  table.add_row({name, cell(grains), cell(c.placed), cell(c.frames), cell(c.simulation_s), cell(c.peak_mib),
                 c.finite ? "yes" : "no", cell(c.inverted), cell(c.overlap), cell(c.thickness),
                 cell(c.overlap / c.thickness), cell(c.pressed_ratio), cell(c.overlap_pressed / c.thickness),
                 ok ? "yes" : "no"});
  const std::string press = std::isnan(c.pressed_ratio) ? ""
                            : ", pressed to " + fixed(100.0 * c.pressed_ratio, 0) + "% with contacts penetrating to " +
                                  fixed(100.0 * c.overlap_pressed / c.thickness, 0) + "% under the lid";
  std::printf("hard-cases: %s, %.0f soft grains, %.0f frames in %.1f s, peak %.0f MiB: %s, %.0f tets inverted, "
              "deepest overlap %.1f%% of the thickness%s: %s\n",
              name.c_str(), c.placed, c.frames, c.simulation_s, c.peak_mib, c.finite ? "finite" : "NOT FINITE",
              c.inverted, 100.0 * c.overlap / c.thickness, press.c_str(), ok ? "passed" : "FAILED");
  std::fflush(stdout);  // a line per case, as it ends
}

}  // namespace

HardCasesStudySettings HardCasesStudySettings::quick() {
  HardCasesStudySettings s;
  s.bunny_grains = 40;
  s.cooker_grains = 40;
  s.fill_seconds = 1.0;
  s.cooker_frames = 45;
  return s;
}

void validate(const HardCasesStudySettings& s) {
  for (const char* name : {"bunny_pressed.toml", "cooker_drop.toml"})
    if (!std::filesystem::is_regular_file(s.scenes / "cases" / name))
      throw std::invalid_argument("--scenes: no file " + (s.scenes / "cases" / name).string());
  if (s.bunny_grains < 1 || s.cooker_grains < 1 || s.cooker_frames < 1 || s.threads < 0)
    throw std::invalid_argument("the grain counts and frames must be positive");
  if (!(s.fill_seconds > 0.0 && s.fill_seconds <= 60.0))
    throw std::invalid_argument("--fill-seconds must be in (0, 60]");
  if (!(s.pressed_fraction > 0.0 && s.pressed_fraction <= 1.0))
    throw std::invalid_argument("--pressed-fraction must be in (0, 1]");
  if (!(s.press_seconds > 0.0 && s.press_seconds <= 60.0))
    throw std::invalid_argument("--press-seconds must be in (0, 60]");
  if (!(s.lid_force >= 0.0 && s.lid_force <= 1e6)) throw std::invalid_argument("--lid-force must be in [0, 1e6] N");
}

bool hard_cases_study_command(const HardCasesStudySettings& s, const std::filesystem::path& folder) {
  validate(s);
  make_output_folder(folder);
  CsvTable table({"case", "grains", "grains_placed", "frames", "simulation_s", "peak_memory_mib", "state_finite",
                  "inverted_tets", "deepest_overlap_m", "grain_thickness_m", "overlap_over_thickness",
                  "pressed_height_ratio", "penetration_under_lid_over_thickness", "passed"});
  const CaseOutcome bunny = bunny_pressed(s, folder);
  add_case(table, s, "bunny_pressed", s.bunny_grains, bunny);
  write_file_atomically(folder / "hard_cases.csv", table.text());
  const CaseOutcome cooker = cooker_drop(s, folder);
  add_case(table, s, "cooker_drop", s.cooker_grains, cooker);
  write_file_atomically(folder / "hard_cases.csv", table.text());
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"command", "study hard-cases"},
                                  {"scenes", s.scenes.string()},
                                  {"fill_seconds", cell(s.fill_seconds)},
                                  {"pressed_fraction", cell(s.pressed_fraction)},
                                  {"press_seconds", cell(s.press_seconds)},
                                  {"lid_force_n", s.lid_force > 0.0 ? cell(s.lid_force) : "the case file's"},
                                  {"seed", s.seed > 0 ? std::to_string(s.seed) : "the case files'"},
                                  {"overlap_limit_of_thickness", cell(s.overlap_limit)},
                                  {"threads", s.threads > 0 ? cell(s.threads) : "the machine's"}}));
  return passed(s, bunny) && passed(s, cooker);
}

}  // namespace rice::experiments
