// `rice study ...`: one function per study, each adding its options and saying how it is
// checked and run.
#include <CLI/CLI.hpp>

#include "experiments/cli/command_family.hpp"
#include "experiments/cli/option_checks.hpp"
#include "experiments/studies/cdrf_study.hpp"
#include "experiments/studies/contact_study.hpp"
#include "experiments/studies/frame_cost_study.hpp"
#include "experiments/studies/convergence_study.hpp"
#include "experiments/studies/grain_substep_study.hpp"
#include "experiments/studies/hard_cases_study.hpp"
#include "experiments/studies/oscillator_study.hpp"
#include "experiments/studies/pour_substep_study.hpp"
#include "experiments/studies/path_depth_study.hpp"
#include "experiments/studies/render_study.hpp"
#include "experiments/studies/scale_study.hpp"
#include "experiments/studies/scene_convergence_study.hpp"
#include "experiments/studies/sleep_study.hpp"
#include "experiments/studies/soft_curvature_study.hpp"
#include "experiments/studies/soft_instance_study.hpp"
#include "experiments/studies/tet_quality_study.hpp"
#include "experiments/studies/translucency_study.hpp"
#include "experiments/studies/xpbd_stiffness_study.hpp"

namespace rice::experiments {
namespace {

class StudyCommands : public CommandFamily {
 public:
  explicit StudyCommands(CLI::App& app) {
    CLI::App* study = app.add_subcommand("study", "convergence, stiffness and validation studies");
    study->require_subcommand(1);
    add_cdrf(study);
    add_translucency(study);
    add_render(study);
    add_path_depth(study);
    add_soft_curvature(study);
    add_soft_instances(study);
    add_frame_cost(study);
    add_pour_substeps(study);
    add_grain_substeps(study);
    add_tet_quality(study);
    add_contact(study);
    add_stiffness(study);
    add_oscillator(study);
    add_convergence(study);
    add_scene_convergence(study);
    add_scale(study);
    add_sleep(study);
    add_hard_cases(study);
  }

 private:
  void add_cdrf(CLI::App* study) {
    CLI::App* c = study->add_subcommand("cdrf", "sigma0 of the CDRF fitted to a random-walk reference per water content");
    c->add_option("--out", cdrf_out_, "output folder")->capture_default_str();
    c->add_option("--soak-minutes", cdrf_.soak_minutes, "soak times, one water content each")
        ->check(number_in(0, 1e4, Ends::kOpenLow))->capture_default_str();
    c->add_option("--temperature", cdrf_.temperature_c, "soaking water [°C]")->check(number_in(0, 100))
        ->capture_default_str();
    c->add_option("--radii-mm", cdrf_.radii_mm, "sphere radii [mm]")->check(number_in(0, 100, Ends::kOpenLow))
        ->capture_default_str();
    c->add_option("--photons", cdrf_.photons, "photons per sphere")->check(number_in(1000, 1e9))->capture_default_str();
    c->add_option("--grain-photons", cdrf_.grain_photons, "photons on the grain mesh check (0: none)")
        ->check(number_in(0, 1e9))->capture_default_str();
    c->add_option("--bins", cdrf_.bins, "theta bins over [0, pi]")->check(number_in(4, 1000))->capture_default_str();
    c->add_option("--seed", cdrf_.seed, "random seed")->check(seed_value())->capture_default_str();
    add(c, [this] { experiments::validate(cdrf_); }, [this] { cdrf_study_command(cdrf_, cdrf_out_); });
  }

  void add_translucency(CLI::App* study) {
    CLI::App* c = study->add_subcommand(
        "translucency", "light through the grain: tau(d, cos theta) fitted per water content on grain meshes");
    TranslucencyStudySettings& s = translucency_;
    c->add_option("--out", translucency_out_, "output folder")->capture_default_str();
    c->add_flag("--quick", translucency_quick_, "one water content, one cultivar, 2 directions, 20000 photons");
    c->add_option("--soak-minutes", s.soak_minutes, "soak times, one water content each")
        ->check(number_in(0, 1e4, Ends::kOpenLow))->capture_default_str();
    c->add_option("--temperature", s.temperature_c, "soaking water [°C]")->check(number_in(0, 100))
        ->capture_default_str();
    c->add_option("--cultivars", s.cultivars, "cultivars of the grains")->capture_default_str();
    c->add_option("--grains", s.grains_per_cultivar, "grains per cultivar fitted (as many more checked)")
        ->check(number_in(1, 100))->capture_default_str();
    c->add_option("--directions", s.directions, "sun directions per grain")->check(number_in(1, 1000))
        ->capture_default_str();
    c->add_option("--photons", s.photons, "photons per grain and direction")->check(number_in(1000, 1e9))
        ->capture_default_str();
    c->add_option("--smoothing", s.smoothing, "weight of the table's second differences")->check(number_in(0, 1e6))
        ->capture_default_str();
    c->add_option("--shading-radius-mm", s.shading_radius_mm,
                  "shading normals and curvature smoothed over this radius [mm] (0: the mesh's own)")
        ->check(number_in(0, 10))->capture_default_str();
    c->add_option("--curvature-radius-mm", s.curvature_radius_mm,
                  "curvature smoothed over this radius [mm], at most --shading-radius-mm")
        ->check(number_in(0, 10))->capture_default_str();
    c->add_option("--curvature-rings", s.curvature_rings, "rings of the curvature's jet fit")->check(number_in(1, 20))
        ->capture_default_str();
    c->add_option("--seed", s.seed, "random seed")->check(seed_value())->capture_default_str();
    add(c, [this] { experiments::validate(translucency_settings()); },
        [this] { translucency_study_command(translucency_settings(), translucency_out_); });
  }

  RenderStudySettings render_settings() const { return render_quick_ ? RenderStudySettings::quick() : render_; }

  TranslucencyStudySettings translucency_settings() const {
    if (!translucency_quick_) return translucency_;
    TranslucencyStudySettings s = translucency_;
    s.soak_minutes = {60};
    s.cultivars = {"japonica"};
    s.directions = 2;
    s.photons = 20'000;
    return s;
  }

  void add_render(CLI::App* study) {
    CLI::App* c =
        study->add_subcommand("render", "image error against time: samplers, and the CDRF against the random walk");
    RenderStudySettings& s = render_;
    c->add_option("--out", render_out_, "output folder")->capture_default_str();
    c->add_flag("--quick", render_quick_, "the models only, at toy sizes: seconds (the other options ignored)");
    c->add_option("--width", s.width, "pixels")->check(number_in(8, 4096))->capture_default_str();
    c->add_option("--height", s.height, "pixels")->check(number_in(8, 4096))->capture_default_str();
    c->add_option("--grains", s.grains, "grains on the plate")->check(number_in(1, 10000))->capture_default_str();
    c->add_option("--samples", s.samples, "samples per pixel to sweep")->check(number_in(1, 65536))
        ->capture_default_str();
    c->add_option("--reference-spp", s.reference_spp, "samples of the reference image")
        ->check(number_in(1, 1 << 20))->capture_default_str();
    c->add_option("--photons", s.photons, "random-walk photons per grain and light to sweep")
        ->check(number_in(1000, 1e9))->capture_default_str();
    c->add_option("--bake-spp", s.bake_render_spp, "samples of the random-walk renders")
        ->check(number_in(1, 65536))->capture_default_str();
    c->add_option("--heap-grains", s.heap_grains, "grains in the heap")->check(number_in(1, 100000))
        ->capture_default_str();
    c->add_option("--model-samples", s.models.samples, "samples per pixel of each model's renders")
        ->check(number_in(1, 65536))->capture_default_str();
    c->add_option("--path-reference-spp", s.models.reference_spp, "samples of the path-traced reference")
        ->check(number_in(2, 1 << 20))->capture_default_str();
    c->add_option("--bounces", s.models.bounces, "bounces of the translucent model to compare (beside 0)")
        ->check(number_in(1, 64))->capture_default_str();
    c->add_flag("--only-models", [&s](std::int64_t) { s.samplers = false; }, "only the models against the path tracer");
    c->add_flag("--no-models", [&s](std::int64_t) { s.compare_models = false; }, "only the samplers and the bake");
    c->add_option("--seed", s.seed, "random seed")->check(seed_value())->capture_default_str();
    add(c, [this] { experiments::validate(render_settings()); },
        [this] { render_study_command(render_settings(), render_out_); });
  }

  void add_path_depth(CLI::App* study) {
    CLI::App* c = study->add_subcommand(
        "path-depth", "the reference path tracer: the depth it needs, and the CDRF's error against it");
    PathDepthSettings& s = path_depth_;
    c->add_option("--out", path_depth_out_, "output folder")->capture_default_str();
    c->add_flag("--quick", path_depth_quick_, "a 32 x 24 image of 6 grains at 16 spp, depths 1, 2, 4 (seconds; the rest ignored)");
    c->add_option("--width", s.width, "pixels")->check(number_in(8, 4096))->capture_default_str();
    c->add_option("--height", s.height, "pixels")->check(number_in(8, 4096))->capture_default_str();
    c->add_option("--grains", s.grains, "grains on the plate")->check(number_in(1, 10000))->capture_default_str();
    c->add_option("--spp", s.samples_per_pixel, "samples per pixel of each path-traced image")
        ->check(number_in(1, 1 << 20))->capture_default_str();
    c->add_option("--depths", s.depths, "path depths (surface events) to sweep")->check(number_in(1, 100000))
        ->capture_default_str();
    c->add_option("--reference-depth", s.reference_depth, "depth of the reference")->check(number_in(2, 100000))
        ->capture_default_str();
    c->add_option("--cdrf-spp", s.cdrf_spp, "samples per pixel of the CDRF image")->check(number_in(1, 1 << 20))
        ->capture_default_str();
    c->add_option("--sun-radius", s.sun_radius, "the sun's angular radius [rad]")->capture_default_str();
    c->add_option("--seed", s.seed, "random seed")->check(seed_value())->capture_default_str();
    add(c, [this] { experiments::validate(path_depth_settings()); },
        [this] { path_depth_study_command(path_depth_settings(), path_depth_out_); });
  }

  PathDepthSettings path_depth_settings() const { return path_depth_quick_ ? PathDepthSettings::quick() : path_depth_; }

  /// --run, --frame, --width, --height and --spp of the soft-grain studies.
  static void add_run_frame_options(CLI::App* c, RunFrameImage& image) {
    c->add_option("--run", image.run, "a soft scene run's output folder (rice run)")->required();
    c->add_option("--frame", image.frame, "the run's frame (0: the last)")->check(number_in(0, 1e6))->capture_default_str();
    c->add_option("--width", image.width, "pixels")->check(number_in(8, 4096))->capture_default_str();
    c->add_option("--height", image.height, "pixels")->check(number_in(8, 4096))->capture_default_str();
    c->add_option("--spp", image.samples_per_pixel, "samples per pixel")->check(number_in(1, 65536))
        ->capture_default_str();
    c->add_option("--eye", image.eye, "camera position x y z [m] (default: framed on the grains)")->expected(3)
        ->check(number_in(-1e6, 1e6));
    c->add_option("--look-at", image.look_at, "camera target x y z [m]")->expected(3)->check(number_in(-1e6, 1e6));
  }

  void add_soft_curvature(CLI::App* study) {
    CLI::App* c = study->add_subcommand(
        "soft-curvature", "a soft run's frame: rest against recomputed curvature of the deformed grains, error and time");
    SoftCurvatureStudySettings& s = soft_curvature_;
    add_run_frame_options(c, s.image);
    c->add_option("--out", soft_curvature_out_, "output folder")->capture_default_str();
    add(c, [this] { experiments::validate(soft_curvature_); },
        [this] { soft_curvature_study_command(soft_curvature_, soft_curvature_out_); });
  }

  void add_soft_instances(CLI::App* study) {
    CLI::App* c = study->add_subcommand(
        "soft-instances", "a soft run's frame: near-rigid grains drawn as instances, image error and time per tolerance");
    SoftInstanceStudySettings& s = soft_instances_;
    add_run_frame_options(c, s.image);
    c->add_option("--out", soft_instances_out_, "output folder")->capture_default_str();
    c->add_option("--tolerances", s.tolerances,
                  "[pixels] fit tolerances to sweep, in pixel footprints at the grain (0, every grain its own mesh, "
                  "always)")
        ->check(number_in(0, 1e6))->capture_default_str();
    add(c, [this] { experiments::validate(soft_instances_); },
        [this] { soft_instance_study_command(soft_instances_, soft_instances_out_); });
  }

  void add_frame_cost(CLI::App* study) {
    CLI::App* c = study->add_subcommand(
        "frame-cost", "a run's frame at full size: the equal-error sample count, and each model's time for the frame");
    FrameCostStudySettings& s = frame_cost_;
    c->add_option("--run", s.run, "a scene run's output folder (rice run)")->required();
    c->add_option("--frame", s.frame, "the run's frame (0: the last)")->check(number_in(0, 1e6))->capture_default_str();
    c->add_option("--width", s.width, "the frame's pixels")->check(number_in(1, 16384))->capture_default_str();
    c->add_option("--height", s.height, "the frame's pixels")->check(number_in(1, 16384))->capture_default_str();
    c->add_option("--window", window_, "width height of the window rendered at the frame's centre")->expected(2)
        ->check(number_in(1, 16384))->capture_default_str();
    c->add_option("--reference-spp", s.reference_spp, "Sobol samples of the reference")->check(number_in(1, 1 << 20))
        ->capture_default_str();
    c->add_option("--paper-spp", s.paper_spp, "independent samples, the paper's sampling")->check(number_in(1, 1 << 20))
        ->capture_default_str();
    c->add_option("--sobol-spp", s.sobol_spp, "Sobol sample counts, ascending")->check(number_in(1, 1 << 20))
        ->capture_default_str();
    c->add_option("--adaptive-errors", s.adaptive_errors,
                  "adaptive sampling's errors, a fraction of the mean radiance, descending (none: no adaptive renders)")
        ->check(number_in(0, 1))->capture_default_str();
    c->add_option("--adaptive-spp", adaptive_spp_, "MIN MAX samples a pixel of the adaptive renders")->expected(2)
        ->check(number_in(2, 1 << 20))->capture_default_str();
    c->add_option("--cost-spp", s.cost_spp, "samples of each model's timed render")->check(number_in(1, 1 << 20))
        ->capture_default_str();
    c->add_option("--integrator", frame_cost_integrator_, "the model under study: cdrf or translucent")
        ->check(CLI::IsMember({"cdrf", "translucent"}))->capture_default_str();
    c->add_option("--bounces", s.bounces, "its bounces of light between surfaces")->check(number_in(0, 64))
        ->capture_default_str();
    c->add_option("--out", frame_cost_out_, "output folder")->capture_default_str();
    const auto settings = [this] {
      FrameCostStudySettings f = frame_cost_;
      f.window_width = window_[0];
      f.window_height = window_[1];
      f.adaptive_min_spp = adaptive_spp_[0];
      f.adaptive_max_spp = adaptive_spp_[1];
      f.integrator = frame_cost_integrator_ == "cdrf" ? RenderIntegrator::kCdrf : RenderIntegrator::kTranslucent;
      return f;
    };
    add(c, [settings] { experiments::validate(settings()); },
        [this, settings] { frame_cost_study_command(settings(), frame_cost_out_); });
  }

  void add_pour_substeps(CLI::App* study) {
    CLI::App* c = study->add_subcommand("pour-substeps", "the pour's overlaps against wall time over substeps");
    c->add_option("--out", pour_substeps_out_, "output folder")->capture_default_str();
    c->add_option("--substeps", pour_substeps_.substeps, "substep counts per frame")->check(number_in(1, 1e4))
        ->capture_default_str();
    c->add_option("--count", pour_substeps_.scene.grains.count, "grains")->check(number_in(1, 1e5))
        ->capture_default_str();
    c->add_option("--frames", pour_substeps_.scene.solver.frames, "frames")->check(number_in(1, 1e5))
        ->capture_default_str();
    c->add_option("--body", pour_substeps_body_, "rigid or soft")->check(CLI::IsMember({"rigid", "soft"}))
        ->capture_default_str();
    c->add_flag("--no-cohesion", pour_substeps_no_cohesion_, "no water-content bonds");
    add(c, [this] { experiments::validate(pour_substeps_settings()); },
        [this] { pour_substep_study_command(pour_substeps_settings(), pour_substeps_out_); });
  }

  PourSubstepStudySettings pour_substeps_settings() const {
    PourSubstepStudySettings settings = pour_substeps_;
    settings.scene.grains.body = pour_substeps_body_ == "soft" ? xpbd::BodyKind::kSoft : xpbd::BodyKind::kRigid;
    settings.scene.effects.cohesion = !pour_substeps_no_cohesion_;
    return settings;
  }

  void add_grain_substeps(CLI::App* study) {
    CLI::App* c = study->add_subcommand(
        "grain-substeps", "one soft grain at rest: largest stable substep and its error, XPBD and vertex block descent");
    GrainSubstepStudySettings& s = grain_substeps_;
    c->add_option("--out", grain_substeps_out_, "output folder")->capture_default_str();
    c->add_option("--substeps", s.substeps, "substep counts per 1/60 s frame")->check(number_in(1, 1e4))
        ->capture_default_str();
    c->add_option("--xpbd-iterations", s.xpbd_iterations, "XPBD iteration counts")->check(number_in(1, 1000))
        ->capture_default_str();
    c->add_option("--vbd-iterations", s.vbd_iterations, "vertex block descent sweep counts")
        ->check(number_in(1, 1000))->capture_default_str();
    c->add_option("--frames", s.setup.frames, "frames of 1/60 s")->check(number_in(1, 1e5))->capture_default_str();
    c->add_option("--young", s.setup.young, "Young's modulus [Pa]")->check(number_in(1, 1e12))->capture_default_str();
    c->add_option("--drop-height", s.setup.drop_height, "the grain's lowest point above the ground at the start [m]")
        ->check(number_in(0, 10))->capture_default_str();
    c->add_flag("--on-spheres", s.setup.on_spheres,
                "touch the ground with the collision spheres through the contact solver, as in a scene");
    c->add_option("--seed", s.seed, "grain seed")->check(seed_value())->capture_default_str();
    c->add_option("--min-vertices", s.min_vertices, "fewest vertices of the simulation mesh")
        ->check(number_in(4, 10000))->capture_default_str();
    c->add_option("--max-vertices", s.max_vertices, "most vertices of the simulation mesh")
        ->check(number_in(4, 10000))->capture_default_str();
    c->add_option("--cage-stations", s.cage_stations,
                  "> 0: the simulation mesh is a template cage with this many diamonds along the grain (0: Mesh_3)")
        ->check(number_in(0, 100))->capture_default_str();
    add(c, [this] { experiments::validate(grain_substeps_); },
        [this] { grain_substep_study_command(grain_substeps_, grain_substeps_out_); });
  }

  void add_tet_quality(CLI::App* study) {
    CLI::App* c = study->add_subcommand(
        "tet-quality", "grain simulation meshes by several Mesh_3 settings: smallest dihedral angle and XPBD's stable substep");
    TetQualityStudySettings& s = tet_quality_;
    c->add_option("--out", tet_quality_out_, "output folder")->capture_default_str();
    c->add_option("--substeps", s.substeps, "substep counts per 1/60 s frame to search, increasing")
        ->check(number_in(1, 1e4))->capture_default_str();
    c->add_option("--seeds", s.seeds, "grain seeds")->check(seed_value())->capture_default_str();
    c->add_option("--iterations", s.iterations, "XPBD iterations per substep")->check(number_in(1, 1000))
        ->capture_default_str();
    c->add_option("--frames", s.frames, "frames of 1/60 s")->check(number_in(1, 1e5))->capture_default_str();
    c->add_option("--young", s.young, "Young's modulus [Pa]")->check(number_in(1, 1e12))->capture_default_str();
    add(c, [this] { experiments::validate(tet_quality_); },
        [this] { tet_quality_study_command(tet_quality_, tet_quality_out_); });
  }

  void add_contact(CLI::App* study) {
    CLI::App* c = study->add_subcommand(
        "contact", "Hertz: a soft half sphere pressed on the ground, reference and vertex block descent");
    c->add_option("--out", contact_out_, "output folder")->capture_default_str();
    c->add_flag("--quick", contact_quick_, "two coarse meshes and two depths, for CI (seconds)");
    contact_depths_ = c->add_option("--depths", contact_.depths, "depths d/R, increasing")
                          ->check(number_in(1e-4, 0.49))->capture_default_str();
    contact_edges_ = c->add_option("--contact-edges", contact_.contact_edges,
                                   "edge lengths of the half sphere's mesh where it touches / R, coarse to fine")
                         ->check(number_in(0.005, 0.25))->capture_default_str();
    c->add_option("--young", contact_.young, "Young's modulus [Pa]")->check(number_in(1, 1e12))->capture_default_str();
    c->add_option("--vbd-iterations", contact_.vbd_iterations, "sweeps per step")->check(number_in(1, 1000))
        ->capture_default_str();
    contact_steps_ = c->add_option("--vbd-steps", contact_.vbd_steps, "steps of 1/60 s per depth")
                         ->check(number_in(1, 100000))->capture_default_str();
    add(c, [this] { experiments::validate(contact_settings()); }, [this] { contact_study_command(contact_settings(), contact_out_); });
  }

  /// --quick's settings, then the options given.
  ContactStudySettings contact_settings() const {
    ContactStudySettings settings = contact_quick_ ? ContactStudySettings::quick() : ContactStudySettings{};
    if (contact_depths_->count()) settings.depths = contact_.depths;
    if (contact_edges_->count()) settings.contact_edges = contact_.contact_edges;
    settings.young = contact_.young;
    settings.vbd_iterations = contact_.vbd_iterations;
    if (contact_steps_->count()) settings.vbd_steps = contact_.vbd_steps;
    return settings;
  }

  void add_stiffness(CLI::App* study) {
    CLI::App* c =
        study->add_subcommand("xpbd-stiffness", "cantilever rest deflection vs iteration count, XPBD against PBD");
    c->add_option("--out", stiffness_out_, "output folder")->capture_default_str();
    c->add_option("--iterations", stiffness_.iterations, "iteration counts")->check(number_in(1, 1000))
        ->capture_default_str();
    c->add_option("--substeps", stiffness_.substeps, "substeps per 1/60 s frame")->check(number_in(1, 10000))
        ->capture_default_str();
    c->add_option("--young", stiffness_.young, "Young's modulus [Pa]")->check(number_in(1, 1e12))
        ->capture_default_str();
    c->add_option("--pbd-stiffness", stiffness_.pbd_stiffness, "PBD stiffness k")
        ->check(number_in(0, 1, Ends::kOpenLow))->capture_default_str();
    add(c, [this] { experiments::validate(stiffness_); }, [this] { stiffness_study_command(stiffness_, stiffness_out_); });
  }

  void add_oscillator(CLI::App* study) {
    CLI::App* c = study->add_subcommand("oscillator", "spring-mass period and decay vs analytic, over substeps per frame");
    c->add_option("--out", oscillator_out_, "output folder")->capture_default_str();
    c->add_option("--damping", oscillator_.damping, "beta [N s/m], below critical (2 sqrt(k m) = 20)")
        ->check(number_in(0, 1e6))->capture_default_str();
    c->add_option("--substeps", oscillator_.substeps, "substeps per frame to sweep")->check(number_in(1, 10000))
        ->capture_default_str();
    add(c, [this] { experiments::validate(oscillator_); }, [this] { oscillator_study_command(oscillator_, oscillator_out_); });
  }

  void add_convergence(CLI::App* study) {
    CLI::App* c = study->add_subcommand("convergence",
                                        "XPBD error against the reference solver over substeps, iterations, resolution");
    c->add_option("--out", convergence_out_, "output folder")->capture_default_str();
    c->add_flag("--quick", convergence_quick_, "reduced grid for CI (under a minute)");
    duration_ = c->add_option("--duration", convergence_.duration, "simulated time [s], >= 1/60")
                    ->check(number_in(1.0 / 60.0, 60))->capture_default_str();
    young_ = c->add_option("--young", convergence_.bar.young, "Young's modulus [Pa]")->check(number_in(1, 1e12))
                 ->capture_default_str();
    tau_ = c->add_option("--rayleigh-time", convergence_.rayleigh_time, "tau of the damped runs [s]")
               ->check(number_in(0, 10, Ends::kOpenLow))->capture_default_str();
    add(c, [this] { experiments::validate(convergence_settings()); },
        [this] { convergence_study_command(convergence_settings(), convergence_out_); });
  }

  void add_scene_convergence(CLI::App* study) {
    CLI::App* c = study->add_subcommand(
        "scene-convergence", "a soft shari pressed in its mould: XPBD and VBD against a converged run, error and time");
    SceneConvergenceSettings& s = scene_convergence_;
    c->add_option("--out", scene_convergence_out_, "output folder")->capture_default_str();
    c->add_flag("--quick", scene_convergence_quick_, "12 grains, 8 frames and a 2 x 2 grid, for CI (seconds)");
    c->add_option("--scene", s.scene, "the scene file (a mould and its lid)")->capture_default_str();
    c->add_option("--count", s.count, "grains")->check(number_in(1, 1e5))->capture_default_str();
    c->add_option("--frames", s.frames, "frames")->check(number_in(1, 1e5))->capture_default_str();
    add(c, [this] { experiments::validate(scene_convergence_settings()); },
        [this] { scene_convergence_study_command(scene_convergence_settings(), scene_convergence_out_); });
  }

  /// --quick's grid, the scene given.
  SceneConvergenceSettings scene_convergence_settings() const {
    if (!scene_convergence_quick_) return scene_convergence_;
    SceneConvergenceSettings settings = SceneConvergenceSettings::quick();
    settings.scene = scene_convergence_.scene;
    return settings;
  }

  void add_scale(CLI::App* study) {
    CLI::App* c = study->add_subcommand(
        "scale", "clumps of 100 to 34,000 grains, rigid and soft: wall time per grain-frame and memory per grain");
    ScaleStudySettings& s = scale_;
    c->add_option("--out", scale_out_, "output folder")->capture_default_str();
    c->add_flag("--quick", scale_quick_, "20 and 60 grains for 10 frames, for CI (seconds)");
    c->add_option("--scene", s.scene, "the scene file whose grains drop as a clump onto its plate")
        ->capture_default_str();
    scale_counts_ = c->add_option("--counts", s.counts, "grain counts, rising")->check(number_in(1, 1e5));
    c->add_option("--bodies", s.bodies, "rigid, soft or both")->capture_default_str();
    scale_frames_ = c->add_option("--frames", s.frames, "frames of each run")->check(number_in(1, 1e5));
    c->add_option("--run-threads", s.threads, "threads of each run; 0: the machine's")->check(number_in(0, 1024));
    add(c, [this] { experiments::validate(scale_settings()); },
        [this] { scale_study_command(scale_settings(), scale_out_); });
  }

  /// --quick's counts and frames, then the options given.
  ScaleStudySettings scale_settings() const {
    if (!scale_quick_) return scale_;
    ScaleStudySettings settings = ScaleStudySettings::quick();
    settings.scene = scale_.scene;
    settings.bodies = scale_.bodies;
    settings.threads = scale_.threads;
    if (scale_counts_->count()) settings.counts = scale_.counts;
    if (scale_frames_->count()) settings.frames = scale_.frames;
    return settings;
  }

  void add_sleep(CLI::App* study) {
    CLI::App* c = study->add_subcommand(
        "sleep", "the sleep rule's frames at rest and speed: wall time against the settled pile's shape");
    SleepStudySettings& s = sleep_;
    c->add_option("--out", sleep_out_, "output folder")->capture_default_str();
    c->add_flag("--quick", sleep_quick_, "40 grains for 30 frames, two settings, for CI (seconds)");
    c->add_option("--scene", s.scene, "the scene file")->capture_default_str();
    c->add_option("--count", s.count, "grains")->check(number_in(1, 1e5))->capture_default_str();
    c->add_option("--frames", s.frames, "frames of each run")->check(number_in(1, 1e5))->capture_default_str();
    c->add_option("--sleep-frames", s.sleep_frames, "frames at rest before a grain sleeps, at the scene's speed")
        ->check(number_in(1, 1e4))->capture_default_str();
    c->add_option("--sleep-speeds", s.sleep_speeds, "speeds [m/s] under which a grain rests, at the scene's frames")
        ->check(number_in(0, 1, Ends::kOpenLow))->capture_default_str();
    c->add_option("--run-threads", s.threads, "threads of each run; 0: the machine's")->check(number_in(0, 1024));
    add(c, [this] { experiments::validate(sleep_settings()); },
        [this] { sleep_study_command(sleep_settings(), sleep_out_); });
  }

  SleepStudySettings sleep_settings() const {
    if (!sleep_quick_) return sleep_;
    SleepStudySettings settings = SleepStudySettings::quick();
    settings.scene = sleep_.scene;
    settings.threads = sleep_.threads;
    return settings;
  }

  void add_hard_cases(CLI::App* study) {
    CLI::App* c = study->add_subcommand(
        "hard-cases", "soft grains at scale: the bunny pressed to 80% and released, 34,000 dropped into the cooker");
    HardCasesStudySettings& s = hard_cases_;
    c->add_option("--out", hard_cases_out_, "output folder")->capture_default_str();
    c->add_flag("--quick", hard_cases_quick_, "40 grains a case, a 1 s fill, 45 frames of drop, for CI (a minute)");
    c->add_option("--scenes", s.scenes, "the folder holding cases/bunny_pressed.toml and cases/cooker_drop.toml")
        ->capture_default_str();
    c->add_option("--bunny-grains", s.bunny_grains, "grains in the bunny")->check(number_in(1, 1e5))
        ->capture_default_str();
    c->add_option("--cooker-grains", s.cooker_grains, "grains dropped into the cooker")->check(number_in(1, 1e5))
        ->capture_default_str();
    c->add_option("--fill-seconds", s.fill_seconds, "the bunny's fill [s]; the press starts 0.5 s after")
        ->check(number_in(0, 60, Ends::kOpenLow))->capture_default_str();
    c->add_option("--pressed-fraction", s.pressed_fraction, "the lid's bottom at this fraction of the settled height")
        ->check(number_in(0, 1, Ends::kOpenLow))->capture_default_str();
    c->add_option("--press-seconds", s.press_seconds, "the lid's way down, from 15 cm to its lowest [s]")
        ->check(number_in(0, 60, Ends::kOpenLow))->capture_default_str();
    c->add_option("--lid-force", s.lid_force, "the lid's force limit [N], past which it gives way; 0: the case file's")
        ->check(number_in(0, 1e6))->capture_default_str();
    c->add_option("--seed", s.seed, "the grains' seed in both cases (0: the case files' own)")->check(seed_value());
    c->add_option("--run-threads", s.threads, "threads of each run; 0: the machine's")->check(number_in(0, 1024));
    add(c, [this] { experiments::validate(hard_cases_settings()); },
        [this] {
          if (!hard_cases_study_command(hard_cases_settings(), hard_cases_out_))
            throw std::runtime_error("hard-cases: a case failed its checks (" + hard_cases_out_ + "/hard_cases.csv)");
        });
  }

  /// --quick's settings, with the folder and threads given.
  HardCasesStudySettings hard_cases_settings() const {
    if (!hard_cases_quick_) return hard_cases_;
    HardCasesStudySettings settings = HardCasesStudySettings::quick();
    settings.scenes = hard_cases_.scenes;
    settings.threads = hard_cases_.threads;
    settings.pressed_fraction = hard_cases_.pressed_fraction;  // the same defaults as the full study's
    settings.press_seconds = hard_cases_.press_seconds;
    settings.seed = hard_cases_.seed;
    settings.lid_force = hard_cases_.lid_force;
    return settings;
  }

  /// --quick's settings, then the options given.
  ConvergenceSettings convergence_settings() const {
    ConvergenceSettings settings = convergence_quick_ ? ConvergenceSettings::quick() : ConvergenceSettings{};
    if (duration_->count()) settings.duration = convergence_.duration;
    if (young_->count()) settings.bar.young = convergence_.bar.young;
    if (tau_->count()) settings.rayleigh_time = convergence_.rayleigh_time;
    return settings;
  }

  CdrfStudySettings cdrf_;
  std::string cdrf_out_ = "out/cdrf";
  TranslucencyStudySettings translucency_;
  std::string translucency_out_ = "out/translucency";
  bool translucency_quick_ = false;
  bool render_quick_ = false;
  RenderStudySettings render_;
  std::string render_out_ = "out/render-study";
  PathDepthSettings path_depth_;
  std::string path_depth_out_ = "out/path-depth";
  bool path_depth_quick_ = false;
  SceneConvergenceSettings scene_convergence_;
  std::string scene_convergence_out_ = "out/scene-convergence";
  bool scene_convergence_quick_ = false;
  SoftCurvatureStudySettings soft_curvature_;
  std::string soft_curvature_out_ = "out/soft-curvature";
  SoftInstanceStudySettings soft_instances_;
  std::string soft_instances_out_ = "out/soft-instances";
  FrameCostStudySettings frame_cost_;
  std::vector<int> window_{480, 270};
  std::vector<int> adaptive_spp_{16, 1024};
  std::string frame_cost_out_ = "out/frame-cost", frame_cost_integrator_ = "translucent";
  PourSubstepStudySettings pour_substeps_;
  std::string pour_substeps_out_ = "out/pour-substeps", pour_substeps_body_ = "rigid";
  bool pour_substeps_no_cohesion_ = false;
  GrainSubstepStudySettings grain_substeps_;
  std::string grain_substeps_out_ = "out/grain-substeps";
  TetQualityStudySettings tet_quality_;
  std::string tet_quality_out_ = "out/tet-quality";
  ContactStudySettings contact_;
  std::string contact_out_ = "out/contact";
  bool contact_quick_ = false;
  CLI::Option *contact_depths_ = nullptr, *contact_edges_ = nullptr, *contact_steps_ = nullptr;
  StiffnessStudySettings stiffness_;
  std::string stiffness_out_ = "out/xpbd-stiffness";
  OscillatorSettings oscillator_;
  std::string oscillator_out_ = "out/oscillator";
  ConvergenceSettings convergence_;
  std::string convergence_out_ = "out/convergence";
  bool convergence_quick_ = false;
  CLI::Option *duration_ = nullptr, *young_ = nullptr, *tau_ = nullptr;
  ScaleStudySettings scale_;
  std::string scale_out_ = "out/scale";
  bool scale_quick_ = false;
  CLI::Option *scale_counts_ = nullptr, *scale_frames_ = nullptr;
  SleepStudySettings sleep_;
  std::string sleep_out_ = "out/sleep";
  bool sleep_quick_ = false;
  HardCasesStudySettings hard_cases_;
  std::string hard_cases_out_ = "out/hard_cases";
  bool hard_cases_quick_ = false;
};

}  // namespace

std::unique_ptr<CommandFamily> add_study_commands(CLI::App& app) { return std::make_unique<StudyCommands>(app); }

}  // namespace rice::experiments
