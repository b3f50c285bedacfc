// `rice study oscillator`: one particle on an XPBD spring (distance constraint) against the
// analytic damped oscillator m ẍ + β ẋ + k x = 0, k = 1/α:
//   ω0 = sqrt(k/m), ζ = β / (2 sqrt(k m)), period T = 2π / (ω0 sqrt(1 − ζ²)), decay rate ζ ω0.
// The number of substeps per 1/60 s frame is swept, so the output is an error-versus-time
// curve: XPBD behaves like backward Euler, whose numerical damping h ω0²/2 shrinks with h.
// The reference solver (fem_reference/, backward Euler by Newton) runs the same sweep: on this
// linear problem the two must agree to round-off.
#pragma once

#include <filesystem>
#include <vector>

namespace rice::experiments {

struct OscillatorSettings {
  double mass = 1.0;          ///< m [kg]
  double stiffness = 100.0;   ///< k [N/m]
  double damping = 0.5;       ///< β [N s/m]
  double amplitude = 0.01;    ///< initial stretch [m]
  double rest_length = 0.1;   ///< [m]
  double duration = 5.0;      ///< simulated time [s]
  double frame = 1.0 / 60.0;  ///< [s]
  std::vector<int> substeps{1, 2, 4, 8, 16, 32, 64, 128};
};

struct OscillationMeasurement {
  double period;      ///< mean time between upward zero crossings [s]
  double decay_rate;  ///< −slope of log(peak amplitude) against time [1/s]
};

/// Period and decay rate of a sampled oscillation x(t) around 0 (at least two periods).
OscillationMeasurement measure_oscillation(const std::vector<double>& t, const std::vector<double>& x);

enum class Integrator { kXpbd, kReference };
const char* integrator_name(Integrator integrator);

/// Simulates the oscillator at h = frame / substeps and measures it. `trajectory`, when
/// given, receives the particle's stretch after every step.
OscillationMeasurement simulate_oscillator(const OscillatorSettings& settings, int substeps, double damping,
                                           Integrator integrator = Integrator::kXpbd,
                                           std::vector<double>* trajectory = nullptr);

/// Analytic period and decay rate for the given damping β.
OscillationMeasurement analytic_oscillator(const OscillatorSettings& settings, double damping);

/// Throws std::invalid_argument naming the setting that is out of range (damping at or
/// above critical, a substep count below 1).
void validate(const OscillatorSettings& settings);

/// Runs the sweep with and without damping; writes oscillator.csv, oscillator.png, run_info.txt.
void oscillator_study_command(const OscillatorSettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
