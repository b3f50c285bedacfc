// Spring–mass oscillator against its analytic period and decay; see oscillator_study.hpp.
#include "experiments/studies/oscillator_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

#include "experiments/io/gnuplot.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "fem_reference/implicit_solver.hpp"
#include "xpbd/solver.hpp"

namespace rice::experiments {

OscillationMeasurement measure_oscillation(const std::vector<double>& t, const std::vector<double>& x) {
  std::vector<double> crossings, peak_times, peak_logs;
  for (size_t i = 1; i + 1 < x.size(); ++i) {
    if (x[i - 1] < 0.0 && x[i] >= 0.0)
      crossings.push_back(t[i - 1] + (t[i] - t[i - 1]) * (-x[i - 1]) / (x[i] - x[i - 1]));
    if (x[i] > 0.0 && x[i] >= x[i - 1] && x[i] > x[i + 1]) {
      // Parabola through the three samples around the maximum.
      const double a = 0.5 * (x[i - 1] - 2.0 * x[i] + x[i + 1]), b = 0.5 * (x[i + 1] - x[i - 1]);
      const double s = a != 0.0 ? -b / (2.0 * a) : 0.0;
      peak_times.push_back(t[i] + s * (t[i + 1] - t[i]));
      peak_logs.push_back(std::log(x[i] + b * s + a * s * s));
    }
  }
  if (crossings.size() < 2 || peak_times.size() < 2)
    throw std::runtime_error("measure_oscillation: fewer than two periods in the signal");
  OscillationMeasurement m;
  m.period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  // Least-squares slope of log(peak) against time.
  double mt = 0.0, ml = 0.0;
  for (size_t i = 0; i < peak_times.size(); ++i) {
    mt += peak_times[i] / peak_times.size();
    ml += peak_logs[i] / peak_times.size();
  }
  double stt = 0.0, stl = 0.0;
  for (size_t i = 0; i < peak_times.size(); ++i) {
    stt += (peak_times[i] - mt) * (peak_times[i] - mt);
    stl += (peak_times[i] - mt) * (peak_logs[i] - ml);
  }
  m.decay_rate = -stl / stt;
  return m;
}

const char* integrator_name(Integrator integrator) {
  return integrator == Integrator::kXpbd ? "xpbd" : "reference";
}

OscillationMeasurement simulate_oscillator(const OscillatorSettings& s, int substeps, double damping,
                                           Integrator integrator, std::vector<double>* trajectory) {
  using namespace rice::xpbd;
  Model model;
  model.gravity.setZero();
  model.particles.x = Positions::Zero(2, 3);
  model.particles.x(1, 0) = s.rest_length + s.amplitude;
  model.particles.v = Positions::Zero(2, 3);
  model.particles.w = Eigen::Vector2d(0.0, 1.0 / s.mass);
  model.distances.push_back({{0, 1}, s.rest_length, 1.0 / s.stiffness, damping});
  const double h = s.frame / substeps;
  // One solver step per substep, so that every substep is sampled.
  Solver xpbd(model, {.time_step = h, .substeps = 1, .iterations = 1, .execution = Execution::kSerial});
  fem::ImplicitSolver reference(model, {.time_step = h, .newton = {.tolerance = 1e-12}});
  const int steps = static_cast<int>(std::round(s.duration / h));
  std::vector<double> t{0.0}, x{s.amplitude};
  for (int k = 1; k <= steps; ++k) {
    stop_point();
    if (integrator == Integrator::kXpbd) xpbd.step();
    else reference.step();
    t.push_back(k * h);
    x.push_back(model.particles.x(1, 0) - s.rest_length);
  }
  if (trajectory) *trajectory = x;
  return measure_oscillation(t, x);
}

OscillationMeasurement analytic_oscillator(const OscillatorSettings& s, double damping) {
  const double omega0 = std::sqrt(s.stiffness / s.mass);
  const double zeta = damping / (2.0 * std::sqrt(s.stiffness * s.mass));
  if (zeta >= 1.0) throw std::invalid_argument("oscillator: damping must be below critical");
  return {2.0 * std::numbers::pi / (omega0 * std::sqrt(1.0 - zeta * zeta)), zeta * omega0};
}

void validate(const OscillatorSettings& s) {
  if (s.substeps.empty() || *std::min_element(s.substeps.begin(), s.substeps.end()) < 1)
    throw std::invalid_argument("oscillator: --substeps needs counts >= 1");
  const double critical = 2.0 * std::sqrt(s.stiffness * s.mass);
  if (!(s.damping >= 0.0 && s.damping < critical))
    throw std::invalid_argument("oscillator: --damping must be in [0, " + std::to_string(critical) +
                                ") (below critical damping)");
}

void oscillator_study_command(const OscillatorSettings& settings, const std::filesystem::path& folder) {
  validate(settings);
  make_output_folder(folder);
  const auto start = std::chrono::steady_clock::now();
  CsvTable table({"solver", "damping_ns_per_m", "substeps_per_frame", "substep_s", "period_s", "period_exact_s",
                  "period_rel_error", "decay_per_s", "decay_exact_per_s", "decay_abs_error_per_s",
                  "wall_s_per_sim_s"});
  std::printf("%10s %10s %9s %12s %12s %12s %12s %14s\n", "solver", "beta", "substeps", "period [s]", "exact",
              "decay [1/s]", "exact", "wall/sim time");
  for (const Integrator integrator : {Integrator::kXpbd, Integrator::kReference}) {
    for (const double damping : {0.0, settings.damping}) {
    const OscillationMeasurement exact = analytic_oscillator(settings, damping);
    for (const int n : settings.substeps) {
      const auto run_start = std::chrono::steady_clock::now();
      const OscillationMeasurement m = simulate_oscillator(settings, n, damping, integrator);
      const double cost = seconds_since(run_start) / settings.duration;
      table.add_row({integrator_name(integrator), cell(damping), cell(n), cell(settings.frame / n), cell(m.period), cell(exact.period),
                     cell(std::abs(m.period - exact.period) / exact.period), cell(m.decay_rate),
                     cell(exact.decay_rate), cell(std::abs(m.decay_rate - exact.decay_rate)), cell(cost)});
      std::printf("%10s %10.3g %9d %12.6f %12.6f %12.5f %12.5f %14.3e\n", integrator_name(integrator), damping, n, m.period, exact.period,
                  m.decay_rate, exact.decay_rate, cost);
      }
    }
  }
  write_file_atomically(folder / "oscillator.csv", table.text());
  render_plot(folder, "oscillator", R"(set terminal pngcairo size 1200,500
set output 'oscillator.png'
set datafile separator ','
set multiplot layout 1,2
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'wall time per simulated second [s]'
set key bottom left
set ylabel 'decay-rate error [1/s]'
xpbd(b) = (strcol(1) eq 'xpbd' && (b ? $2 > 0 : $2 == 0))
reference(b) = (strcol(1) eq 'reference' && (b ? $2 > 0 : $2 == 0))
set title 'Decay-rate error falls as h: XPBD is backward Euler, at a fraction of the reference cost' font ',10'
plot 'oscillator.csv' using (xpbd(0) ? $11 : 1/0):10 with linespoints title 'XPBD, beta = 0', \
     '' using (xpbd(1) ? $11 : 1/0):10 with linespoints title 'XPBD, beta > 0', \
     '' using (reference(0) ? $11 : 1/0):10 with points pt 6 ps 1.5 title 'reference, beta = 0', \
     '' using (reference(1) ? $11 : 1/0):10 with points pt 6 ps 1.5 title 'reference, beta > 0'
set ylabel 'relative period error'
set title 'Period error falls as h^2 without damping, on both solvers (substeps 1..128 per frame)' font ',10'
plot 'oscillator.csv' using (xpbd(0) ? $11 : 1/0):7 with linespoints title 'XPBD, beta = 0', \
     '' using (xpbd(1) ? $11 : 1/0):7 with linespoints title 'XPBD, beta > 0', \
     '' using (reference(0) ? $11 : 1/0):7 with points pt 6 ps 1.5 title 'reference, beta = 0', \
     '' using (reference(1) ? $11 : 1/0):7 with points pt 6 ps 1.5 title 'reference, beta > 0'
unset multiplot
)");
  stop_point();  // a Ctrl-C while gnuplot ran (it does not get the signal) stops here
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"study", "oscillator"},
                                  {"mass_kg", cell(settings.mass)},
                                  {"stiffness_n_per_m", cell(settings.stiffness)},
                                  {"damping_ns_per_m", cell(settings.damping)},
                                  {"duration_s", cell(settings.duration)},
                                  {"wall_s", cell(seconds_since(start))}}));
}

}  // namespace rice::experiments
