// The CDRF study; see cdrf_study.hpp.
#include "experiments/studies/cdrf_study.hpp"

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>

#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/render/scene_pieces.hpp"
#include "shading/renderer.hpp"
#include "grains/cultivar.hpp"
#include "grains/grain_generator.hpp"
#include "grains/water_content.hpp"
#include "shading/cdrf.hpp"
#include "shading/random_walk.hpp"
#include "shading/sigma0_fit.hpp"
#include "shading/subsurface_bake.hpp"
#include "shading/thickness.hpp"

namespace rice::experiments {
namespace {

// Wall time of one CDRF evaluation from the default table, averaged over the samples.
double cdrf_nanoseconds(const std::vector<shading::ExitanceSample>& samples, double sigma0) {
  static const shading::CdrfTable table(513, 513);
  const auto start = std::chrono::steady_clock::now();
  double sink = 0.0;
  constexpr int kRepeats = 2000;
  for (int r = 0; r < kRepeats; ++r)
    for (const auto& s : samples) sink += table(std::cos(s.theta), sigma0 * s.curvature);
  const double seconds = seconds_since(start);
  volatile double keep = sink;  // the loop's result is used, so it is not optimised away
  (void)keep;
  return 1e9 * seconds / (kRepeats * static_cast<double>(samples.size()));
}

}  // namespace

void validate(const CdrfStudySettings& s) {
  if (s.soak_minutes.size() < 2) throw std::invalid_argument("study cdrf: give at least two --soak-minutes");
  for (const double t : s.soak_minutes)
    if (!(t > 0.0 && t <= 10000.0)) throw std::invalid_argument("study cdrf: --soak-minutes must be in (0, 10000]");
  if (s.radii_mm.empty()) throw std::invalid_argument("study cdrf: give at least one --radii-mm");
  for (const double r : s.radii_mm)
    if (!(r > 0.0 && r <= 100.0)) throw std::invalid_argument("study cdrf: --radii-mm must be in (0, 100]");
  if (s.grain_photons != 0 && (s.grain_photons < 1000 || s.grain_photons > 1'000'000'000LL))
    throw std::invalid_argument("study cdrf: --grain-photons must be 0 or in [1000, 1e9]");
  if (s.photons < 1000 || s.photons > 1'000'000'000LL)
    throw std::invalid_argument("study cdrf: --photons must be in [1000, 1e9]");
  if (s.bins < 4 || s.bins > 1000) throw std::invalid_argument("study cdrf: --bins must be in [4, 1000]");
  if (!(s.temperature_c >= 0.0 && s.temperature_c <= 100.0))
    throw std::invalid_argument("study cdrf: --temperature must be in [0, 100] °C");
}

WaterContentFit fit_water_content(double absorption_percent, const CdrfStudySettings& settings,
                                  const std::function<void()>& sphere_done) {
  WaterContentFit r;
  r.absorption_percent = absorption_percent;
  r.optics = grains::WaterContentModel::optics(absorption_percent);
  const shading::Medium medium = grain_medium(absorption_percent);
  for (const double radius_mm : settings.radii_mm) {
    stop_point();
    r.spheres.push_back(shading::sphere_exitance(
        medium, 1e-3 * radius_mm, {.photons = settings.photons, .bins = settings.bins, .seed = settings.seed}));
    r.reference_seconds += r.spheres.back().seconds;
    for (size_t k = 0; k < r.spheres.back().theta.size(); ++k)
      r.samples.push_back({r.spheres.back().theta[k], 1e3 / radius_mm, r.spheres.back().exitance[k]});
    if (sphere_done) sphere_done();
  }
  r.fit = shading::fit_sigma0(r.samples, 1e-6, 1e-1);
  for (const auto& s : r.samples) {
    const double model = r.fit.amplitude * shading::cdrf_integral(std::cos(s.theta), r.fit.sigma0 * s.curvature);
    r.max_error = std::max(r.max_error, std::abs(model - s.exitance));
    r.mean_exitance += s.exitance / r.samples.size();
  }
  return r;
}

GrainCheck check_on_grain(const WaterContentFit& fit, const shading::MeshVertices& V, const shading::MeshTriangles& F,
                          long long photons, std::uint64_t seed) {
  shading::RenderScene scene;
  const Eigen::VectorXd kappa = shading::vertex_mean_curvature(V, F);
  scene.add_instance(scene.add_prototype(V, F, kappa), Eigen::Affine3d::Identity(), 0);
  scene.commit();
  shading::Lights lights;
  lights.suns.push_back({.direction = {0, 0, 1}, .angular_radius = 0.0f, .irradiance = shading::Color::Constant(1.0f)});
  const shading::Medium medium = grain_medium(fit.absorption_percent);
  shading::BakeStats stats;
  const std::vector<float> m = shading::bake_subsurface(scene, {0}, {medium}, lights,
                                                         {.photons_per_light = photons, .seed = seed}, &stats)[0];
  // Bins: 12 in cos θ, 4 in κ (quartiles of the convex vertices; concave ones in the first).
  const shading::MeshVertices N = shading::vertex_normals(V, F);
  std::vector<double> area = scene.vertex_areas(0);
  const std::vector<bool> outer = shading::vertex_sees_out(V, F);
  for (std::size_t v = 0; v < area.size(); ++v)
    if (!outer[v]) area[v] = 0.0;  // the walls of pores inside: nobody sees them, and the bake leaves them dark
  std::vector<double> convex;
  for (Eigen::Index v = 0; v < V.rows(); ++v)
    if (outer[v] && kappa(v) > 0.0) convex.push_back(kappa(v));
  std::sort(convex.begin(), convex.end());
  const auto quantile = [&](double q) { return convex.empty() ? 0.0 : convex[static_cast<size_t>(q * (convex.size() - 1))]; };
  const std::array<double, 3> edges = {quantile(0.25), quantile(0.5), quantile(0.75)};
  constexpr int kCos = 12, kKappa = 4;
  std::vector<double> flux(kCos * kKappa, 0.0), band(kCos * kKappa, 0.0), cos_sum(kCos * kKappa, 0.0),
      kappa_sum(kCos * kKappa, 0.0);
  for (Eigen::Index v = 0; v < V.rows(); ++v) {
    const double c = std::clamp(N(v, 2), -1.0, 1.0);
    const int i = std::min(kCos - 1, static_cast<int>((c + 1.0) / 2.0 * kCos));
    const int j = static_cast<int>(std::upper_bound(edges.begin(), edges.end(), kappa(v)) - edges.begin());
    const int b = j * kCos + i;
    flux[b] += m[v] * area[v];
    band[b] += area[v];
    cos_sum[b] += c * area[v];
    kappa_sum[b] += std::max(kappa(v), 0.0) * area[v];
  }
  GrainCheck check;
  check.bake_seconds = stats.seconds;
  double sum_sq = 0.0;
  for (int b = 0; b < kCos * kKappa; ++b) {
    if (band[b] <= 0.0) continue;
    const double c = cos_sum[b] / band[b], k = kappa_sum[b] / band[b];
    check.samples.push_back({std::acos(c), k, flux[b] / band[b]});
    check.cdrf.push_back(fit.fit.amplitude * shading::cdrf_integral(c, fit.fit.sigma0 * k));
    sum_sq += std::pow(check.cdrf.back() - check.samples.back().exitance, 2);
    check.mean_exitance += check.samples.back().exitance;
  }
  check.mean_exitance /= static_cast<double>(check.samples.size());
  check.rms = std::sqrt(sum_sq / static_cast<double>(check.samples.size()));
  return check;
}

namespace {

/// A fit's profile on each sphere: the random walk and the CDRF, per θ bin.
void add_sphere_profiles(CsvTable& profiles, const WaterContentFit& r, const CdrfStudySettings& settings) {
  for (size_t i = 0; i < r.spheres.size(); ++i) {
    const auto& sphere = r.spheres[i];
    for (size_t k = 0; k < sphere.theta.size(); ++k) {
      const double kappa = 1e3 / settings.radii_mm[i];
      profiles.add_row({cell(r.absorption_percent), cell(settings.radii_mm[i]), cell(sphere.theta[k]),
                        cell(sphere.exitance[k]), cell(sphere.standard_error[k]),
                        cell(r.fit.amplitude * shading::cdrf_integral(std::cos(sphere.theta[k]), r.fit.sigma0 * kappa))});
    }
  }
}

void add_grain_profiles(CsvTable& grain_profiles, const WaterContentFit& r, const GrainCheck& g) {
  for (size_t k = 0; k < g.samples.size(); ++k)
    grain_profiles.add_row({cell(r.absorption_percent), cell(g.samples[k].theta), cell(1e-3 * g.samples[k].curvature),
                            cell(g.samples[k].exitance), cell(g.cdrf[k])});
}

/// The laws across the water contents: ln σ0 = s0 + s1 W, and the albedo A = a0 + a1 W.
struct CdrfLaws {
  double s0 = 0, s1 = 0, rms_log = 0;
  double a0 = 0, a1 = 0, albedo_rms = 0;
};

CdrfLaws fit_laws(const std::vector<WaterContentFit>& results) {
  std::vector<double> w, log_sigma0, amplitude;
  for (const auto& r : results) {
    w.push_back(r.absorption_percent);
    log_sigma0.push_back(std::log(r.fit.sigma0));
    amplitude.push_back(r.fit.amplitude);
  }
  CdrfLaws law;
  double c00 = 0, c01 = 0, c11 = 0, sum_sq = 0, albedo_sum_sq = 0;
  gsl_fit_linear(w.data(), 1, log_sigma0.data(), 1, w.size(), &law.s0, &law.s1, &c00, &c01, &c11, &sum_sq);
  law.rms_log = std::sqrt(sum_sq / w.size());
  gsl_fit_linear(w.data(), 1, amplitude.data(), 1, w.size(), &law.a0, &law.a1, &c00, &c01, &c11, &albedo_sum_sq);
  law.albedo_rms = std::sqrt(albedo_sum_sq / w.size());
  return law;
}

/// cdrf_fit.csv's rows: per water content, the fit, the law, the error and the times.
CsvTable fit_table(const std::vector<WaterContentFit>& results, const std::vector<GrainCheck>& grain_checks,
                   const CdrfLaws& law) {
  CsvTable fits({"soak_minutes", "absorption_percent", "reduced_scattering_per_mm", "refractive_index", "sigma0_mm",
                 "law_sigma0_mm", "amplitude", "rms", "relative_rms", "max_abs_error", "reference_s", "cdrf_ns",
                 "grain_rms", "grain_relative_rms", "grain_bake_s"});
  for (size_t i = 0; i < results.size(); ++i) {
    const auto& r = results[i];
    const GrainCheck g = i < grain_checks.size() ? grain_checks[i] : GrainCheck{};
    fits.add_row({cell(r.soak_minutes), cell(r.absorption_percent), cell(1e-3 * r.optics.reduced_scattering),
                  cell(r.optics.refractive_index), cell(1e3 * r.fit.sigma0),
                  cell(1e3 * std::exp(law.s0 + law.s1 * r.absorption_percent)), cell(r.fit.amplitude), cell(r.fit.rms),
                  cell(r.fit.rms / r.mean_exitance), cell(r.max_error), cell(r.reference_seconds),
                  cell(cdrf_nanoseconds(r.samples, r.fit.sigma0)), cell(g.rms),
                  cell(g.mean_exitance > 0.0 ? g.rms / g.mean_exitance : 0.0), cell(g.bake_seconds)});
  }
  return fits;
}

void plot_sphere_profiles(const std::filesystem::path& folder, const CdrfStudySettings& settings,
                          const WaterContentFit& middle, double worst_relative) {
  std::string radii;
  for (const double x : settings.radii_mm) radii += cell(x) + " ";
  render_plot(folder, "cdrf_profiles", R"(set terminal pngcairo size 900,600
set output 'cdrf_profiles.png'
set datafile separator ','
set xlabel 'angle between normal and light, θ [rad]'
set ylabel 'exitance / irradiance'
set title 'One σ0 per water content fits every radius to within )" + fixed(100 * worst_relative, 0) +
                                     R"(% RMS (W = )" + fixed(middle.absorption_percent, 1) + R"( % shown)'
set key right top
W = )" + cell(middle.absorption_percent) + R"(
R = ')" + radii + R"('
plot for [i=1:words(R)] 'cdrf_profiles.csv' using ($1 == W && $2 == word(R,i) ? $3 : 1/0):4:5 \
       with yerrorbars pt 7 ps 0.5 lc i title 'random walk, r = '.word(R,i).' mm', \
     for [i=1:words(R)] '' using ($1 == W && $2 == word(R,i) ? $3 : 1/0):6 with lines lw 2 lc i \
       title 'CDRF, r = '.word(R,i).' mm'
)");
}

void plot_grain_profiles(const std::filesystem::path& folder, const WaterContentFit& middle, double grain_worst) {
  render_plot(folder, "grain_profiles", R"(set terminal pngcairo size 900,600
set output 'grain_profiles.png'
set datafile separator ','
set xlabel 'angle between normal and light, θ [rad]'
set ylabel 'exitance / irradiance'
set title 'Sphere-fitted CDRF on a grain: )" + fixed(100 * grain_worst, 0) +
                                      R"(% RMS off, a thin grain lets light through (W = )" +
                                      fixed(middle.absorption_percent, 1) + R"( %)'
set key right top
W = )" + cell(middle.absorption_percent) + R"(
plot 'grain_profiles.csv' using ($1 == W ? $2 : 1/0):4:3 with points pt 7 palette title 'random walk on the grain (colour: κ [1/mm])', \
     '' using ($1 == W ? $2 : 1/0):5:3 with points pt 6 ps 1.5 palette title 'CDRF at the same θ and κ'
)");
}

void plot_sigma0_law(const std::filesystem::path& folder, const CdrfLaws& law) {
  render_plot(folder, "sigma0_law", R"(set terminal pngcairo size 900,600
set output 'sigma0_law.png'
set datafile separator ','
set logscale y
set format y '10^{%L}'
set xlabel 'water absorption W [%]'
set ylabel 'σ0 [mm] (log)'
set title 'σ0 = exp()" + fixed(law.s0, 3) + " + " + fixed(law.s1, 4) + R"( W) m: wetter grains scatter light further'
set key left top
plot 'cdrf_fit.csv' using 2:5 with points pt 7 ps 1.5 title 'fitted to the random walk', \
     '' using 2:6 with lines lw 2 title 'ln σ0 linear in W'
)");
}

}  // namespace

void cdrf_study_command(const CdrfStudySettings& settings, const std::filesystem::path& folder) {
  validate(settings);
  const auto start = std::chrono::steady_clock::now();
  const grains::WaterContentModel model(grains::read_absorption_table(grains::default_absorption_table()));
  make_output_folder(folder);

  CsvTable profiles({"absorption_percent", "radius_mm", "theta_rad", "reference", "standard_error", "cdrf"});
  CsvTable grain_profiles({"absorption_percent", "theta_rad", "curvature_per_mm", "reference", "cdrf"});
  std::vector<WaterContentFit> results;
  std::vector<GrainCheck> grain_checks;
  grains::GrainRecipe recipe;
  recipe.cultivar = grains::cultivar_by_name("japonica");
  const grains::Grain grain = grains::make_grain(recipe, settings.seed, 1.0);
  Progress progress("study cdrf: spheres", static_cast<int>(settings.soak_minutes.size() * settings.radii_mm.size()));
  int done = 0;
  for (const double minutes : settings.soak_minutes) {
    WaterContentFit r = fit_water_content(model.absorption_percent(minutes, settings.temperature_c), settings,
                                          [&] { progress.update(++done); });
    r.soak_minutes = minutes;
    if (settings.grain_photons > 0) {
      grain_checks.push_back(check_on_grain(r, grain.render.V, grain.render.F, settings.grain_photons, settings.seed));
      add_grain_profiles(grain_profiles, r, grain_checks.back());
    }
    add_sphere_profiles(profiles, r, settings);
    results.push_back(r);
  }
  progress.finish();

  const CdrfLaws law = fit_laws(results);
  double worst_relative = 0.0, grain_worst = 0.0;
  for (const auto& r : results) worst_relative = std::max(worst_relative, r.fit.rms / r.mean_exitance);
  for (const GrainCheck& g : grain_checks)
    if (g.mean_exitance > 0.0) grain_worst = std::max(grain_worst, g.rms / g.mean_exitance);
  write_file_atomically(folder / "cdrf_fit.csv", fit_table(results, grain_checks, law).text());
  write_file_atomically(folder / "cdrf_profiles.csv", profiles.text());
  if (settings.grain_photons > 0) write_file_atomically(folder / "grain_profiles.csv", grain_profiles.text());
  const WaterContentFit& middle = results[results.size() / 2];
  plot_sphere_profiles(folder, settings, middle, worst_relative);
  if (settings.grain_photons > 0) plot_grain_profiles(folder, middle, grain_worst);
  plot_sigma0_law(folder, law);
  stop_point();
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"study", "cdrf"},
                                  {"temperature_c", cell(settings.temperature_c)},
                                  {"photons_per_sphere", cell(static_cast<long>(settings.photons))},
                                  {"seed", cell(static_cast<long>(settings.seed))},
                                  {"law_s0", cell(law.s0)},
                                  {"law_s1_per_percent", cell(law.s1)},
                                  {"law_rms_log", cell(law.rms_log)},
                                  {"albedo_a0", cell(law.a0)},
                                  {"albedo_a1_per_percent", cell(law.a1)},
                                  {"albedo_rms", cell(law.albedo_rms)},
                                  {"worst_relative_rms", cell(worst_relative)},
                                  {"grain_worst_relative_rms", cell(grain_worst)},
                                  {"wall_s", cell(seconds_since(start))}}));
  std::printf("study cdrf: ln sigma0[m] = %.4f + %.5f W (RMS %.3f in ln), albedo = %.4f %+.5f W; worst relative "
              "RMS of the fit %.1f%% on spheres, %.1f%% on the grain\n",
              law.s0, law.s1, law.rms_log, law.a0, law.a1, 100 * worst_relative, 100 * grain_worst);
}

}  // namespace rice::experiments
