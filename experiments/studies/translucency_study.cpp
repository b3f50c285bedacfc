// The translucency study; see translucency_study.hpp.
#include "experiments/studies/translucency_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "experiments/render/scene_pieces.hpp"
#include "grains/cultivar.hpp"
#include "grains/grain_generator.hpp"
#include "grains/water_content.hpp"
#include "shading/cdrf.hpp"
#include "shading/smooth_normals.hpp"
#include "shading/subsurface_bake.hpp"
#include "shading/thickness.hpp"
#include "shading/translucency.hpp"

namespace rice::experiments {
namespace {

/// A grain mesh and what the models read at its vertices.
struct GrainGeometry {
  std::string cultivar;
  int index = 0;  // within its cultivar: < grains_per_cultivar fitted, the rest checked
  shading::MeshVertices V, N;
  shading::MeshTriangles F;
  Eigen::VectorXd curvature, thickness;
  std::vector<double> area;  // a vertex's share of the surface; 0 on the walls of pores inside
};

GrainGeometry grain_geometry(const std::string& cultivar, int index, std::uint64_t seed,
                             const TranslucencyStudySettings& s) {
  grains::GrainRecipe recipe;
  recipe.cultivar = grains::cultivar_by_name(cultivar);
  const grains::Grain grain = grains::make_grain(recipe, seed, 1.0);
  const shading::MeshVertices& V = grain.render.V;
  const shading::MeshTriangles& F = grain.render.F;
  const double radius = 1e-3 * s.shading_radius_mm;
  const Eigen::VectorXd H = shading::vertex_mean_curvature(V, F, {.rings = s.curvature_rings});
  const double curvature_radius = std::min(radius, 1e-3 * s.curvature_radius_mm);
  GrainGeometry g{cultivar, index, V, shading::smoothed_vertex_normals(V, F, radius), F,
                  shading::smoothed_vertex_values(V, F, H, curvature_radius), shading::vertex_thickness(V, F), {}};
  shading::RenderScene scene;
  scene.add_instance(scene.add_prototype(g.V, g.F), Eigen::Affine3d::Identity(), 0);
  scene.commit();
  g.area = scene.vertex_areas(0);
  const std::vector<bool> outer = shading::vertex_sees_out(g.V, g.F);
  for (std::size_t v = 0; v < g.area.size(); ++v)
    if (!outer[v]) g.area[v] = 0.0;  // nobody sees a pore's wall: it counts for nothing
  return g;
}

/// `count` directions spread evenly over the sphere (a Fibonacci lattice).
std::vector<Eigen::Vector3d> sun_directions(int count) {
  std::vector<Eigen::Vector3d> out;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < count; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / count, r = std::sqrt(1.0 - z * z);
    out.emplace_back(r * std::cos(golden * k), r * std::sin(golden * k), z);
  }
  return out;
}

/// M/E at every vertex of the grain under a sun of unit irradiance along `direction`.
std::vector<float> bake_exitance(const GrainGeometry& g, const shading::Medium& medium, const Eigen::Vector3d& direction,
                                 long long photons, std::uint64_t seed) {
  shading::RenderScene scene;
  scene.add_instance(scene.add_prototype(g.V, g.F), Eigen::Affine3d::Identity(), 0);
  scene.commit();
  shading::Lights lights;
  lights.suns.push_back({.direction = direction.cast<float>(), .angular_radius = 0.0f,
                         .irradiance = shading::Color::Constant(1.0f)});
  return shading::bake_subsurface(scene, {0}, {medium}, lights, {.photons_per_light = photons, .seed = seed})[0];
}

/// The paper's CDRF, A f_r(θ, σ0 max(κ, 0)), at a vertex.
double cdrf_exitance(const shading::CdrfTable& cdrf, const shading::Material& m, double cos_theta, double curvature) {
  return m.albedo.mean() * cdrf(cos_theta, m.sigma0 * std::max(curvature, 0.0));
}

/// One grain under one sun: the bake, and the CDRF's prediction, at every vertex.
struct LitGrain {
  const GrainGeometry* grain = nullptr;
  int direction = 0;
  Eigen::Vector3d sun;
  std::vector<float> reference, second;  // second: another seed's bake (checked grains only)
};

double cos_at(const LitGrain& lit, Eigen::Index v) { return std::clamp(lit.grain->N.row(v).dot(lit.sun), -1.0, 1.0); }

/// A model's error on one grain under one sun, over the area-weighted mean exitance: per
/// vertex, and per bin of (cos θ, d) (12 × 6 bins of the vertices' area-weighted means; the
/// scale of the cdrf study's grain check, which bins by cos θ and κ).
struct GrainError {
  double mean = 0.0;
  double cdrf_rms = 0.0, model_rms = 0.0, noise_rms = 0.0;                // per vertex
  double cdrf_binned = 0.0, model_binned = 0.0, noise_binned = 0.0;       // per bin
};

/// Area-weighted sums of one vertex set: the reference, the two models and the bakes' noise.
struct Sums {
  double area = 0.0, reference = 0.0, paper = 0.0, model = 0.0, noise = 0.0;
  void add(double a, double r, double p, double m, double n) {
    area += a;
    reference += a * r;
    paper += a * p;
    model += a * m;
    noise += a * n;
  }
};

GrainError grain_error(const LitGrain& lit, const shading::CdrfTable& cdrf, const shading::Material& m,
                       const shading::TranslucencyTable& tau) {
  const GrainGeometry& g = *lit.grain;
  constexpr int kCos = 12, kThickness = 6;
  constexpr double kBinThickness = 1e-3;  // [m]
  std::vector<Sums> bins(kCos * kThickness);
  Sums total, squared;
  for (Eigen::Index v = 0; v < g.V.rows(); ++v) {
    const double a = g.area[v], c = cos_at(lit, v);
    if (a <= 0.0) continue;
    const double reference = 0.5 * (lit.reference[v] + lit.second[v]);
    const double paper = cdrf_exitance(cdrf, m, c, g.curvature(v));
    const double model = std::max(0.0, paper + tau(g.thickness(v), c));
    const double noise = 0.5 * (lit.reference[v] - lit.second[v]);  // the mean of two bakes' noise
    total.add(a, reference, paper, model, noise);
    squared.add(a, 0.0, std::pow(paper - reference, 2), std::pow(model - reference, 2), noise * noise);
    const int i = std::min(kCos - 1, static_cast<int>((c + 1.0) / 2.0 * kCos));
    const int j = std::min(kThickness - 1, static_cast<int>(g.thickness(v) / kBinThickness));
    bins[j * kCos + i].add(a, reference, paper, model, noise);
  }
  GrainError e;
  e.mean = total.reference / total.area;
  e.cdrf_rms = std::sqrt(squared.paper / total.area) / e.mean;
  e.model_rms = std::sqrt(squared.model / total.area) / e.mean;
  e.noise_rms = std::sqrt(squared.noise / total.area) / e.mean;
  Sums binned;
  for (const Sums& b : bins) {
    if (b.area <= 0.0) continue;
    const double r = b.reference / b.area;
    binned.add(b.area, 0.0, std::pow(b.paper / b.area - r, 2), std::pow(b.model / b.area - r, 2),
               std::pow(b.noise / b.area, 2));
  }
  e.cdrf_binned = std::sqrt(binned.paper / binned.area) / e.mean;
  e.model_binned = std::sqrt(binned.model / binned.area) / e.mean;
  e.noise_binned = std::sqrt(binned.noise / binned.area) / e.mean;
  return e;
}

std::vector<shading::TranslucencySample> residuals(const std::vector<LitGrain>& fitted, const shading::CdrfTable& cdrf,
                                                   const shading::Material& m) {
  std::vector<shading::TranslucencySample> out;
  for (const LitGrain& lit : fitted) {
    const GrainGeometry& g = *lit.grain;
    for (Eigen::Index v = 0; v < g.V.rows(); ++v) {
      if (g.area[v] <= 0.0) continue;
      const double c = cos_at(lit, v);
      out.push_back({c, g.thickness(v), lit.reference[v] - cdrf_exitance(cdrf, m, c, g.curvature(v)), g.area[v]});
    }
  }
  return out;
}

}  // namespace

void validate(const TranslucencyStudySettings& s) {
  if (s.soak_minutes.empty()) throw std::invalid_argument("study translucency: --soak-minutes needs at least one time");
  for (const double t : s.soak_minutes)
    if (!(t > 0.0)) throw std::invalid_argument("study translucency: --soak-minutes must be positive");
  if (s.cultivars.empty()) throw std::invalid_argument("study translucency: --cultivars needs at least one name");
  for (const std::string& c : s.cultivars) grains::cultivar_by_name(c);  // throws, listing the names
  if (s.grains_per_cultivar < 1) throw std::invalid_argument("study translucency: --grains must be at least 1");
  if (s.directions < 1) throw std::invalid_argument("study translucency: --directions must be at least 1");
  if (s.photons < 1000) throw std::invalid_argument("study translucency: --photons must be at least 1000");
  if (!(s.d_max_mm > 0.0) || s.d_nodes < 2 || s.c_nodes < 2)
    throw std::invalid_argument("study translucency: the table needs d_max > 0 and at least 2 nodes a side");
  if (!(s.smoothing >= 0.0)) throw std::invalid_argument("study translucency: --smoothing must be >= 0");
}

namespace {

/// Every grain of the study, fitted ones first within each cultivar.
std::vector<GrainGeometry> study_grains(const TranslucencyStudySettings& s) {
  std::vector<GrainGeometry> out;
  for (const std::string& cultivar : s.cultivars)
    for (int k = 0; k < 2 * s.grains_per_cultivar; ++k)
      out.push_back(grain_geometry(cultivar, k, s.seed + 1000 * static_cast<std::uint64_t>(k), s));
  return out;
}

/// One water content: bakes every grain under every sun, fits τ to the fitted grains, and
/// adds a row per checked grain and direction to `errors`. Returns τ.
shading::TranslucencyTable study_water_content(const TranslucencyStudySettings& s, double minutes, double absorption,
                                               const std::vector<GrainGeometry>& grain_set,
                                               const shading::CdrfTable& cdrf, CsvTable& errors,
                                               std::vector<GrainError>& checks, const std::function<void()>& bake_done) {
  const shading::Material material = rice_material(absorption);
  const shading::Medium medium = grain_medium(absorption);
  const std::vector<Eigen::Vector3d> suns = sun_directions(s.directions);
  std::vector<LitGrain> fitted, checked;
  for (const GrainGeometry& g : grain_set) {
    const bool fit = g.index < s.grains_per_cultivar;
    for (int k = 0; k < s.directions; ++k) {
      const std::uint64_t seed = s.seed + 7919 * static_cast<std::uint64_t>(k) + 104729 * g.index;
      LitGrain lit{&g, k, suns[k], bake_exitance(g, medium, suns[k], s.photons, seed), {}};
      if (!fit) lit.second = bake_exitance(g, medium, suns[k], s.photons, seed + 1);
      (fit ? fitted : checked).push_back(std::move(lit));
      bake_done();
      stop_point();
    }
  }
  shading::TranslucencyTable tau = shading::fit_translucency(residuals(fitted, cdrf, material), 1e-3 * s.d_max_mm,
                                                             s.d_nodes, s.c_nodes, s.smoothing);
  for (const LitGrain& lit : checked) {
    const GrainError e = grain_error(lit, cdrf, material, tau);
    checks.push_back(e);
    errors.add_row({cell(minutes), cell(absorption), lit.grain->cultivar, cell(lit.grain->index), cell(lit.direction),
                    cell(lit.sun.z()), cell(e.mean), cell(e.cdrf_rms), cell(e.model_rms), cell(e.noise_rms),
                    cell(e.cdrf_binned), cell(e.model_binned), cell(e.noise_binned)});
  }
  return tau;
}

void add_table_rows(CsvTable& table, double minutes, double absorption, const shading::TranslucencyTable& tau) {
  for (int j = 0; j < tau.c_nodes(); ++j)  // cos θ-major: each cos θ's nodes one run of rows
    for (int i = 0; i < tau.d_nodes(); ++i)
      table.add_row({cell(minutes), cell(absorption), cell(1e3 * tau.d_max() * i / (tau.d_nodes() - 1)),
                     cell(-1.0 + 2.0 * j / (tau.c_nodes() - 1)), cell(tau.values()[i * tau.c_nodes() + j])});
}

void plot_table(const std::filesystem::path& folder, double absorption) {
  render_plot(folder, "translucency_table", R"(set terminal pngcairo size 900,600
set output 'translucency_table.png'
set datafile separator ','
set xlabel 'thickness along -N, d [mm]'
set ylabel 'τ: exitance / irradiance beyond the CDRF'
set title 'Light through the grain, τ(d, cos θ) (W = )" + fixed(absorption, 1) + R"( %)'
set key outside right
W = )" + cell(absorption) + R"(
plot for [c in "-1 -0.75 -0.5 -0.25 0 0.5 1"] 'translucency_table.csv' \
  using ($2 == W && abs($4 - c) < 1e-9 ? $3 : 1/0):5 with linespoints lw 2 title 'cos θ = '.c
)");
}

void plot_errors(const std::filesystem::path& folder) {
  render_plot(folder, "translucency_error", R"(set terminal pngcairo size 900,600
set output 'translucency_error.png'
set datafile separator ','
set xlabel 'water absorption W [%]'
set ylabel 'RMS over a grain / its mean exitance'
set title 'Grains the fit never saw, every cultivar and sun direction' noenhanced
set logscale y
set key top right
plot 'translucency_fit.csv' using ($2-0.45):8 with points pt 7 ps 0.6 lc 1 title 'paper CDRF, per vertex', \
     '' using ($2-0.15):9 with points pt 5 ps 0.6 lc 2 title 'CDRF + τ(d, cos θ), per vertex', \
     '' using ($2+0.15):11 with points pt 6 ps 0.6 lc 1 title 'paper CDRF, per (cos θ, d) bin', \
     '' using ($2+0.45):12 with points pt 4 ps 0.6 lc 2 title 'CDRF + τ, per bin', \
     '' using 2:10 with points pt 1 ps 0.6 lc rgb 'gray40' title 'reference noise per vertex'
)");
}

double mean_of(const std::vector<GrainError>& checks, double GrainError::*field) {
  double sum = 0.0;
  for (const GrainError& e : checks) sum += e.*field;
  return sum / static_cast<double>(checks.size());
}

}  // namespace

void translucency_study_command(const TranslucencyStudySettings& settings, const std::filesystem::path& folder) {
  validate(settings);
  const auto start = std::chrono::steady_clock::now();
  const grains::WaterContentModel model(grains::read_absorption_table(grains::default_absorption_table()));
  make_output_folder(folder);
  const std::vector<GrainGeometry> grain_set = study_grains(settings);
  const shading::CdrfTable cdrf(513, 513);
  CsvTable errors({"soak_minutes", "absorption_percent", "cultivar", "grain", "direction", "sun_z", "mean_exitance",
                   "cdrf_relative_rms", "model_relative_rms", "reference_noise", "cdrf_binned_rms",
                   "model_binned_rms", "reference_binned_noise"});
  CsvTable table({"soak_minutes", "absorption_percent", "d_mm", "cos_theta", "tau"});
  Progress progress("study translucency: bakes", static_cast<int>(settings.soak_minutes.size() * grain_set.size() *
                                                                  settings.directions));
  int done = 0;
  std::vector<double> absorptions;
  std::vector<GrainError> checks;
  for (const double minutes : settings.soak_minutes) {
    absorptions.push_back(model.absorption_percent(minutes, settings.temperature_c));
    const shading::TranslucencyTable tau = study_water_content(settings, minutes, absorptions.back(), grain_set, cdrf,
                                                               errors, checks, [&] { progress.update(++done); });
    add_table_rows(table, minutes, absorptions.back(), tau);
  }
  progress.finish();
  write_file_atomically(folder / "translucency_fit.csv", errors.text());
  write_file_atomically(folder / "translucency_table.csv", table.text());
  plot_table(folder, absorptions[absorptions.size() / 2]);
  plot_errors(folder);
  // Means over every checked grain, direction and water content.
  const double cdrf_rms = mean_of(checks, &GrainError::cdrf_rms), model_rms = mean_of(checks, &GrainError::model_rms),
               noise = mean_of(checks, &GrainError::noise_rms), cdrf_binned = mean_of(checks, &GrainError::cdrf_binned),
               model_binned = mean_of(checks, &GrainError::model_binned),
               noise_binned = mean_of(checks, &GrainError::noise_binned);
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"study", "translucency"},
                                  {"temperature_c", cell(settings.temperature_c)},
                                  {"photons_per_bake", cell(static_cast<long>(settings.photons))},
                                  {"directions", cell(settings.directions)},
                                  {"grains_per_cultivar", cell(settings.grains_per_cultivar)},
                                  {"seed", cell(static_cast<long>(settings.seed))},
                                  {"mean_cdrf_relative_rms", cell(cdrf_rms)},
                                  {"mean_model_relative_rms", cell(model_rms)},
                                  {"mean_reference_noise", cell(noise)},
                                  {"mean_cdrf_binned_rms", cell(cdrf_binned)},
                                  {"mean_model_binned_rms", cell(model_binned)},
                                  {"mean_reference_binned_noise", cell(noise_binned)},
                                  {"wall_s", cell(seconds_since(start))}}));
  std::printf("study translucency: on grains the fit never saw, RMS / mean exitance per vertex: paper CDRF %.1f%%, "
              "CDRF + tau %.1f%% (reference noise %.1f%%); per (cos theta, d) bin: %.1f%%, %.1f%% (noise %.1f%%)\n",
              100 * cdrf_rms, 100 * model_rms, 100 * noise, 100 * cdrf_binned, 100 * model_binned, 100 * noise_binned);
}

}  // namespace rice::experiments
