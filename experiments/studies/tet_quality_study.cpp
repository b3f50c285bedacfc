// The tet-quality study; see tet_quality_study.hpp.
#include "experiments/studies/tet_quality_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/item_loop.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/studies/grain_substep_study.hpp"
#include "grains/tet_quality.hpp"

namespace rice::experiments {
namespace {

struct MeshSetting {
  const char* name;
  grains::SimulationMeshParameters parameters;
};

/// The settings compared: the default first, then one change at a time, then all together.
std::vector<MeshSetting> mesh_settings() {
  using Optimiser = grains::SimulationMeshParameters::Optimiser;
  grains::SimulationMeshParameters base;
  auto with = [&](auto change) {
    grains::SimulationMeshParameters p = base;
    change(p);
    return p;
  };
  return {
      {"exude10", base},
      {"perturb10_exude10", with([](auto& p) { p.perturb_sliver_degrees = 10.0; })},
      {"odt_perturb_exude", with([](auto& p) {
         p.optimiser = Optimiser::kOdt;
         p.perturb_sliver_degrees = 10.0;
       })},
      {"lloyd_perturb_exude", with([](auto& p) {
         p.optimiser = Optimiser::kLloyd;
         p.perturb_sliver_degrees = 10.0;
       })},
      {"ratio2_odt_perturb15_exude15", with([](auto& p) {
         p.radius_edge_ratio = 2.0;
         p.facet_angle_degrees = 30.0;
         p.optimiser = Optimiser::kOdt;
         p.perturb_sliver_degrees = 15.0;
         p.exude_sliver_degrees = 15.0;
       })},
  };
}

struct Row {
  std::string setting;
  std::uint64_t seed = 0;
  long vertices = 0, tets = 0;
  grains::TetQuality quality;
  double min_edge = 0.0, mean_edge = 0.0;  ///< [m]
  int fewest_stable = 0;  ///< 0: none of the counts
  double wall = 0.0;      ///< at that count [s per simulated second]
};

Row measure(const MeshSetting& setting, std::uint64_t seed, const TetQualityStudySettings& s) {
  grains::GrainRecipe recipe;
  recipe.cultivar = grains::cultivar_by_name("japonica");
  recipe.simulation = setting.parameters;
  const grains::Grain grain = grains::make_grain(recipe, seed);
  Row row{setting.name, seed, static_cast<long>(grain.simulation.V.rows()), static_cast<long>(grain.simulation.T.rows()),
          grains::measure_tet_quality(grain.simulation)};
  const auto& V = grain.simulation.V;
  const auto& T = grain.simulation.T;
  row.min_edge = INFINITY;
  for (Eigen::Index t = 0; t < T.rows(); ++t)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) {
        const double edge = (V.row(T(t, a)) - V.row(T(t, b))).norm();
        row.min_edge = std::min(row.min_edge, edge);
        row.mean_edge += edge / (6.0 * T.rows());
      }
  for (const int n : s.substeps) {
    const GrainRestRun run =
        simulate_grain_at_rest(grain, {.young = s.young, .frames = s.frames}, xpbd::Method::kXpbd, n, s.iterations);
    if (!run.stable()) continue;
    row.fewest_stable = n;
    row.wall = run.wall;
    break;
  }
  return row;
}

void write_plot(const std::filesystem::path& folder) {
  render_plot(folder, "tet_quality", csv_plot_header("tet_quality", 1100, 650) + R"(set logscale y
set xrange [0:30]
set yrange [10:2000]
set xlabel "smallest dihedral angle of the grain's simulation mesh [deg]"
set ylabel 'fewest substeps per 1/60 s frame at which XPBD keeps it at rest'
set title 'XPBD stable substep against tet quality (japonica grains, E = 100 kPa, K = 5)' noenhanced
set key outside right
plot for [m in 'exude10 perturb10_exude10 odt_perturb_exude lloyd_perturb_exude ratio2_odt_perturb15_exude15'] 'tet_quality.csv' using (strcol(1) eq m && $12 > 0 ? $6 : 1/0):12 with points pt 7 ps 1.5 title m noenhanced
)");
}

}  // namespace

void validate(const TetQualityStudySettings& s) {
  if (s.substeps.empty() || !std::is_sorted(s.substeps.begin(), s.substeps.end()))
    throw std::invalid_argument("tet-quality: --substeps must be a non-empty increasing list");
  for (const int n : s.substeps)
    if (n < 1 || n > 10000) throw std::invalid_argument("tet-quality: --substeps counts must be in [1, 10000]");
  if (s.seeds.empty()) throw std::invalid_argument("tet-quality: give at least one --seeds value");
  if (s.iterations < 1 || s.iterations > 1000) throw std::invalid_argument("tet-quality: --iterations must be in [1, 1000]");
  if (s.frames < 1) throw std::invalid_argument("tet-quality: --frames must be >= 1");
  if (!(s.young > 0.0)) throw std::invalid_argument("tet-quality: --young must be > 0");
}

void tet_quality_study_command(const TetQualityStudySettings& s, const std::filesystem::path& folder) {
  validate(s);
  make_output_folder(folder);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<MeshSetting> settings = mesh_settings();
  std::vector<Row> rows(settings.size() * s.seeds.size());
  for_each_item("tet-quality", static_cast<int>(rows.size()), [&](int k) {
    rows[k] = measure(settings[k / s.seeds.size()], s.seeds[k % s.seeds.size()], s);
  });
  CsvTable table({"setting", "seed", "vertices", "tets", "min_volume_m3", "min_dihedral_deg", "max_dihedral_deg",
                  "max_radius_edge_ratio", "min_edge_m", "mean_edge_m", "wave_substeps_mean_edge",
                  "fewest_stable_substeps", "h_s", "wall_s_per_sim_s"});
  // The P-wave speed c = sqrt((λ + 2μ)/ρ) at ν = 0.3 (λ + 2μ = 1.346 E), ρ of a cooked grain:
  // a substep of one mean edge's crossing time, edge / c, per 1/60 s frame.
  const double wave_speed = std::sqrt(1.346 * s.young / 1.1e3);
  std::printf("\n%-30s %4s %5s %5s %9s %9s %9s %8s %8s\n", "mesh", "seed", "verts", "tets", "min dih", "max r/e",
              "N wave", "N stable", "wall s/s");
  for (const Row& r : rows) {
    table.add_row({r.setting, std::to_string(r.seed), cell(r.vertices), cell(r.tets),
                   cell(r.quality.min_volume), cell(r.quality.min_dihedral_degrees),
                   cell(r.quality.max_dihedral_degrees), cell(r.quality.max_radius_edge_ratio), cell(r.min_edge),
                   cell(r.mean_edge), cell(std::ceil(wave_speed / (60.0 * r.mean_edge))), cell(r.fewest_stable),
                   cell(r.fewest_stable ? 1.0 / (60.0 * r.fewest_stable) : 0.0), cell(r.wall)});
    std::printf("%-30s %4llu %5ld %5ld %9.2f %9.2f %9.0f %8s %8.3f\n", r.setting.c_str(), static_cast<unsigned long long>(r.seed), r.vertices, r.tets,
                r.quality.min_dihedral_degrees, r.quality.max_radius_edge_ratio,
                std::ceil(wave_speed / (60.0 * r.mean_edge)),
                r.fewest_stable ? std::to_string(r.fewest_stable).c_str() : "none", r.wall);
  }
  write_file_atomically(folder / "tet_quality.csv", table.text());
  write_plot(folder);
  stop_point();
  write_file_atomically(folder / "run_info.txt", run_info({{"study", "tet-quality"},
                                                           {"frames", cell(s.frames)},
                                                           {"iterations", cell(s.iterations)},
                                                           {"young_pa", cell(s.young)},
                                                           {"wall_s", cell(seconds_since(start))}}));
}

}  // namespace rice::experiments
