// The `rice` command line (see command_line.hpp). Each subcommand is a thin wrapper over a
// driver in this folder; the ranges below are what a run accepts, checked while parsing.
#include "experiments/cli/command_line.hpp"

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include <charconv>
#include <cstdint>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "experiments/studies/cdrf_study.hpp"
#include "experiments/studies/convergence_study.hpp"
#include "experiments/figures/figure10.hpp"
#include "experiments/figures/figure13.hpp"
#include "experiments/figures/grain_figures.hpp"
#include "experiments/figures/grain_library.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/studies/oscillator_study.hpp"
#include "experiments/scene/pour_scene.hpp"
#include "experiments/studies/pour_substep_study.hpp"
#include "experiments/scene/scene_file.hpp"
#include "experiments/scene/scene_run.hpp"
#include "experiments/studies/grain_substep_study.hpp"
#include "experiments/studies/contact_study.hpp"
#include "experiments/render/render_command.hpp"
#include "experiments/studies/render_study.hpp"
#include "experiments/cli/reproduce.hpp"
#include "experiments/figures/table1.hpp"
#include "experiments/figures/water_absorption_figure.hpp"
#include "experiments/studies/xpbd_stiffness_study.hpp"
#include "grains/cultivar.hpp"
#include "grains/mesh_io.hpp"

namespace rice::experiments {
namespace {

std::string number_text(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

// Which ends of a range are open.
enum class Ends { kClosed, kOpenLow, kOpenHigh };

// A number option: finite and in [low, high] (or with the ends `ends` opens). CLI11
// prefixes the message with the option's name.
CLI::Validator number_in(double low, double high, Ends ends = Ends::kClosed) {
  const std::string range = std::string(ends == Ends::kOpenLow ? "(" : "[") + number_text(low) + ", " +
                            number_text(high) + (ends == Ends::kOpenHigh ? ")" : "]");
  return CLI::Validator(
      [=](std::string& input) -> std::string {
        double value = 0.0;
        try {
          size_t used = 0;
          value = std::stod(input, &used);
          if (used != input.size()) return "'" + input + "' is not a number";
        } catch (const std::exception&) {
          return "'" + input + "' is not a number in " + range;
        }
        const bool above = ends == Ends::kOpenLow ? value > low : value >= low;
        const bool below = ends == Ends::kOpenHigh ? value < high : value <= high;
        if (!std::isfinite(value) || !above || !below) return input + " is outside " + range;
        return {};
      },
      "in " + range);
}

// A seed: an integer in [0, 2^64 - 1] (CLI11 alone wraps -1 around).
CLI::Validator seed_value() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        std::uint64_t value = 0;
        const auto [end, error] = std::from_chars(input.data(), input.data() + input.size(), value);
        if (error != std::errc{} || end != input.data() + input.size())
          return "'" + input + "' is not a seed (an integer in [0, 2^64 - 1])";
        return {};
      },
      "in [0, 2^64 - 1]");
}

// The chosen command's words ("study oscillator", "figure 11"), for messages.
std::string command_name(const CLI::App& app) {
  std::string name;
  for (const CLI::App* command = &app; !command->get_subcommands().empty();) {
    command = command->get_subcommands().front();
    if (!name.empty()) name += ' ';
    name += command->get_name();
  }
  return name;
}

}  // namespace

struct CommandLine::Commands {
  CLI::App app{"rice: a testbed for simulating and rendering freshly cooked rice"};
  int threads = 0;

  CLI::App* stiffness_cmd = nullptr;
  CLI::App* render_study_cmd = nullptr;
  RenderStudySettings render_study;
  std::string render_study_out = "out/render-study";
  CLI::App* cdrf_cmd = nullptr;
  CdrfStudySettings cdrf;
  std::string cdrf_out = "out/cdrf";
  CLI::App* pour_substeps_cmd = nullptr;
  CLI::App* grain_substeps_cmd = nullptr;
  CLI::App* contact_cmd = nullptr;
  ContactStudySettings contact;
  std::string contact_out = "out/contact";
  bool contact_quick = false;
  CLI::Option *contact_depths_opt = nullptr, *contact_edges_opt = nullptr, *contact_steps_opt = nullptr;
  GrainSubstepStudySettings grain_substeps;
  std::string grain_substeps_out = "out/grain-substeps";
  PourSubstepStudySettings pour_substeps;
  std::string pour_substeps_out = "out/pour-substeps", pour_substeps_body = "rigid";
  bool pour_substeps_no_cohesion = false;
  StiffnessStudySettings stiffness;
  std::string stiffness_out = "out/xpbd-stiffness";

  CLI::App* oscillator_cmd = nullptr;
  OscillatorSettings oscillator;
  std::string oscillator_out = "out/oscillator";

  CLI::App* convergence_cmd = nullptr;
  ConvergenceSettings convergence;
  std::string convergence_out = "out/convergence";
  bool convergence_quick = false;
  CLI::Option *duration_opt = nullptr, *young_opt = nullptr, *tau_opt = nullptr;

  CLI::App* grains_cmd = nullptr;
  GrainLibrarySettings library;
  std::string library_out = "out/grains", cultivar_name = "japonica", base_mesh_path;
  bool no_sections = false;
  // Edits of the chosen cultivar, applied after it is looked up by name.
  std::vector<std::pair<CLI::Option*, std::function<double&(grains::Cultivar&)>>> cultivar_edits;

  CLI::App *figure8_cmd = nullptr, *figure9_cmd = nullptr, *figure10_cmd = nullptr, *figure11_cmd = nullptr,
           *figure13_cmd = nullptr;
  Figure10Settings figure10;
  std::string figure10_out = "out/figure10";
  CLI::App* reproduce_cmd = nullptr;
  ReproduceSettings reproduce;
  std::string reproduce_out = "out";
  CLI::App* table1_cmd = nullptr;
  Table1Settings table1;
  std::string table1_out = "out/table1";
  Figure13Settings figure13;
  std::string figure13_out = "out/figure13";
  WaterAbsorptionFigureSettings absorption;
  std::string absorption_out = "out/figure11", figure8_out = "out/figure8", figure9_out = "out/figure9";
  std::uint64_t figure_seed = 1;
  int figure9_count = 20;

  CLI::App* render_cmd = nullptr;
  RenderCommandSettings render;
  std::string render_out = "out/render", render_sampler = "sobol";
  std::vector<std::string> render_meshes;
  std::vector<double> render_eye, render_look_at, render_area;
  double render_fov = 30.0, render_aperture = 0.0, render_focus = 0.0;
  bool render_no_shadows = false, render_no_ao = false, render_no_ground = false, render_side_by_side = false;
  std::string render_sky_image, render_pour;

  CLI::App* run_cmd = nullptr;
  std::string run_scene, run_out = "out/scene";
  std::vector<std::string> run_overrides;

  CLI::App* pour_cmd = nullptr;
  PourSettings pour;
  std::string pour_out = "out/pour", pour_body = "rigid", pour_container = "chawan";
  bool no_cohesion = false, no_damping = false, no_sleep = false;

  Commands() {
    app.require_subcommand(1);
    app.add_option("--threads", threads, "worker threads (0: all cores)")->check(number_in(0, 1024));
    add_studies();
    add_grains();
    add_render();
    add_figures();
    add_pour();
    add_run();
    add_table();
    add_reproduce();
  }

  void add_reproduce() {
    reproduce_cmd = app.add_subcommand("reproduce", "every figure, table and study into out/, with out/index.md");
    reproduce_cmd->add_option("--out", reproduce_out, "output folder")->capture_default_str();
    reproduce_cmd->add_flag("--full", reproduce.full, "the paper's settings where a command has them (long)");
    reproduce_cmd->add_flag("--force", reproduce.force, "rerun the steps that are up to date too");
    reproduce_cmd->add_option("--only", reproduce.only, "run only these steps (their folders' names)");
    reproduce_cmd->add_option("--scenes", reproduce.scenes, "the folder of the shipped scene files")
        ->capture_default_str();
  }

  void add_table() {
    CLI::App* table = app.add_subcommand("table", "regenerate a table of the paper");
    table->require_subcommand(1);
    table1_cmd = table->add_subcommand("1", "shari, chawan, onigiri and bunny: simulation and render times beside the paper's");
    table1_cmd->add_option("--out", table1_out, "output folder")->capture_default_str();
    table1_cmd->add_option("--scenes", table1.scenes, "the folder of the scene files")->capture_default_str();
    table1_cmd->add_flag("--full", table1.full, "also render each last frame at 3840x2160, 800 spp (long)");
    table1_cmd->add_option("--set", table1.overrides, "section.key=value for every scene (repeatable)");
  }

  void add_run() {
    run_cmd = app.add_subcommand("run", "runs a scene file (experiments/scenes/*.toml)");
    run_cmd->add_option("scene", run_scene, "the scene's TOML file")->required();
    run_cmd->add_option("--out", run_out, "output folder")->capture_default_str();
    run_cmd->add_option("--set", run_overrides, "section.key=value: overrides a key of the file (repeatable)");
  }

  void add_pour() {
    pour_cmd = app.add_subcommand("pour", "grains poured into a chawan: contact, friction, cohesion, sleeping");
    pour_cmd->add_option("--out", pour_out, "output folder")->capture_default_str();
    pour_cmd->add_option("--container", pour_container, "chawan, or plate: a heap whose angle of repose is measured")
        ->check(CLI::IsMember({"chawan", "plate"}))
        ->capture_default_str();
    pour_cmd->add_option("--cultivar", pour.cultivar, "japonica, indica, aromatic or glutinous")->capture_default_str();
    pour_cmd->add_option("--count", pour.count, "grains")->check(number_in(1, 1e5))->capture_default_str();
    pour_cmd->add_option("--variants", pour.variants, "distinct generated grains, instanced")
        ->check(number_in(1, 1000))->capture_default_str();
    pour_cmd->add_option("--body", pour_body, "rigid or soft")->check(CLI::IsMember({"rigid", "soft"}))
        ->capture_default_str();
    pour_cmd->add_option("--frames", pour.frames, "frames to simulate")->check(number_in(1, 1e5))->capture_default_str();
    pour_cmd->add_option("--pour-seconds", pour.pour_seconds, "time over which the grains leave the spout [s]")
        ->check(number_in(0, 1e4))->capture_default_str();
    pour_cmd->add_option("--spout-height", pour.spout_height, "spout above the chawan's rim or the plate [m]")->check(number_in(0, 10))
        ->capture_default_str();
    pour_cmd->add_option("--spout-radius", pour.spout_radius, "spout opening [m]; 0: the container's")
        ->check(number_in(0, 1))->capture_default_str();
    pour_cmd->add_option("--fps", pour.fps, "frames per second")->check(number_in(0, 1000, Ends::kOpenLow))
        ->capture_default_str();
    pour_cmd->add_option("--substeps", pour.substeps, "substeps per frame; 0: 80 rigid, 480 soft")
        ->check(number_in(0, 1e4))
        ->capture_default_str();
    pour_cmd->add_option("--iterations", pour.iterations, "Gauss-Seidel sweeps per substep")
        ->check(number_in(1, 1000))->capture_default_str();
    pour_cmd->add_flag("--vbd", pour.vertex_block_descent,
                       "soft grains by vertex block descent; experimental: with cohesive bonds a pile gains energy (README)");
    pour_cmd->add_option("--young", pour.young, "soft grains' Young's modulus [Pa]")->check(number_in(1e3, 1e9))
        ->capture_default_str();
    pour_cmd->add_option("--soak-minutes", pour.soak_minutes, "soaking time [min]")
        ->check(number_in(0, 1e5, Ends::kOpenLow))->capture_default_str();
    pour_cmd->add_option("--soak-temperature", pour.soak_temperature, "soaking water temperature [C]")
        ->check(number_in(0, 100))->capture_default_str();
    pour_cmd->add_option("--stickiness", pour.stickiness,
                         "pull-off force of two grains at the reference soak [grain weights]; default: the cultivar's")
        ->check(number_in(0, 1000));
    pour_cmd->add_option("--static-friction", pour.static_friction, "mu_s, grains and bowl")
        ->check(number_in(0, 10))->capture_default_str();
    pour_cmd->add_option("--dynamic-friction", pour.dynamic_friction, "mu_k <= mu_s")->check(number_in(0, 10))
        ->capture_default_str();
    pour_cmd->add_option("--grid-spacing", pour.grid_spacing, "chawan distance grid [m]")
        ->check(number_in(2e-4, 1e-2))->capture_default_str();
    pour_cmd->add_option("--seed", pour.seed, "random seed")->check(seed_value())->capture_default_str();
    pour_cmd->add_flag("--no-cohesion", no_cohesion, "no water-content bonds between grains");
    pour_cmd->add_flag("--no-damping", no_damping, "soft grains without the soak's Rayleigh damping");
    pour_cmd->add_flag("--no-sleep", no_sleep, "resting grains keep being simulated");
    pour_cmd->add_flag("--render-meshes", pour.render_meshes, "also write each frame's render meshes (PLY, large)");
  }

  PourSubstepStudySettings pour_substeps_settings() const {
    PourSubstepStudySettings settings = pour_substeps;
    settings.pour.body = pour_substeps_body == "soft" ? xpbd::BodyKind::kSoft : xpbd::BodyKind::kRigid;
    settings.pour.cohesion = !pour_substeps_no_cohesion;
    return settings;
  }

  PourSettings pour_settings() const {
    PourSettings settings = pour;
    settings.body = pour_body == "soft" ? xpbd::BodyKind::kSoft : xpbd::BodyKind::kRigid;
    settings.container = pour_container == "plate" ? Container::kPlate : Container::kChawan;
    settings.cohesion = !no_cohesion;
    settings.damping = !no_damping;
    settings.sleeping = !no_sleep;
    return settings;
  }

  void add_studies() {
    CLI::App* study = app.add_subcommand("study", "convergence, stiffness and validation studies");
    study->require_subcommand(1);

    cdrf_cmd = study->add_subcommand("cdrf", "sigma0 of the CDRF fitted to a random-walk reference per water content");
    cdrf_cmd->add_option("--out", cdrf_out, "output folder")->capture_default_str();
    cdrf_cmd->add_option("--soak-minutes", cdrf.soak_minutes, "soak times, one water content each")
        ->check(number_in(0, 1e4, Ends::kOpenLow))->capture_default_str();
    cdrf_cmd->add_option("--temperature", cdrf.temperature_c, "soaking water [°C]")->check(number_in(0, 100))
        ->capture_default_str();
    cdrf_cmd->add_option("--radii-mm", cdrf.radii_mm, "sphere radii [mm]")->check(number_in(0, 100, Ends::kOpenLow))
        ->capture_default_str();
    cdrf_cmd->add_option("--photons", cdrf.photons, "photons per sphere")->check(number_in(1000, 1e9))
        ->capture_default_str();
    cdrf_cmd->add_option("--grain-photons", cdrf.grain_photons, "photons on the grain mesh check (0: none)")
        ->check(number_in(0, 1e9))->capture_default_str();
    cdrf_cmd->add_option("--bins", cdrf.bins, "theta bins over [0, pi]")->check(number_in(4, 1000))
        ->capture_default_str();
    cdrf_cmd->add_option("--seed", cdrf.seed, "random seed")->check(seed_value())->capture_default_str();

    render_study_cmd = study->add_subcommand("render", "image error against time: samplers, and the CDRF against the random walk");
    render_study_cmd->add_option("--out", render_study_out, "output folder")->capture_default_str();
    render_study_cmd->add_option("--width", render_study.width, "pixels")->check(number_in(8, 4096))->capture_default_str();
    render_study_cmd->add_option("--height", render_study.height, "pixels")->check(number_in(8, 4096))->capture_default_str();
    render_study_cmd->add_option("--grains", render_study.grains, "grains on the plate")->check(number_in(1, 10000))
        ->capture_default_str();
    render_study_cmd->add_option("--samples", render_study.samples, "samples per pixel to sweep")
        ->check(number_in(1, 65536))->capture_default_str();
    render_study_cmd->add_option("--reference-spp", render_study.reference_spp, "samples of the reference image")
        ->check(number_in(1, 1 << 20))->capture_default_str();
    render_study_cmd->add_option("--photons", render_study.photons, "random-walk photons per grain and light to sweep")
        ->check(number_in(1000, 1e9))->capture_default_str();
    render_study_cmd->add_option("--bake-spp", render_study.bake_render_spp, "samples of the random-walk renders")
        ->check(number_in(1, 65536))->capture_default_str();
    render_study_cmd->add_option("--seed", render_study.seed, "random seed")->check(seed_value())->capture_default_str();

    pour_substeps_cmd = study->add_subcommand("pour-substeps", "the pour's overlaps against wall time over substeps");
    pour_substeps_cmd->add_option("--out", pour_substeps_out, "output folder")->capture_default_str();
    pour_substeps_cmd->add_option("--substeps", pour_substeps.substeps, "substep counts per frame")
        ->check(number_in(1, 1e4))->capture_default_str();
    pour_substeps_cmd->add_option("--count", pour_substeps.pour.count, "grains")->check(number_in(1, 1e5))
        ->capture_default_str();
    pour_substeps_cmd->add_option("--frames", pour_substeps.pour.frames, "frames")->check(number_in(1, 1e5))
        ->capture_default_str();
    pour_substeps_cmd->add_option("--body", pour_substeps_body, "rigid or soft")
        ->check(CLI::IsMember({"rigid", "soft"}))->capture_default_str();
    pour_substeps_cmd->add_flag("--no-cohesion", pour_substeps_no_cohesion, "no water-content bonds");

    grain_substeps_cmd = study->add_subcommand(
        "grain-substeps", "one soft grain at rest: largest stable substep and its error, XPBD and vertex block descent");
    grain_substeps_cmd->add_option("--out", grain_substeps_out, "output folder")->capture_default_str();
    grain_substeps_cmd->add_option("--substeps", grain_substeps.substeps, "substep counts per 1/60 s frame")
        ->check(number_in(1, 1e4))->capture_default_str();
    grain_substeps_cmd->add_option("--xpbd-iterations", grain_substeps.xpbd_iterations, "XPBD iteration counts")
        ->check(number_in(1, 1000))->capture_default_str();
    grain_substeps_cmd->add_option("--vbd-iterations", grain_substeps.vbd_iterations,
                                   "vertex block descent sweep counts")
        ->check(number_in(1, 1000))->capture_default_str();
    grain_substeps_cmd->add_option("--frames", grain_substeps.frames, "frames of 1/60 s")
        ->check(number_in(1, 1e5))->capture_default_str();
    grain_substeps_cmd->add_option("--young", grain_substeps.young, "Young's modulus [Pa]")
        ->check(number_in(1, 1e12))->capture_default_str();
    grain_substeps_cmd->add_option("--seed", grain_substeps.seed, "grain seed")->check(seed_value())
        ->capture_default_str();

    contact_cmd = study->add_subcommand(
        "contact", "Hertz: a soft half sphere pressed on the ground, reference and vertex block descent");
    contact_cmd->add_option("--out", contact_out, "output folder")->capture_default_str();
    contact_cmd->add_flag("--quick", contact_quick, "two coarse meshes and two depths, for CI (seconds)");
    contact_depths_opt = contact_cmd->add_option("--depths", contact.depths, "depths d/R, increasing")
                             ->check(number_in(1e-4, 0.49))->capture_default_str();
    contact_edges_opt = contact_cmd->add_option("--contact-edges", contact.contact_edges,
                                                "edge lengths of the half sphere's mesh where it touches / R, coarse to fine")
                            ->check(number_in(0.005, 0.25))->capture_default_str();
    contact_cmd->add_option("--young", contact.young, "Young's modulus [Pa]")->check(number_in(1, 1e12))
        ->capture_default_str();
    contact_cmd->add_option("--vbd-iterations", contact.vbd_iterations, "sweeps per step")
        ->check(number_in(1, 1000))->capture_default_str();
    contact_steps_opt = contact_cmd->add_option("--vbd-steps", contact.vbd_steps, "steps of 1/60 s per depth")
        ->check(number_in(1, 100000))->capture_default_str();

    stiffness_cmd = study->add_subcommand("xpbd-stiffness",
                                          "cantilever rest deflection vs iteration count, XPBD against PBD");
    stiffness_cmd->add_option("--out", stiffness_out, "output folder")->capture_default_str();
    stiffness_cmd->add_option("--iterations", stiffness.iterations, "iteration counts")
        ->check(number_in(1, 1000))->capture_default_str();
    stiffness_cmd->add_option("--substeps", stiffness.substeps, "substeps per 1/60 s frame")
        ->check(number_in(1, 10000))->capture_default_str();
    stiffness_cmd->add_option("--young", stiffness.young, "Young's modulus [Pa]")
        ->check(number_in(1, 1e12))->capture_default_str();
    stiffness_cmd->add_option("--pbd-stiffness", stiffness.pbd_stiffness, "PBD stiffness k")
        ->check(number_in(0, 1, Ends::kOpenLow))->capture_default_str();

    oscillator_cmd = study->add_subcommand("oscillator",
                                           "spring-mass period and decay vs analytic, over substeps per frame");
    oscillator_cmd->add_option("--out", oscillator_out, "output folder")->capture_default_str();
    oscillator_cmd->add_option("--damping", oscillator.damping, "beta [N s/m], below critical (2 sqrt(k m) = 20)")
        ->check(number_in(0, 1e6))->capture_default_str();
    oscillator_cmd->add_option("--substeps", oscillator.substeps, "substeps per frame to sweep")
        ->check(number_in(1, 10000))->capture_default_str();

    convergence_cmd = study->add_subcommand(
        "convergence", "XPBD error against the reference solver over substeps, iterations, resolution");
    convergence_cmd->add_option("--out", convergence_out, "output folder")->capture_default_str();
    convergence_cmd->add_flag("--quick", convergence_quick, "reduced grid for CI (under a minute)");
    duration_opt = convergence_cmd->add_option("--duration", convergence.duration, "simulated time [s], >= 1/60")
                       ->check(number_in(1.0 / 60.0, 60))->capture_default_str();
    young_opt = convergence_cmd->add_option("--young", convergence.bar.young, "Young's modulus [Pa]")
                    ->check(number_in(1, 1e12))->capture_default_str();
    tau_opt = convergence_cmd->add_option("--rayleigh-time", convergence.rayleigh_time, "tau of the damped runs [s]")
                  ->check(number_in(0, 10, Ends::kOpenLow))->capture_default_str();
  }

  void add_grains() {
    grains::PorosityParameters& porosity = library.recipe.porosity;
    grains_cmd = app.add_subcommand("grains", "procedural grains: render and simulation meshes, embedding");
    grains_cmd->add_option("--out", library_out, "output folder")->capture_default_str();
    grains_cmd->add_option("--cultivar", cultivar_name, "japonica, indica, aromatic or glutinous")
        ->capture_default_str();
    grains_cmd->add_option("--count", library.count, "number of grains")
        ->check(number_in(1, 1e6))->capture_default_str();
    grains_cmd->add_option("--variants", library.variants, "0: generate every grain; K: K variants, instanced")
        ->check(number_in(0, 1e5))->capture_default_str();
    grains_cmd->add_option("--seed", library.seed, "random seed")->check(seed_value())->capture_default_str();
    grains_cmd->add_option("--base-mesh", base_mesh_path, "closed manifold OBJ/OFF/PLY [m] replacing the base shape")
        ->check(CLI::ExistingFile);
    const auto cultivar_option = [&](const std::string& name, const std::string& help, CLI::Validator range,
                                     std::function<double&(grains::Cultivar&)> field) {
      CLI::Option* option =
          grains_cmd->add_option(name)->type_name("FLOAT")->description(help + " (cultivar default)")->check(range);
      cultivar_edits.emplace_back(option, std::move(field));
    };
    using grains::Cultivar;
    cultivar_option("--length", "mean raw length [m]", number_in(1e-3, 30e-3),
                    [](Cultivar& c) -> double& { return c.length.mean; });
    cultivar_option("--width", "mean raw width [m]", number_in(0.5e-3, 10e-3),
                    [](Cultivar& c) -> double& { return c.width.mean; });
    cultivar_option("--thickness", "mean raw thickness [m]", number_in(0.5e-3, 10e-3),
                    [](Cultivar& c) -> double& { return c.thickness.mean; });
    cultivar_option("--cooked-length-ratio", "cooked/raw length", number_in(0.5, 3),
                    [](Cultivar& c) -> double& { return c.cooked_length_ratio; });
    cultivar_option("--cooked-width-ratio", "cooked/raw width", number_in(0.5, 3),
                    [](Cultivar& c) -> double& { return c.cooked_width_ratio; });
    cultivar_option("--cooked-thickness-ratio", "cooked/raw thickness", number_in(0.5, 3),
                    [](Cultivar& c) -> double& { return c.cooked_thickness_ratio; });
    cultivar_option("--tip-exponent", "tip profile exponent p (2 ellipsoidal, larger blunter)", number_in(1, 8),
                    [](Cultivar& c) -> double& { return c.tip_exponent; });
    cultivar_option("--asymmetry", "dorsal/ventral width asymmetry", number_in(0, 0.5, Ends::kOpenHigh),
                    [](Cultivar& c) -> double& { return c.asymmetry; });
    cultivar_option("--notch-depth", "embryo notch depth / thickness", number_in(0, 0.5, Ends::kOpenHigh),
                    [](Cultivar& c) -> double& { return c.notch_depth; });
    cultivar_option("--notch-size", "embryo notch radius / length", number_in(0, 0.5, Ends::kOpenHigh),
                    [](Cultivar& c) -> double& { return c.notch_size; });
    cultivar_option("--swell-min", "smallest P of eq. 2", number_in(1, 1.5),
                    [](Cultivar& c) -> double& { return c.swell_min; });
    cultivar_option("--swell-max", "largest P of eq. 2", number_in(1, 1.5),
                    [](Cultivar& c) -> double& { return c.swell_max; });
    grains_cmd->add_option("--density", library.recipe.density, "grain material density [kg/m^3]")
        ->check(number_in(100, 1e4))->capture_default_str();
    grains_cmd->add_option("--porosity", porosity.core_porosity, "void fraction of the core")
        ->check(number_in(0, 0.9))->capture_default_str();
    grains_cmd->add_option("--pores", porosity.pore_count, "pore count (-1: from --porosity)")
        ->check(number_in(-1, 1e5))->capture_default_str();
    // Radii and voxels under 20 µm and 5 µm would make level sets of billions of voxels.
    grains_cmd->add_option("--pore-radius-min", porosity.pore_radius_min, "[m]")
        ->check(number_in(20e-6, 1e-3))->capture_default_str();
    grains_cmd->add_option("--pore-radius-max", porosity.pore_radius_max, "[m]")
        ->check(number_in(20e-6, 1e-3))->capture_default_str();
    grains_cmd->add_option("--bumps", porosity.bump_count, "spheres on the surface")
        ->check(number_in(0, 1e5))->capture_default_str();
    grains_cmd->add_option("--bump-radius-min", porosity.bump_radius_min, "[m]")
        ->check(number_in(20e-6, 1e-3))->capture_default_str();
    grains_cmd->add_option("--bump-radius-max", porosity.bump_radius_max, "[m]")
        ->check(number_in(20e-6, 1e-3))->capture_default_str();
    grains_cmd->add_option("--skin", porosity.skin_thickness, "pore-free skin [m]")
        ->check(number_in(0, 1e-3))->capture_default_str();
    grains_cmd->add_option("--voxel-size", porosity.voxel_size, "[m] (0: smallest radius / 1.5; else >= 5e-6)")
        ->check(number_in(0, 1e-3))->capture_default_str();
    grains_cmd->add_option("--adaptivity", library.recipe.mesh_adaptivity, "render mesh adaptivity")
        ->check(number_in(0, 1))->capture_default_str();
    grains_cmd->add_option("--min-vertices", library.recipe.simulation.min_vertices, "simulation mesh size range")
        ->check(number_in(4, 1e4))->capture_default_str();
    grains_cmd->add_option("--max-vertices", library.recipe.simulation.max_vertices, "simulation mesh size range")
        ->check(number_in(4, 1e4))->capture_default_str();
    grains_cmd->add_flag("--no-sections", no_sections, "skip the cross-section PNGs");
  }

  void add_render() {
    render_cmd = app.add_subcommand("render", "grain meshes rendered as cooked rice with the CDRF (PNG and EXR)");
    render_cmd->add_option("--meshes", render_meshes, "mesh files (PLY, OBJ), or folders of them");
    render_cmd->add_option("--pour", render_pour, "or: the output folder of a rigid rice pour");
    render_cmd->add_option("--frame", render.frame, "the pour's frame (0: the last)")->check(number_in(0, 1e6))
        ->capture_default_str();
    render_cmd->add_flag("--every-frame", render.every_frame,
                         "every frame of the pour into frame_NNNN.png, framed as the last");
    render_cmd->add_option("--out", render_out, "output folder")->capture_default_str();
    render_cmd->add_option("--absorption", render.absorption_percent, "water absorption W [%]: sigma0 and albedo")
        ->check(number_in(0, 100))->capture_default_str();
    render_cmd->add_option("--width", render.render.width, "pixels")->check(number_in(1, 16384))->capture_default_str();
    render_cmd->add_option("--height", render.render.height, "pixels")->check(number_in(1, 16384))->capture_default_str();
    render_cmd->add_option("--spp", render.render.samples_per_pixel, "samples per pixel")
        ->check(number_in(1, 1 << 20))->capture_default_str();
    render_cmd->add_option("--sampler", render_sampler, "sobol, stratified or independent")
        ->check(CLI::IsMember({"sobol", "stratified", "independent"}))->capture_default_str();
    render_cmd->add_option("--seed", render.render.seed, "random seed")->check(seed_value())->capture_default_str();
    render_cmd->add_flag("--no-shadows", render_no_shadows, "lights are not blocked");
    render_cmd->add_flag("--no-ao", render_no_ao, "the sky is not blocked (no ambient occlusion)");
    render_cmd->add_flag("--no-ground", render_no_ground, "no grey plane under the meshes");
    render_cmd->add_flag("--side-by-side", render_side_by_side, "lay the meshes out in a row along x");
    render_cmd->add_option("--eye", render_eye, "camera position x y z [m] (default: framed)")->expected(3)
        ->check(number_in(-1e6, 1e6));
    render_cmd->add_option("--look-at", render_look_at, "camera target x y z [m]")->expected(3)
        ->check(number_in(-1e6, 1e6));
    render_cmd->add_option("--fov", render_fov, "vertical field of view [degrees]")
        ->check(number_in(0, 170, Ends::kOpenLow))->capture_default_str();
    render_cmd->add_option("--aperture", render_aperture, "thin-lens aperture radius [m] (0: pinhole)")
        ->check(number_in(0, 10))->capture_default_str();
    render_cmd->add_option("--focus", render_focus, "focus distance [m] (0: the look-at point)")
        ->check(number_in(0, 1e6))->capture_default_str();
    render_cmd->add_option("--sun-elevation", render.sun_elevation_degrees, "[degrees]")->check(number_in(-90, 90))
        ->capture_default_str();
    render_cmd->add_option("--sun-azimuth", render.sun_azimuth_degrees, "[degrees] from +x towards +y")
        ->check(number_in(-360, 360))->capture_default_str();
    render_cmd->add_option("--sun-irradiance", render.sun_irradiance, "at normal incidence (0: no sun)")
        ->check(number_in(0, 1e6))->capture_default_str();
    render_cmd->add_option("--sun-diameter", render.sun_diameter_degrees, "angular diameter [degrees]")
        ->check(number_in(0, 90, Ends::kOpenLow))->capture_default_str();
    render_cmd->add_option("--area-light", render_area,
                           "a parallelogram light: corner x y z, edge u x y z, edge v x y z, radiance; it shines "
                           "towards v x u; repeatable")
        ->expected(10)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)->check(number_in(-1e6, 1e6));
    render_cmd->add_option("--sky", render.sky_radiance, "uniform sky radiance")->check(number_in(0, 1e6))
        ->capture_default_str();
    render_cmd->add_option("--sky-image", render_sky_image, "latitude-longitude OpenEXR sky, z up");
    render_cmd->add_option("--exposure", render.exposure, "stops, for the PNG")->check(number_in(-30, 30))
        ->capture_default_str();
  }

  RenderCommandSettings render_settings() const {
    RenderCommandSettings settings = render;
    settings.meshes.assign(render_meshes.begin(), render_meshes.end());
    settings.render.sampler = render_sampler == "stratified"    ? shading::SamplerKind::kStratified
                              : render_sampler == "independent" ? shading::SamplerKind::kIndependent
                                                                : shading::SamplerKind::kSobol;
    settings.render.shadows = !render_no_shadows;
    settings.render.ambient_occlusion = !render_no_ao;
    settings.ground = !render_no_ground;
    settings.side_by_side = render_side_by_side;
    settings.sky_image = render_sky_image;
    settings.pour = render_pour;
    for (size_t k = 0; k + 10 <= render_area.size(); k += 10) {
      const auto& a = render_area;
      settings.area_lights.push_back({.corner = Eigen::Vector3f(a[k], a[k + 1], a[k + 2]),
                                      .edge_u = Eigen::Vector3f(a[k + 3], a[k + 4], a[k + 5]),
                                      .edge_v = Eigen::Vector3f(a[k + 6], a[k + 7], a[k + 8]),
                                      .radiance = shading::Color::Constant(static_cast<float>(a[k + 9]))});
    }
    if (!render_eye.empty() || !render_look_at.empty()) {
      shading::Camera camera;
      if (render_eye.size() == 3) camera.position = {render_eye[0], render_eye[1], render_eye[2]};
      if (render_look_at.size() == 3) camera.target = {render_look_at[0], render_look_at[1], render_look_at[2]};
      camera.vertical_fov_degrees = render_fov;
      camera.aperture_radius = render_aperture;
      camera.focus_distance = render_focus;
      settings.camera = camera;
    }
    return settings;
  }

  void add_figures() {
    CLI::App* figure = app.add_subcommand("figure", "regenerate a figure of the paper");
    figure->require_subcommand(1);
    figure11_cmd = figure->add_subcommand("11", "water absorption vs soaking time and the damping law of eq. 4");
    figure11_cmd->add_option("--out", absorption_out, "output folder")->capture_default_str();
    figure11_cmd->add_option("--table", absorption.table,
                             "absorption CSV (temperature_c,soak_minutes,absorption_percent); default: shipped table")
        ->check(CLI::ExistingFile);

    figure8_cmd = figure->add_subcommand("8", "japonica grains of different sizes (P from 1 to 1.5)");
    figure8_cmd->add_option("--out", figure8_out, "output folder")->capture_default_str();
    figure8_cmd->add_option("--seed", figure_seed, "random seed")->check(seed_value())->capture_default_str();
    figure9_cmd =
        figure->add_subcommand("9", "indica, japonica, aromatic side by side; dimensions against the literature");
    figure9_cmd->add_option("--out", figure9_out, "output folder")->capture_default_str();
    figure9_cmd->add_option("--seed", figure_seed, "random seed")->check(seed_value())->capture_default_str();
    figure9_cmd->add_option("--count", figure9_count, "grains per cultivar for the dimension statistics")
        ->check(number_in(2, 1000))->capture_default_str();

    figure10_cmd = figure->add_subcommand("10", "a clump of grains dropped on a plate after three soak times");
    figure10_cmd->add_option("--out", figure10_out, "output folder")->capture_default_str();
    figure10_cmd->add_option("--scene", figure10.scene, "the drop scene")->capture_default_str();
    figure10_cmd->add_option("--soak-minutes", figure10.soak_minutes, "soak times at the scene's temperature")
        ->check(number_in(0, 1e5, Ends::kOpenLow))->capture_default_str();
    figure10_cmd->add_option("--set", figure10.overrides, "section.key=value for every run (repeatable)");

    figure13_cmd = figure->add_subcommand("13", "japonica grains soaked at 5 °C for five times, rendered with the CDRF");
    figure13_cmd->add_option("--out", figure13_out, "output folder")->capture_default_str();
    figure13_cmd->add_option("--soak-minutes", figure13.soak_minutes, "soak times, one grain each")
        ->check(number_in(0, 1e4, Ends::kOpenLow))->capture_default_str();
    figure13_cmd->add_option("--temperature", figure13.temperature_c, "soaking water [°C]")
        ->check(number_in(0, 100))->capture_default_str();
    figure13_cmd->add_option("--width", figure13.width, "pixels")->check(number_in(16, 16384))->capture_default_str();
    figure13_cmd->add_option("--height", figure13.height, "pixels")->check(number_in(16, 16384))->capture_default_str();
    figure13_cmd->add_option("--spp", figure13.samples_per_pixel, "samples per pixel")
        ->check(number_in(1, 1 << 20))->capture_default_str();
    figure13_cmd->add_option("--photons", figure13.photons, "reference: photons per grain and light")
        ->check(number_in(1000, 1e9))->capture_default_str();
    figure13_cmd->add_option("--seed", figure13.seed, "random seed (the grain and the samples)")
        ->check(seed_value())->capture_default_str();
  }

  ContactStudySettings contact_settings() const {
    ContactStudySettings settings = contact_quick ? ContactStudySettings::quick() : ContactStudySettings{};
    if (contact_depths_opt->count()) settings.depths = contact.depths;
    if (contact_edges_opt->count()) settings.contact_edges = contact.contact_edges;
    settings.young = contact.young;
    settings.vbd_iterations = contact.vbd_iterations;
    if (contact_steps_opt->count()) settings.vbd_steps = contact.vbd_steps;
    return settings;
  }

  ConvergenceSettings convergence_settings() const {
    ConvergenceSettings settings = convergence_quick ? ConvergenceSettings::quick() : ConvergenceSettings{};
    if (duration_opt->count()) settings.duration = convergence.duration;
    if (young_opt->count()) settings.bar.young = convergence.bar.young;
    if (tau_opt->count()) settings.rayleigh_time = convergence.rayleigh_time;
    return settings;
  }

  // The cultivar named, then the user's edits of it, then the base mesh read.
  GrainLibrarySettings grain_library_settings() const {
    GrainLibrarySettings settings = library;
    settings.recipe.cultivar = grains::cultivar_by_name(cultivar_name);
    for (const auto& [option, field] : cultivar_edits)
      if (option->count()) field(settings.recipe.cultivar) = option->as<double>();
    if (!base_mesh_path.empty()) settings.recipe.base_mesh = grains::read_surface_mesh(base_mesh_path);
    settings.sections = !no_sections;
    return settings;
  }
};

CommandLine::CommandLine() : commands_(std::make_unique<Commands>()) {}
CommandLine::~CommandLine() = default;

CLI::App& CommandLine::app() { return commands_->app; }

int CommandLine::threads() const { return commands_->threads; }

void CommandLine::validate() const {
  const Commands& c = *commands_;
  if (*c.stiffness_cmd) experiments::validate(c.stiffness);
  if (*c.cdrf_cmd) experiments::validate(c.cdrf);
  if (*c.render_study_cmd) experiments::validate(c.render_study);
  if (*c.oscillator_cmd) experiments::validate(c.oscillator);
  if (*c.convergence_cmd) experiments::validate(c.convergence_settings());
  if (*c.contact_cmd) experiments::validate(c.contact_settings());
  if (*c.grains_cmd) experiments::validate(c.grain_library_settings());
  if (*c.figure11_cmd) experiments::validate(c.absorption);
  if (*c.figure10_cmd) experiments::validate(c.figure10);
  if (*c.reproduce_cmd) experiments::validate(c.reproduce);
  if (*c.figure13_cmd) experiments::validate(c.figure13);
  if (*c.pour_cmd) experiments::validate(c.pour_settings());
  if (*c.run_cmd) experiments::validate(read_scene_file(c.run_scene, c.run_overrides).pour);
  if (*c.render_cmd) experiments::validate(c.render_settings());
  if (*c.pour_substeps_cmd) experiments::validate(c.pour_substeps_settings());
  if (*c.grain_substeps_cmd) experiments::validate(c.grain_substeps);
}

void CommandLine::run() const {
  const Commands& c = *commands_;
  if (*c.stiffness_cmd) stiffness_study_command(c.stiffness, c.stiffness_out);
  if (*c.cdrf_cmd) cdrf_study_command(c.cdrf, c.cdrf_out);
  if (*c.render_study_cmd) render_study_command(c.render_study, c.render_study_out);
  if (*c.pour_substeps_cmd) pour_substep_study_command(c.pour_substeps_settings(), c.pour_substeps_out);
  if (*c.grain_substeps_cmd) grain_substep_study_command(c.grain_substeps, c.grain_substeps_out);
  if (*c.oscillator_cmd) oscillator_study_command(c.oscillator, c.oscillator_out);
  if (*c.convergence_cmd) convergence_study_command(c.convergence_settings(), c.convergence_out);
  if (*c.contact_cmd) contact_study_command(c.contact_settings(), c.contact_out);
  if (*c.grains_cmd) grain_library_command(c.grain_library_settings(), c.library_out);
  if (*c.figure8_cmd) grain_sizes_figure_command(c.figure_seed, c.figure8_out);
  if (*c.figure9_cmd) cultivars_figure_command(c.figure_seed, c.figure9_count, c.figure9_out);
  if (*c.figure11_cmd) water_absorption_figure_command(c.absorption, c.absorption_out);
  if (*c.figure10_cmd) figure10_command(c.figure10, c.figure10_out);
  if (*c.table1_cmd) table1_command(c.table1, c.table1_out);
  if (*c.reproduce_cmd)
    reproduce_command(c.reproduce, c.reproduce_out, [](const std::vector<std::string>& arguments) {
      std::vector<std::string> words{"rice"};
      words.insert(words.end(), arguments.begin(), arguments.end());
      std::vector<char*> argv;
      for (std::string& w : words) argv.push_back(w.data());
      return run_command_line(static_cast<int>(argv.size()), argv.data());
    });
  if (*c.figure13_cmd) figure13_command(c.figure13, c.figure13_out);
  if (*c.pour_cmd) pour_command(c.pour_settings(), c.pour_out);
  if (*c.run_cmd) run_scene_command(c.run_scene, c.run_overrides, c.run_out);
  if (*c.render_cmd) render_command(c.render_settings(), c.render_out);
}

int run_command_line(int argc, char** argv) {
  install_interrupt_handlers();
  CommandLine command_line;
  CLI::App& app = command_line.app();
  try {
    app.parse(argc, argv);
    std::unique_ptr<tbb::global_control> limit;
    if (command_line.threads() > 0)
      limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    command_line.threads());
    command_line.validate();
    command_line.run();
    stop_point();  // a Ctrl-C in a phase without stop points (writing, plotting) still stops
  } catch (const CLI::Error& e) {
    return app.exit(e);
  } catch (const Interrupted& e) {
    const std::string doing = activity();  // empty where no progress was reported yet
    std::cerr << "rice: " << e.what() << " during " << (doing.empty() ? command_name(app) : doing)
              << "; the files written so far are complete\n";
    return 128 + e.signal();
  } catch (const std::exception& e) {
    std::cerr << "rice: " << e.what() << '\n';
    return 1;
  }
  return 0;
}

}  // namespace rice::experiments
