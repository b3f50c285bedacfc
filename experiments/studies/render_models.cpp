// The rendering models against the path-traced reference; see render_models.hpp.
#include "experiments/studies/render_models.hpp"

#include <optional>

#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/render_images.hpp"
#include "experiments/render/scene_pieces.hpp"
#include "experiments/render/translucency_tables.hpp"
#include "shading/path_tracer.hpp"
#include "shading/renderer.hpp"

namespace rice::experiments {
namespace {

const shading::Material kGround{.kind = shading::MaterialKind::kDiffuse, .albedo = shading::Color::Constant(0.5f)};

/// A rendering model: its name, its grains' material, and how it renders (bounces < 0: the direct
/// renderer; else the path tracer's fast model with that many bounces).
struct RenderModel {
  std::string name;
  shading::Material grain;
  int bounces = -1;
};

struct ModelRender {
  shading::Image image;
  double seconds = 0.0;
};

ModelRender render_model(const GrainPlate& scene, const RenderModel& model, const RenderModelSettings& s,
                   const shading::CdrfTable& cdrf, int spp) {
  const std::vector<shading::Material> materials = {model.grain, kGround};
  ModelRender out;
  if (model.bounces < 0) {
    shading::RenderStats stats;
    out.image = shading::render(scene.scene, materials, scene.lights, scene.camera, cdrf,
                                {.width = s.width, .height = s.height, .samples_per_pixel = spp, .seed = s.seed}, &stats,
                                {}, stop_requested);
    out.seconds = stats.seconds;
  } else {
    shading::PathTraceSettings settings{.width = s.width, .height = s.height, .samples_per_pixel = spp, .seed = s.seed,
                                        .max_depth = 1 + model.bounces};
    settings.cdrf = &cdrf;
    shading::PathTraceStats stats;
    out.image = shading::path_trace(scene.scene, materials, {}, scene.lights, scene.camera, settings, &stats, {},
                                    stop_requested);
    out.seconds = stats.seconds;
  }
  stop_point();
  return out;
}

/// The reference: two halves of its samples on seeds s and s + 1, averaged.
struct PathReference {
  shading::Image image;
  double seconds = 0.0, noise = 0.0;  // noise: RMS of the average's noise [radiance]
};

PathReference render_reference(const GrainPlate& scene, const RenderModelSettings& s, const std::function<void()>& tick) {
  const std::vector<shading::Material> materials = {rice_material(s.absorption_percent), kGround};
  const std::vector<std::optional<shading::Medium>> media = {grain_medium(s.absorption_percent)};
  PathReference r;
  std::vector<shading::Image> halves;
  for (const std::uint64_t seed : {s.seed, s.seed + 1}) {
    shading::PathTraceStats stats;
    halves.push_back(shading::path_trace(scene.scene, materials, media, scene.lights, scene.camera,
                                         {.width = s.width, .height = s.height,
                                          .samples_per_pixel = std::max(1, s.reference_spp / 2), .seed = seed},
                                         &stats, {}, stop_requested));
    stop_point();
    r.seconds += stats.seconds;
    tick();
  }
  r.image = halves[0];
  for (std::size_t k = 0; k < r.image.pixels.size(); ++k) r.image.pixels[k] = 0.5f * (halves[0].pixels[k] + halves[1].pixels[k]);
  r.noise = 0.5 * shading::rms_difference(halves[0], halves[1]);  // σ of the mean of two = |a − b| / 2
  return r;
}

}  // namespace

int render_model_runs(const RenderModelSettings& settings) {
  return 2 + (2 + static_cast<int>(settings.bounces.size())) * static_cast<int>(settings.samples.size());
}

RenderModelScene compare_render_models(const GrainPlate& scene, const std::string& name,
                                       const RenderModelSettings& settings, const shading::CdrfTable& cdrf,
                                       const std::filesystem::path& folder, CsvTable& table, const std::function<void()>& tick) {
  const PathReference reference = render_reference(scene, settings, tick);
  const double mean = shading::mean_radiance(reference.image);
  write_png(folder / (name + "_reference.png"), tone_map(reference.image, 0.0));
  write_exr(folder / (name + "_reference.exr"), reference.image);
  table.add_row({name, "reference", cell(settings.reference_spp), cell(reference.seconds), cell(reference.noise),
                 cell(reference.noise / mean)});
  const shading::Material translucent = translucent_rice_material(settings.absorption_percent);
  std::vector<RenderModel> models = {{"cdrf", rice_material(settings.absorption_percent), -1},
                                     {"translucent", translucent, -1}};
  for (const int k : settings.bounces) models.push_back({"translucent+" + std::to_string(k), translucent, k});
  RenderModelScene found{reference.seconds, reference.noise / mean, 1e9, 0.0, ""};
  bool met = false;
  for (const RenderModel& model : models) {
    for (const int spp : settings.samples) {
      const ModelRender t = render_model(scene, model, settings, cdrf, spp);
      tick();
      const double rmse = shading::rms_difference(t.image, reference.image), relative = rmse / mean;
      table.add_row({name, model.name, cell(spp), cell(t.seconds), cell(rmse), cell(relative)});
      if (spp == settings.samples.back()) write_png(folder / (name + "_" + model.name + ".png"), tone_map(t.image, 0.0));
      // The fastest render within 5%, or failing any, the most accurate.
      const bool within = relative <= 0.05;
      if ((within && (!met || t.seconds < found.best_seconds)) || (!met && !within && relative < found.best_relative_rms)) {
        found.best_relative_rms = relative;
        found.best_seconds = t.seconds;
        found.best_model = model.name + " at " + std::to_string(spp) + " spp";
        met = met || within;
      }
    }
  }
  return found;
}

void plot_render_models(const std::filesystem::path& folder, const std::string& name, const RenderModelScene& found,
                        const std::vector<int>& bounces) {
  const std::string file = "render_models_" + name;
  std::string bounce_names;
  for (const int k : bounces) bounce_names += " translucent+" + std::to_string(k);
  render_plot(folder, file, csv_plot_header(file, 900, 600) + kLogLogAxes + R"(set xlabel 'wall time [s]'
set ylabel 'RMS against the path-traced reference / its mean radiance'
set title ')" + name + ": best " + found.best_model + " " + fixed(100 * found.best_relative_rms, 1) + "% in " +
                                      fixed(found.best_seconds, 1) + " s; the reference " +
                                      fixed(found.reference_seconds, 0) + " s, noise " +
                                      fixed(100 * found.reference_noise, 1) + R"(%' noenhanced
set key right top
S = ')" + name + R"('
plot for [m in 'cdrf translucent )" + bounce_names + R"('] 'render_models.csv' \
       using ((strcol(1) eq S && strcol(2) eq m) ? $4 : 1/0):6 with linespoints pt 7 lw 2 title m, \
     '' using ((strcol(1) eq S && strcol(2) eq 'reference') ? $4 : 1/0):6 with points pt 5 ps 2 title 'reference (time, noise)'
)");
}

}  // namespace rice::experiments
