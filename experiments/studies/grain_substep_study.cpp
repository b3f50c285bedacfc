// The soft grain's substep study; see grain_substep_study.hpp.
#include "experiments/studies/grain_substep_study.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/item_loop.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "grains/grain_generator.hpp"
#include "xpbd/body.hpp"
#include "xpbd/solver.hpp"

namespace rice::experiments {

namespace {

/// The grain as a soft body with its collision spheres, on a half-space collider at z = 0.
void add_grain_on_spheres(xpbd::Model& model, const grains::Grain& grain, const xpbd::TetMesh& mesh,
                          const xpbd::LameParameters& material) {
  const grains::CollisionSpheres spheres = grains::fit_grain_collision_spheres(grain);
  const Eigen::RowVector3d lift = mesh.V.row(0) - grain.simulation.V.row(0);
  xpbd::add_soft_body(model, mesh, grain.simulation_density, material, 0.0,
                      {spheres.centres.rowwise() + lift, spheres.radii});
  xpbd::Collider ground;
  ground.static_friction = 0.5;
  ground.dynamic_friction = 0.4;
  model.colliders.push_back(ground);
}

/// The reference: the finest stable vertex-block-descent run (most substeps, then most
/// iterations), or where none is stable (on spheres some grains keep rocking under VBD), the
/// finest stable XPBD run; null where no run is stable.
const GrainRestRun* finest_stable_run(const std::vector<GrainRestRun>& runs) {
  const GrainRestRun* finest = nullptr;
  for (const xpbd::Method method : {xpbd::Method::kVbd, xpbd::Method::kXpbd}) {
    for (const GrainRestRun& r : runs)
      if (r.method == method && r.stable() &&
          (!finest || std::tie(r.substeps, r.iterations) > std::tie(finest->substeps, finest->iterations)))
        finest = &r;
    if (finest) return finest;
  }
  return nullptr;
}

/// grain_substeps.png from grain_substeps.csv: error against wall time, one colour and point
/// type per method and K, each point labelled with its substep count N.
void plot_grain_substeps(const std::filesystem::path& folder, const GrainSubstepStudySettings& s,
                         const std::string& title, const GrainRestRun& reference) {
  const auto words = [](const std::vector<int>& counts) {
    std::string list;
    for (const int k : counts) {
      if (!list.empty()) list += ' ';
      list += std::to_string(k);
    }
    return list;
  };
  const std::string reference_name = std::string(xpbd::method_name(reference.method)) + " N = " +
                                     std::to_string(reference.substeps) + ", K = " + std::to_string(reference.iterations);
  render_plot(folder, "grain_substeps", csv_plot_header("grain_substeps", 1200, 700) + kLogLogAxes + R"(set xlabel 'wall time per simulated second [s]'
set ylabel 'RMS distance of the rest state to the reference run ()" + reference_name + R"() / grain length' noenhanced
set title ")" + title + R"(" noenhanced
set key bottom left
X = ')" + words(s.xpbd_iterations) + R"('
V = ')" + words(s.vbd_iterations) + R"('
plot for [i=1:words(X)] 'grain_substeps.csv' using (strcol(1) eq 'xpbd' && $3 == word(X, i)+0 && $5 == 1 ? $9 : 1/0):8:(sprintf('%d', $2)) with labels point pt 7 lc i offset 0.8,0.8 title sprintf('XPBD, K = %s (labels: N)', word(X, i)), \
     for [i=1:words(V)] 'grain_substeps.csv' using (strcol(1) eq 'vbd' && $3 == word(V, i)+0 && $5 == 1 ? $9 : 1/0):8:(sprintf('%d', $2)) with labels point pt (4 + i) lc (words(X) + i) offset 0.8,-0.8 title sprintf('vertex block descent, K = %s', word(V, i))
)");
}

}  // namespace

GrainRestRun simulate_grain_at_rest(const grains::Grain& grain, const GrainRestSetup& setup, xpbd::Method method,
                                    int substeps, int iterations) {
  xpbd::TetMesh mesh{grain.simulation.V, grain.simulation.T};
  mesh.V.col(2).array() += setup.drop_height - mesh.V.col(2).minCoeff();
  const auto material = xpbd::lame_from_young_poisson(setup.young, 0.3);
  xpbd::Model model;
  if (setup.on_spheres) {
    add_grain_on_spheres(model, grain, mesh, material);
  } else {
    model.particles = xpbd::make_particles(mesh, grain.simulation_density);
    xpbd::add_neo_hookean_tets(model, mesh, material);
    model.ground = xpbd::GroundPlane{.static_friction = 0.5, .dynamic_friction = 0.4};
  }
  GrainRestRun run;
  run.method = method;
  run.substeps = substeps;
  run.iterations = iterations;
  xpbd::Solver solver(model, {.time_step = 1.0 / 60.0, .substeps = substeps, .iterations = iterations,
                              .method = method, .execution = xpbd::Execution::kSerial});
  const auto start = std::chrono::steady_clock::now();
  xpbd::Positions last_frame_start;
  try {
    for (int f = 0; f < setup.frames; ++f) {
      if (f + 1 == setup.frames) last_frame_start = model.particles.x;
      solver.step();
    }
  } catch (const xpbd::SimulationError&) {
    run.finite = false;
  }
  run.wall = seconds_since(start) / (setup.frames / 60.0);
  run.x = model.particles.x;
  if (run.finite) {
    // Over the last frame, as sleeping measures speed (xpbd/sleeping.hpp), not the last
    // substep's velocities: vertex block descent leaves a resting grain's particles jittering
    // by a few tenths of a micrometre between substeps, which at h = 2e-4 s reads as 1-2 mm/s.
    run.fastest = (model.particles.x - last_frame_start).rowwise().norm().maxCoeff() * 60.0;
    run.volume_ratio =
        (xpbd::tet_volumes(model.particles.x, mesh.T).array() / xpbd::tet_volumes(mesh.V, mesh.T).array()).minCoeff();
  }
  return run;
}

void validate(const GrainSubstepStudySettings& s) {
  if (s.substeps.empty() || (s.xpbd_iterations.empty() && s.vbd_iterations.empty()))
    throw std::invalid_argument("grain-substeps: give substep counts and iteration counts");
  for (const int n : s.substeps)
    if (n < 1 || n > 10000) throw std::invalid_argument("grain-substeps: --substeps counts must be in [1, 10000]");
  for (const auto* list : {&s.xpbd_iterations, &s.vbd_iterations})
    for (const int k : *list)
      if (k < 1 || k > 1000) throw std::invalid_argument("grain-substeps: iteration counts must be in [1, 1000]");
  if (s.setup.frames < 1) throw std::invalid_argument("grain-substeps: --frames must be >= 1");
  if (!(s.setup.young > 0.0)) throw std::invalid_argument("grain-substeps: --young must be > 0");
  if (!(s.setup.drop_height >= 0.0)) throw std::invalid_argument("grain-substeps: --drop-height must be >= 0");
  if (s.cage_stations < 0 || s.cage_stations > 100)
    throw std::invalid_argument("grain-substeps: --cage-stations must lie in [0, 100]");
  if (s.min_vertices < 4 || s.max_vertices < s.min_vertices)
    throw std::invalid_argument("grain-substeps: need 4 <= --min-vertices <= --max-vertices");
}

void grain_substep_study_command(const GrainSubstepStudySettings& s, const std::filesystem::path& folder) {
  validate(s);
  make_output_folder(folder);
  const auto start = std::chrono::steady_clock::now();
  grains::GrainRecipe recipe;
  recipe.cultivar = grains::cultivar_by_name("japonica");
  recipe.simulation.min_vertices = s.min_vertices;
  recipe.simulation.max_vertices = s.max_vertices;
  if (s.cage_stations > 0) recipe.cage = grains::TemplateCageParameters{.stations = s.cage_stations};
  const grains::Grain grain = grains::make_grain(recipe, s.seed);
  struct Job {
    xpbd::Method method;
    int substeps, iterations;
  };
  std::vector<Job> jobs;
  for (const int n : s.substeps) {
    for (const int k : s.xpbd_iterations) jobs.push_back({xpbd::Method::kXpbd, n, k});
    for (const int k : s.vbd_iterations) jobs.push_back({xpbd::Method::kVbd, n, k});
  }
  std::vector<GrainRestRun> runs(jobs.size());
  for_each_item("grain-substeps", static_cast<int>(jobs.size()), [&](int j) {
    runs[j] = simulate_grain_at_rest(grain, s.setup, jobs[j].method, jobs[j].substeps, jobs[j].iterations);
  });
  const GrainRestRun* reference = finest_stable_run(runs);
  const double length = (grain.simulation.V.colwise().maxCoeff() - grain.simulation.V.colwise().minCoeff()).maxCoeff();
  CsvTable table({"method", "substeps", "iterations", "h_s", "stable", "fastest_m_per_s", "min_volume_ratio",
                  "rms_error_rel", "wall_s_per_sim_s"});
  std::printf("\n%-5s %5s %3s %10s %7s %11s %9s %11s %9s\n", "", "N", "K", "h [s]", "stable", "fastest", "min V/V0",
              "error/len", "wall [s/s]");
  int largest_stable[2] = {0, 0};  // fewest substeps that was stable, per method (xpbd, vbd)
  for (const GrainRestRun& r : runs) {
    const double error = reference && r.finite ? std::sqrt((r.x - reference->x).rowwise().squaredNorm().mean()) / length
                                               : std::numeric_limits<double>::quiet_NaN();
    table.add_row({xpbd::method_name(r.method), cell(r.substeps), cell(r.iterations), cell(1.0 / (60.0 * r.substeps)),
                   cell(r.stable() ? 1 : 0), cell(r.fastest), cell(r.volume_ratio), cell(error), cell(r.wall)});
    std::printf("%-5s %5d %3d %10.2e %7s %11.2e %9.3f %11.2e %9.3f\n", xpbd::method_name(r.method), r.substeps, r.iterations,
                1.0 / (60.0 * r.substeps), r.stable() ? "yes" : "NO", r.fastest, r.volume_ratio, error, r.wall);
    int& fewest = largest_stable[r.method == xpbd::Method::kVbd];
    if (r.stable() && (fewest == 0 || r.substeps < fewest)) fewest = r.substeps;
  }
  write_file_atomically(folder / "grain_substeps.csv", table.text());
  const auto describe = [](int n) { return n == 0 ? std::string("none stable") : "N = " + std::to_string(n); };
  const std::string title = "A soft grain at rest: XPBD stable from " + describe(largest_stable[0]) +
                            ", vertex block descent from " + describe(largest_stable[1]) + " substeps per frame";
  std::printf("\n%s\n", title.c_str());
  const auto plotted = std::count_if(runs.begin(), runs.end(),
                                     [&](const GrainRestRun& r) { return r.stable() && &r != reference; });
  if (plotted > 0)
    plot_grain_substeps(folder, s, title, *reference);
  else
    std::printf("no plot: fewer than two runs came to rest\n");
  stop_point();
  write_file_atomically(folder / "run_info.txt", run_info({{"study", "grain-substeps"},
                                                           {"frames", cell(s.setup.frames)},
                                                           {"young_pa", cell(s.setup.young)},
                                                           {"drop_height_m", cell(s.setup.drop_height)},
                                                           {"contact", s.setup.on_spheres ? "collision spheres" : "particles"},
                                                           {"simulation_mesh", s.cage_stations > 0 ? "template cage" : "Mesh_3"},
                                                           {"seed", cell(static_cast<long>(s.seed))},
                                                           {"vertices", cell(static_cast<long>(grain.simulation.V.rows()))},
                                                           {"tets", cell(static_cast<long>(grain.simulation.T.rows()))},
                                                           {"wall_s", cell(seconds_since(start))}}));
}

}  // namespace rice::experiments
