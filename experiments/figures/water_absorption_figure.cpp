// Figure 11 driver (see water_absorption_figure.hpp).
#include "experiments/figures/water_absorption_figure.hpp"

#include <cmath>
#include <iostream>

#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "grains/water_content.hpp"

namespace rice::experiments {

namespace {

std::filesystem::path table_path(const WaterAbsorptionFigureSettings& settings) {
  return settings.table.empty() ? grains::default_absorption_table() : settings.table;
}

/// The table's samples, with log10 t and log10(1/β) from eq. 4's reading of them.
CsvTable data_table(const std::vector<grains::AbsorptionSample>& samples, const grains::WaterContentModel& model,
                    const grains::DampingReference& reference) {
  CsvTable data({"temperature_c", "soak_minutes", "absorption_percent", "log10_seconds", "log10_inverse_beta"});
  for (const grains::AbsorptionSample& s : samples)
    data.add_row({cell(s.temperature_c), cell(s.soak_minutes), cell(s.absorption_percent),
                  cell(std::log10(60.0 * s.soak_minutes)),
                  cell(std::log10(s.absorption_percent /
                                  (reference.beta * model.absorption_percent(reference.soak_minutes,
                                                                             reference.temperature_c))))});
  return data;
}

/// Fitted curves: each temperature's own Peleg fit, and the temperature-interpolated model,
/// from 1 to 180 minutes.
CsvTable curve_table(const grains::WaterContentModel& model) {
  CsvTable curves({"temperature_c", "soak_minutes", "peleg_fit_percent", "model_percent", "beta_s",
                   "eq4_beta_s", "sigma0_rad_m"});
  for (size_t i = 0; i < model.peleg_fits().size(); ++i) {
    const grains::PelegFit& peleg = model.peleg_fits()[i];
    const grains::DampingFit& damping = model.damping_fits()[i];
    for (int minutes = 1; minutes <= 180; ++minutes) {
      const double w = model.absorption_percent(minutes, peleg.temperature_c);
      curves.add_row({cell(peleg.temperature_c), cell(minutes), cell(peleg.absorption_percent(minutes)), cell(w),
                      cell(model.beta(minutes, peleg.temperature_c)), cell(damping.beta(60.0 * minutes)),
                      cell(grains::WaterContentModel::scattering_sigma0(w))});
    }
  }
  return curves;
}

/// The Peleg and eq. 4 fits per temperature (the latter printed too).
void write_fit_tables(const std::filesystem::path& folder, const grains::WaterContentModel& model) {
  CsvTable peleg({"temperature_c", "k1_min_per_percent", "k2_per_percent", "saturation_percent", "rms_residual_percent",
                  "samples"});
  for (const grains::PelegFit& fit : model.peleg_fits())
    peleg.add_row({cell(fit.temperature_c), cell(fit.k1), cell(fit.k2), cell(1.0 / fit.k2), cell(fit.rms_residual),
                   cell(fit.samples)});
  write_file_atomically(folder / "peleg_fits.csv", peleg.text());
  CsvTable damping({"temperature_c", "a", "b", "rms_residual_log10", "r_squared", "samples"});
  for (const grains::DampingFit& fit : model.damping_fits()) {
    damping.add_row({cell(fit.temperature_c), cell(fit.a), cell(fit.b), cell(fit.rms_residual), cell(fit.r_squared),
                     cell(fit.samples)});
    std::cout << "eq. 4 at " << fit.temperature_c << " C: a = " << fit.a << ", b = " << fit.b
              << ", rms residual = " << fit.rms_residual << " (log10), R^2 = " << fit.r_squared << '\n';
  }
  write_file_atomically(folder / "damping_fits.csv", damping.text());
}

void plot_figure11(const std::filesystem::path& folder, const grains::WaterContentModel& model) {
  std::string temperatures;
  for (const grains::PelegFit& fit : model.peleg_fits()) {
    if (!temperatures.empty()) temperatures += ' ';
    temperatures += cell(fit.temperature_c);
  }
  render_plot(folder, "figure11", "temps = '" + temperatures + "'\n" + R"(set terminal pngcairo size 1200,500
set output 'figure11.png'
set datafile separator ','
set multiplot layout 1,2
set key bottom right
set xlabel 'soaking time [min]'
set ylabel 'water absorption [% of dry weight]'
set title 'Water absorption (points: table, lines: Peleg fits)'
T(i) = word(temps, i) + 0
plot for [i=1:words(temps)] 'absorption_data.csv' using ($1 == T(i) ? $2 : 1/0):3 with points pt 7 lc i title word(temps, i).' C', \
     for [i=1:words(temps)] 'absorption_curves.csv' using ($1 == T(i) ? $2 : 1/0):3 with lines lc i notitle
set title 'Eq. 4: log10(1/beta) = a log10(t) + b'
set xlabel 'log10 soaking time [s]'
set ylabel 'log10(1/beta), beta in s'
set key bottom right
plot for [i=1:words(temps)] 'absorption_data.csv' using ($1 == T(i) ? $4 : 1/0):5 with points pt 7 lc i title word(temps, i).' C', \
     for [i=1:words(temps)] 'absorption_curves.csv' using ($1 == T(i) ? log10(60*$2) : 1/0):(-log10($6)) with lines lc i notitle
unset multiplot
)");
}

}  // namespace

void validate(const WaterAbsorptionFigureSettings& settings) {
  const std::filesystem::path table = table_path(settings);
  try {
    grains::WaterContentModel model(grains::read_absorption_table(table));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(table.string() + ": " + e.what());
  }
}

void water_absorption_figure_command(const WaterAbsorptionFigureSettings& settings,
                                     const std::filesystem::path& folder) {
  validate(settings);
  const auto start = std::chrono::steady_clock::now();
  const std::filesystem::path table = table_path(settings);
  const std::vector<grains::AbsorptionSample> samples = grains::read_absorption_table(table);
  const grains::DampingReference reference;
  const grains::WaterContentModel model(samples, reference);
  make_output_folder(folder);
  write_file_atomically(folder / "absorption_data.csv", data_table(samples, model, reference).text());
  write_file_atomically(folder / "absorption_curves.csv", curve_table(model).text());
  write_fit_tables(folder, model);
  plot_figure11(folder, model);
  stop_point();  // a Ctrl-C while gnuplot ran (it does not get the signal) stops here
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"figure", "11"},
                                  {"table", table.string()},
                                  {"damping_reference_temperature_c", cell(reference.temperature_c)},
                                  {"damping_reference_minutes", cell(reference.soak_minutes)},
                                  {"damping_reference_beta_s", cell(reference.beta)},
                                  {"arrhenius_c0", cell(model.arrhenius_c0())},
                                  {"arrhenius_c1_K", cell(model.arrhenius_c1())},
                                  {"wall_s", cell(seconds_since(start))}}));
}

}  // namespace rice::experiments
