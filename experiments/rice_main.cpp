// The `rice` command line: one entry point for studies and figures (and, later, scenes).
// Each subcommand is a thin wrapper over a driver in this folder.
#include <CLI/CLI.hpp>
#include <tbb/global_control.h>
#include <tbb/info.h>

#include <iostream>
#include <memory>

#include "experiments/convergence_study.hpp"
#include "experiments/oscillator_study.hpp"
#include "experiments/water_absorption_figure.hpp"
#include "experiments/xpbd_stiffness_study.hpp"

int main(int argc, char** argv) {
  using namespace rice::experiments;
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
    if (*figure11_cmd) water_absorption_figure_command(absorption, absorption_out);
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "rice: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
