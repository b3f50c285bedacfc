// `rice render`: its options (what to render, the image, the camera, the lights) mapped onto
// RenderCommandSettings.
#include <CLI/CLI.hpp>

#include "experiments/cli/command_family.hpp"
#include "experiments/cli/option_checks.hpp"
#include "experiments/render/crop_merge.hpp"
#include "experiments/render/join_video.hpp"
#include "experiments/render/point_cache.hpp"
#include "experiments/render/render_command.hpp"

namespace rice::experiments {
namespace {

class RenderCommands : public CommandFamily {
 public:
  explicit RenderCommands(CLI::App& app) {
    CLI::App* c = app.add_subcommand("render", "grain meshes or a scene run's frame rendered as cooked rice, by the CDRF or the reference path tracer (PNG and EXR)");
    add_inputs_and_image(c);
    add_camera(c);
    add_lights(c);
    add(c, [this] { experiments::validate(settings()); }, [this] { render_command(settings(), out_); });
    add_merge_crops(app);
    add_join_video(app);
    add_point_cache(app);
  }

 private:
  void add_inputs_and_image(CLI::App* c) {
    c->add_option("--meshes", meshes_, "mesh files (PLY, OBJ), or folders of them");
    c->add_option("--run", run_, "or: the output folder of a scene run (rice run)");
    c->add_option("--frame", render_.frame, "the run's frame (0: the last)")->check(number_in(0, 1e6))
        ->capture_default_str();
    c->add_flag("--every-frame", render_.every_frame, "every frame of the run into frame_NNNN.png, framed as the last");
    c->add_option("--frames", frame_range_,
                  "with --every-frame: only frames FIRST LAST, with the whole video's camera (rice join-video joins "
                  "the parts)")
        ->expected(2)->check(number_in(1, 1e6));
    c->add_flag("--video", render_.video, "with --every-frame: also render.mp4 (H.264, by ffmpeg) and contact_sheet.png of 12 frames");
    c->add_flag("--deformed-curvature", deformed_curvature_,
                "soft grains drawn as their own mesh shaded with its curvature (default: their rest curvature; with "
                "--soft-instance-pixels 0, every soft grain)");
    c->add_option("--soft-instance-pixels", render_.soft.instance_pixels,
                  "[pixels] a soft grain within this many pixel footprints (at its distance from the camera) of its "
                  "best rigid fit is drawn as an instance of its variant (0: every soft grain its own deformed mesh)")
        ->check(number_in(0, 1e6))->capture_default_str();
    c->add_option("--out", out_, "output folder")->capture_default_str();
    c->add_option("--absorption", render_.absorption_percent, "water absorption W [%]: sigma0 and albedo")
        ->check(number_in(0, 100))->capture_default_str();
    c->add_option("--width", render_.render.width, "pixels")->check(number_in(1, 16384))->capture_default_str();
    c->add_option("--height", render_.render.height, "pixels")->check(number_in(1, 16384))->capture_default_str();
    c->add_option("--spp", render_.render.samples_per_pixel, "samples per pixel")->check(number_in(1, 1 << 20))
        ->capture_default_str();
    c->add_option("--adaptive-error", render_.render.adaptive.relative_error,
                  "adaptive sampling: a pixel stops once its standard error is under this fraction of the image's "
                  "mean radiance, or at --spp (0: off, every pixel takes --spp)")
        ->check(number_in(0, 1))->capture_default_str();
    c->add_option("--min-spp", render_.render.adaptive.min_samples,
                  "adaptive sampling: the samples every pixel takes first, which measure the image's mean")
        ->check(number_in(2, 1 << 20))->capture_default_str();
    c->add_option("--sampler", sampler_, "sobol, stratified or independent")
        ->check(CLI::IsMember({"sobol", "stratified", "independent"}))->capture_default_str();
    c->add_option("--seed", render_.render.seed, "random seed")->check(seed_value())->capture_default_str();
    c->add_option("--integrator", integrator_,
                  "cdrf (the paper's shading), translucent (the CDRF and the light through the grain) or path (the "
                  "reference: light through and between grains)")
        ->check(CLI::IsMember({"cdrf", "translucent", "path"}))->capture_default_str();
    c->add_option("--bounces", render_.bounces, "cdrf, translucent: bounces of light between surfaces (0: direct)")
        ->check(number_in(0, 64))->capture_default_str();
    c->add_option("--max-depth", render_.max_depth, "path: surface events per path")->check(number_in(1, 100000))
        ->capture_default_str();
    c->add_flag("--no-shadows", no_shadows_, "lights are not blocked");
    c->add_flag("--no-ao", no_ao_, "the sky is not blocked (no ambient occlusion)");
    c->add_flag("--no-ground", no_ground_, "no table and backdrop (studio), no grey plane (sun)");
    c->add_flag("--side-by-side", side_by_side_, "lay the meshes out side by side on a grid");
    c->add_option("--exposure", render_.exposure, "stops, for the PNG")->check(number_in(-30, 30))->capture_default_str();
    c->add_option("--crop", crop_,
                  "render only pixels x0 <= x < x1, y0 <= y < y1 of the frame (rice merge-crops joins the parts)")
        ->expected(4)->check(number_in(0, 16384));
    c->add_option("--shading-radius-mm", shading_radius_mm_,
                  "grains' shading normals and curvature smoothed over this radius [mm] (0: the meshes' own)")
        ->check(number_in(0, 10))->capture_default_str();
  }

  void add_camera(CLI::App* c) {
    c->add_option("--eye", eye_, "camera position x y z [m] (default: framed)")->expected(3)->check(number_in(-1e6, 1e6));
    c->add_option("--look-at", look_at_, "camera target x y z [m]")->expected(3)->check(number_in(-1e6, 1e6));
    c->add_option("--fov", fov_, "vertical field of view [degrees]")->check(number_in(0, 170, Ends::kOpenLow))
        ->capture_default_str();
    c->add_option("--aperture", aperture_, "thin-lens aperture radius [m] (0: pinhole)")->check(number_in(0, 10))
        ->capture_default_str();
    c->add_option("--focus", focus_, "focus distance [m] (0: the look-at point)")->check(number_in(0, 1e6))
        ->capture_default_str();
  }

  void add_lights(CLI::App* c) {
    c->add_option("--lighting", lighting_,
                  "studio (a soft key and fill, a table and a backdrop) or sun (the sun, the sky and a grey ground)")
        ->check(CLI::IsMember({"studio", "sun"}))->capture_default_str();
    c->add_option("--key-irradiance", render_.studio.key_irradiance,
                  "studio: the key light's irradiance at the subject")
        ->check(number_in(0, 1e6))->capture_default_str();
    c->add_option("--fill-ratio", render_.studio.fill_ratio, "studio: fill irradiance / key irradiance")
        ->check(number_in(0, 10))->capture_default_str();
    c->add_option("--sun-elevation", render_.sun_elevation_degrees, "[degrees]")->check(number_in(-90, 90))
        ->capture_default_str();
    c->add_option("--sun-azimuth", render_.sun_azimuth_degrees, "[degrees] from +x towards +y")
        ->check(number_in(-360, 360))->capture_default_str();
    c->add_option("--sun-irradiance", render_.sun_irradiance, "at normal incidence (0: no sun)")
        ->check(number_in(0, 1e6))->capture_default_str();
    c->add_option("--sun-diameter", render_.sun_diameter_degrees, "angular diameter [degrees]")
        ->check(number_in(0, 90, Ends::kOpenLow))->capture_default_str();
    c->add_option("--area-light", area_,
                  "a parallelogram light: corner x y z, edge u x y z, edge v x y z, radiance; it shines towards v x u; "
                  "repeatable")
        ->expected(10)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)->check(number_in(-1e6, 1e6));
    c->add_option("--sky", render_.sky_radiance, "uniform sky radiance")->check(number_in(0, 1e6))->capture_default_str();
    c->add_option("--sky-image", sky_image_, "latitude-longitude OpenEXR sky, z up");
  }

  void add_merge_crops(CLI::App& app) {
    CLI::App* c = app.add_subcommand("merge-crops", "the crops of a frame (rice render --crop) joined into the frame");
    c->add_option("parts", merge_parts_, "output folders of rice render --crop")->required();
    c->add_option("--out", merge_out_, "output folder")->capture_default_str();
    c->add_option("--exposure", merge_.exposure, "stops, for the PNG")
        ->check(number_in(-30, 30))
        ->capture_default_str();
    add(c, [this] { experiments::validate(merge_settings()); },
        [this] { merge_crops_command(merge_settings(), merge_out_); });
  }

  void add_join_video(CLI::App& app) {
    CLI::App* c = app.add_subcommand("join-video", "the parts of a video (rice render --every-frame --frames) "
                                                   "joined: every frame, render.mp4 and contact_sheet.png");
    c->add_option("parts", join_parts_, "output folders of rice render --every-frame --frames")->required();
    c->add_option("--out", join_out_, "output folder")->capture_default_str();
    add(c, [this] { experiments::validate(join_settings()); },
        [this] { join_video_command(join_settings(), join_out_); });
  }

  void add_point_cache(CLI::App& app) {
    CLI::App* c = app.add_subcommand("point-cache", "a run's grains for Blender: grains.obj and grains.pc2, its "
                                                    "vertices at every frame (scripts/blender_import.py)");
    c->add_option("--run", cache_.run, "the output folder of a scene run (rice run)")->required();
    c->add_option("--max-vertices", cache_.max_vertices, "per grain, the render mesh simplified (0: whole)")
        ->check(number_in(0, 1e7))
        ->capture_default_str();
    c->add_option("--out", cache_out_, "output folder")->capture_default_str();
    add(c, [this] { experiments::validate(cache_); }, [this] { point_cache_command(cache_, cache_out_); });
  }

  JoinVideoSettings join_settings() const {
    return {std::vector<std::filesystem::path>(join_parts_.begin(), join_parts_.end())};
  }

  MergeCropsSettings merge_settings() const {
    MergeCropsSettings s = merge_;
    s.parts.assign(merge_parts_.begin(), merge_parts_.end());
    return s;
  }

  RenderCommandSettings settings() const {
    RenderCommandSettings s = render_;
    s.meshes.assign(meshes_.begin(), meshes_.end());
    s.run = run_;
    if (frame_range_.size() == 2) {
      s.first_frame = frame_range_[0];
      s.last_frame = frame_range_[1];
    }
    s.render.sampler = sampler_ == "stratified"    ? shading::SamplerKind::kStratified
                       : sampler_ == "independent" ? shading::SamplerKind::kIndependent
                                                   : shading::SamplerKind::kSobol;
    s.integrator = integrator_ == "path"          ? RenderIntegrator::kPath
                   : integrator_ == "translucent" ? RenderIntegrator::kTranslucent
                                                  : RenderIntegrator::kCdrf;
    s.render.shadows = !no_shadows_;
    s.render.ambient_occlusion = !no_ao_;
    s.ground = !no_ground_;
    s.side_by_side = side_by_side_;
    s.soft.curvature = deformed_curvature_ ? SoftCurvature::kDeformed : SoftCurvature::kRest;
    s.sky_image = sky_image_;
    s.lighting = lighting_ == "sun" ? Lighting::kSun : Lighting::kStudio;
    if (crop_.size() == 4) s.render.crop = {crop_[0], crop_[1], crop_[2], crop_[3]};
    s.shading_radius = 1e-3 * shading_radius_mm_;
    for (size_t k = 0; k + 10 <= area_.size(); k += 10) {
      const auto& a = area_;
      s.area_lights.push_back({.corner = Eigen::Vector3f(a[k], a[k + 1], a[k + 2]),
                               .edge_u = Eigen::Vector3f(a[k + 3], a[k + 4], a[k + 5]),
                               .edge_v = Eigen::Vector3f(a[k + 6], a[k + 7], a[k + 8]),
                               .radiance = shading::Color::Constant(static_cast<float>(a[k + 9]))});
    }
    if (!eye_.empty() || !look_at_.empty()) {
      shading::Camera camera;
      if (eye_.size() == 3) camera.position = {eye_[0], eye_[1], eye_[2]};
      if (look_at_.size() == 3) camera.target = {look_at_[0], look_at_[1], look_at_[2]};
      camera.vertical_fov_degrees = fov_;
      camera.aperture_radius = aperture_;
      camera.focus_distance = focus_;
      s.camera = camera;
    }
    return s;
  }

  RenderCommandSettings render_;
  MergeCropsSettings merge_;
  std::vector<std::string> merge_parts_, join_parts_;
  std::string merge_out_ = "out/render", join_out_ = "out/video", cache_out_ = "out/point-cache";
  PointCacheSettings cache_;
  std::string out_ = "out/render", sampler_ = "sobol", sky_image_, run_, integrator_ = "cdrf", lighting_ = "studio";
  std::vector<std::string> meshes_;
  std::vector<double> eye_, look_at_, area_;
  std::vector<int> crop_, frame_range_;
  double fov_ = 30.0, aperture_ = 0.0, focus_ = 0.0, shading_radius_mm_ = 1e3 * kShadingRadius;
  bool no_shadows_ = false, no_ao_ = false, no_ground_ = false, side_by_side_ = false, deformed_curvature_ = false;
};

}  // namespace

std::unique_ptr<CommandFamily> add_render_commands(CLI::App& app) { return std::make_unique<RenderCommands>(app); }

}  // namespace rice::experiments
