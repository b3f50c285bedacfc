// The `rice` command line: one entry point for studies and figures (and, later, scenes).
// Each subcommand is a thin wrapper over a driver in this folder.
#include <CLI/CLI.hpp>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <iostream>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "experiments/convergence_study.hpp"
#include "experiments/grain_figures.hpp"
#include "experiments/grain_library.hpp"
#include "grains/mesh_io.hpp"
#include "experiments/oscillator_study.hpp"
#include "experiments/water_absorption_figure.hpp"
#include "experiments/xpbd_stiffness_study.hpp"

int main(int argc, char** argv) {
  using namespace rice::experiments;
  namespace grains = rice::grains;
  CLI::App app{"rice: a testbed for simulating and rendering freshly cooked rice"};
  app.require_subcommand(1);
  int threads = 0;
  app.add_option("--threads", threads, "worker threads (0: all cores)")->check(CLI::NonNegativeNumber);

  CLI::App* study = app.add_subcommand("study", "convergence, stiffness and validation studies");
  study->require_subcommand(1);

  StiffnessStudySettings stiffness;
  std::string stiffness_out = "out/xpbd-stiffness";
  CLI::App* stiffness_cmd = study->add_subcommand(
      "xpbd-stiffness", "cantilever rest deflection vs iteration count, XPBD against PBD");
  stiffness_cmd->add_option("--out", stiffness_out, "output folder")->capture_default_str();
  stiffness_cmd->add_option("--iterations", stiffness.iterations, "iteration counts")->capture_default_str();
  stiffness_cmd->add_option("--substeps", stiffness.substeps, "substeps per 1/60 s frame")
      ->check(CLI::PositiveNumber)->capture_default_str();
  stiffness_cmd->add_option("--young", stiffness.young, "Young's modulus [Pa]")
      ->check(CLI::PositiveNumber)->capture_default_str();
  stiffness_cmd->add_option("--pbd-stiffness", stiffness.pbd_stiffness, "PBD stiffness k")
      ->check(CLI::Range(0.0, 1.0))->capture_default_str();

  OscillatorSettings oscillator;
  std::string oscillator_out = "out/oscillator";
  CLI::App* oscillator_cmd = study->add_subcommand(
      "oscillator", "spring-mass period and decay vs analytic, over substeps per frame");
  oscillator_cmd->add_option("--out", oscillator_out, "output folder")->capture_default_str();
  oscillator_cmd->add_option("--damping", oscillator.damping, "beta [N s/m]")
      ->check(CLI::NonNegativeNumber)->capture_default_str();
  oscillator_cmd->add_option("--substeps", oscillator.substeps, "substeps per frame to sweep")
      ->capture_default_str();

  ConvergenceSettings convergence;
  std::string convergence_out = "out/convergence";
  bool convergence_quick = false;
  CLI::App* convergence_cmd = study->add_subcommand(
      "convergence", "XPBD error against the reference solver over substeps, iterations, resolution");
  convergence_cmd->add_option("--out", convergence_out, "output folder")->capture_default_str();
  convergence_cmd->add_flag("--quick", convergence_quick, "reduced grid for CI (under a minute)");
  CLI::Option* duration_opt = convergence_cmd->add_option("--duration", convergence.duration, "simulated time [s]")
      ->check(CLI::PositiveNumber)->capture_default_str();
  CLI::Option* young_opt = convergence_cmd->add_option("--young", convergence.bar.young, "Young's modulus [Pa]")
      ->check(CLI::PositiveNumber)->capture_default_str();
  CLI::Option* tau_opt = convergence_cmd->add_option("--rayleigh-time", convergence.rayleigh_time,
                                                     "tau of the damped runs [s]")
      ->check(CLI::PositiveNumber)->capture_default_str();

  GrainLibrarySettings library;
  std::string library_out = "out/grains", cultivar_name = "japonica", base_mesh_path;
  grains::Cultivar& cultivar = library.recipe.cultivar;  // looked up by name after parsing
  grains::PorosityParameters& porosity = library.recipe.porosity;
  bool no_sections = false;
  CLI::App* grains_cmd = app.add_subcommand("grains", "procedural grains: render and simulation meshes, embedding");
  grains_cmd->add_option("--out", library_out, "output folder")->capture_default_str();
  grains_cmd->add_option("--cultivar", cultivar_name, "japonica, indica, aromatic or glutinous")->capture_default_str();
  grains_cmd->add_option("--count", library.count, "number of grains")->capture_default_str();
  grains_cmd->add_option("--variants", library.variants, "0: generate every grain; K: K variants, instanced")
      ->capture_default_str();
  grains_cmd->add_option("--seed", library.seed, "random seed")->capture_default_str();
  grains_cmd->add_option("--base-mesh", base_mesh_path, "closed manifold OBJ/OFF/PLY [m] replacing the base shape")
      ->check(CLI::ExistingFile);
  // Edits of the chosen cultivar, applied after it is looked up by name.
  std::vector<std::pair<CLI::Option*, std::function<double&(grains::Cultivar&)>>> cultivar_edits;
  const auto cultivar_option = [&](const std::string& name, const std::string& help,
                                   std::function<double&(grains::Cultivar&)> field) {
    cultivar_edits.emplace_back(grains_cmd->add_option(name)->type_name("FLOAT")->description(help + " (cultivar default)"), field);
  };
  cultivar_option("--length", "mean raw length [m]", [](grains::Cultivar& c) -> double& { return c.length.mean; });
  cultivar_option("--width", "mean raw width [m]", [](grains::Cultivar& c) -> double& { return c.width.mean; });
  cultivar_option("--thickness", "mean raw thickness [m]",
                  [](grains::Cultivar& c) -> double& { return c.thickness.mean; });
  cultivar_option("--cooked-length-ratio", "cooked/raw length",
                  [](grains::Cultivar& c) -> double& { return c.cooked_length_ratio; });
  cultivar_option("--cooked-width-ratio", "cooked/raw width",
                  [](grains::Cultivar& c) -> double& { return c.cooked_width_ratio; });
  cultivar_option("--cooked-thickness-ratio", "cooked/raw thickness",
                  [](grains::Cultivar& c) -> double& { return c.cooked_thickness_ratio; });
  cultivar_option("--tip-exponent", "tip profile exponent p (2 ellipsoidal, larger blunter)",
                  [](grains::Cultivar& c) -> double& { return c.tip_exponent; });
  cultivar_option("--asymmetry", "dorsal/ventral width asymmetry",
                  [](grains::Cultivar& c) -> double& { return c.asymmetry; });
  cultivar_option("--notch-depth", "embryo notch depth / thickness",
                  [](grains::Cultivar& c) -> double& { return c.notch_depth; });
  cultivar_option("--notch-size", "embryo notch radius / length",
                  [](grains::Cultivar& c) -> double& { return c.notch_size; });
  cultivar_option("--swell-min", "smallest P of eq. 2", [](grains::Cultivar& c) -> double& { return c.swell_min; });
  cultivar_option("--swell-max", "largest P of eq. 2", [](grains::Cultivar& c) -> double& { return c.swell_max; });
  grains_cmd->add_option("--density", library.recipe.density, "grain material density [kg/m^3]")
      ->capture_default_str();
  grains_cmd->add_option("--porosity", porosity.core_porosity, "void fraction of the core")->capture_default_str();
  grains_cmd->add_option("--pores", porosity.pore_count, "pore count (-1: from --porosity)")->capture_default_str();
  grains_cmd->add_option("--pore-radius-min", porosity.pore_radius_min, "[m]")->capture_default_str();
  grains_cmd->add_option("--pore-radius-max", porosity.pore_radius_max, "[m]")->capture_default_str();
  grains_cmd->add_option("--bumps", porosity.bump_count, "spheres on the surface")->capture_default_str();
  grains_cmd->add_option("--bump-radius-min", porosity.bump_radius_min, "[m]")->capture_default_str();
  grains_cmd->add_option("--bump-radius-max", porosity.bump_radius_max, "[m]")->capture_default_str();
  grains_cmd->add_option("--skin", porosity.skin_thickness, "pore-free skin [m]")->capture_default_str();
  grains_cmd->add_option("--voxel-size", porosity.voxel_size, "[m] (0: smallest radius / 1.5)")->capture_default_str();
  grains_cmd->add_option("--adaptivity", library.recipe.mesh_adaptivity, "render mesh adaptivity in [0, 1]")
      ->capture_default_str();
  grains_cmd->add_option("--min-vertices", library.recipe.simulation.min_vertices, "simulation mesh size range")
      ->capture_default_str();
  grains_cmd->add_option("--max-vertices", library.recipe.simulation.max_vertices, "simulation mesh size range")
      ->capture_default_str();
  grains_cmd->add_flag("--no-sections", no_sections, "skip the cross-section PNGs");

  CLI::App* figure = app.add_subcommand("figure", "regenerate a figure of the paper");
  figure->require_subcommand(1);

  WaterAbsorptionFigureSettings absorption;
  std::string absorption_out = "out/figure11";
  CLI::App* figure11_cmd =
      figure->add_subcommand("11", "water absorption vs soaking time and the damping law of eq. 4");
  figure11_cmd->add_option("--out", absorption_out, "output folder")->capture_default_str();
  figure11_cmd->add_option("--table", absorption.table,
                           "absorption CSV (temperature_c,soak_minutes,absorption_percent); default: shipped table")
      ->check(CLI::ExistingFile);

  std::string figure8_out = "out/figure8", figure9_out = "out/figure9";
  std::uint64_t figure_seed = 1;
  int figure9_count = 20;
  CLI::App* figure8_cmd = figure->add_subcommand("8", "japonica grains of different sizes (P from 1 to 1.5)");
  figure8_cmd->add_option("--out", figure8_out, "output folder")->capture_default_str();
  figure8_cmd->add_option("--seed", figure_seed, "random seed")->capture_default_str();
  CLI::App* figure9_cmd =
      figure->add_subcommand("9", "indica, japonica, aromatic side by side; dimensions against the literature");
  figure9_cmd->add_option("--out", figure9_out, "output folder")->capture_default_str();
  figure9_cmd->add_option("--seed", figure_seed, "random seed")->capture_default_str();
  figure9_cmd->add_option("--count", figure9_count, "grains per cultivar for the dimension statistics")
      ->check(CLI::Range(2, 100000))->capture_default_str();

  CLI11_PARSE(app, argc, argv);
  std::unique_ptr<tbb::global_control> limit;
  if (threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, threads);

  try {
    if (*stiffness_cmd) {
      for (const int k : stiffness.iterations)
        if (k < 1) throw CLI::ValidationError("--iterations", "every count must be >= 1");
      stiffness_study_command(stiffness, stiffness_out);
    }
    if (*oscillator_cmd) {
      for (const int n : oscillator.substeps)
        if (n < 1) throw CLI::ValidationError("--substeps", "every count must be >= 1");
      oscillator_study_command(oscillator, oscillator_out);
    }
    if (*convergence_cmd) {
      ConvergenceSettings settings = convergence_quick ? ConvergenceSettings::quick() : ConvergenceSettings{};
      if (duration_opt->count()) settings.duration = convergence.duration;
      if (young_opt->count()) settings.bar.young = convergence.bar.young;
      if (tau_opt->count()) settings.rayleigh_time = convergence.rayleigh_time;
      convergence_study_command(settings, convergence_out);
    }
    if (*grains_cmd) {
      // Cultivar first, then the user's edits of it.
      cultivar = grains::cultivar_by_name(cultivar_name);
      for (const auto& [option, field] : cultivar_edits)
        if (option->count()) field(cultivar) = option->as<double>();
      if (!base_mesh_path.empty()) library.recipe.base_mesh = grains::read_surface_mesh(base_mesh_path);
      library.sections = !no_sections;
      grain_library_command(library, library_out);
    }
    if (*figure8_cmd) grain_sizes_figure_command(figure_seed, figure8_out);
    if (*figure9_cmd) cultivars_figure_command(figure_seed, figure9_count, figure9_out);
    if (*figure11_cmd) water_absorption_figure_command(absorption, absorption_out);
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "rice: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
