// Strain-rate damping (xpbd/strain_rate_damping.hpp) against the modal Rayleigh rate: its
// damping matrix near rest is τ K, so a mode of frequency ω decays at σ = τ ω² / 2. A clamped
// bar (0.1 m × 0.02 m × 0.02 m, E = 100 kPa) is bent by a tip load, or twisted by a torque at
// its free end, then released without gravity; the decay of the tip's deflection (angle) is
// fitted over three periods, for the reference solver and vertex block descent (XPBD refuses
// this damping, xpbd/solver.hpp). Each method's own undamped run gives ω and
// the decay its time discretisation adds (backward Euler: about h ω² / 2), which is subtracted.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "fem_reference/implicit_solver.hpp"
#include "xpbd/solver.hpp"

namespace rice {
namespace {

using xpbd::Vec3;

constexpr double kLength = 0.1, kWidth = 0.02;

enum class Load { kBend, kTwist };
enum class Integrator { kReference, kVbd };

/// Vertices of the free end x = L.
std::vector<int> free_end(const xpbd::Positions& x) {
  std::vector<int> end;
  for (int i = 0; i < x.rows(); ++i)
    if (x(i, 0) > kLength - 1e-9) end.push_back(i);
  return end;
}

/// The bar bent (or twisted) by a static load at its free end and released at rest.
xpbd::Model loaded_bar(Load load, double tau) {
  const xpbd::TetMesh mesh = xpbd::make_box_tet_mesh(Vec3(kLength, kWidth, kWidth), 5, 1, 1);
  xpbd::Model model;
  model.particles = xpbd::make_particles(mesh, 1000.0);
  xpbd::add_neo_hookean_tets(model, mesh, xpbd::lame_from_young_poisson(1e5, 0.3), 0.0, tau);
  xpbd::pin_particles(model, xpbd::vertices_at_min_x(mesh.V));
  model.gravity.setZero();
  model.external_forces = xpbd::Positions::Zero(model.particles.size(), 3);
  const Vec3 axis_point(0.0, 0.5 * kWidth, 0.5 * kWidth);
  for (const int i : free_end(model.particles.x)) {
    const Vec3 arm = model.particles.x.row(i).transpose() - axis_point;
    const Vec3 force = load == Load::kBend ? Vec3(0.0, 0.0, -5e-3) : Vec3(Vec3::UnitX().cross(arm) * 0.5);
    model.external_forces.row(i) = force.transpose();
  }
  fem::ImplicitSolver(model, {.time_step = 1e-3, .newton = {}}).solve_static();
  model.external_forces.resize(0, 3);
  return model;
}

/// The tip's mean vertical deflection, or its mean rotation about the bar's axis.
double tip_signal(Load load, const xpbd::Positions& x, const xpbd::Positions& rest, const std::vector<int>& end) {
  double sum = 0.0;
  const Vec3 axis_point(0.0, 0.5 * kWidth, 0.5 * kWidth);
  for (const int i : end) {
    if (load == Load::kBend) {
      sum += x(i, 2) - rest(i, 2);
    } else {
      const Vec3 a = rest.row(i).transpose() - axis_point, b = x.row(i).transpose() - axis_point;
      sum += std::atan2(a.y() * b.z() - a.z() * b.y(), a.y() * b.y() + a.z() * b.z());
    }
  }
  return sum / static_cast<double>(end.size());
}

struct Decay {
  double omega;  ///< angular frequency from the spacing of the peaks [rad/s]
  double rate;   ///< σ of the fitted envelope e^{−σt} [1/s]
};

/// Simulates `periods` periods of the released bar and fits the peaks of |signal|.
Decay measure(Load load, Integrator integrator, double tau, double h, double duration) {
  xpbd::Model model = loaded_bar(load, tau);
  const xpbd::TetMesh rest_mesh = xpbd::make_box_tet_mesh(Vec3(kLength, kWidth, kWidth), 5, 1, 1);
  const std::vector<int> end = free_end(rest_mesh.V);
  std::function<void()> step;
  std::unique_ptr<fem::ImplicitSolver> reference;
  std::unique_ptr<xpbd::Solver> solver;
  if (integrator == Integrator::kReference) {
    reference = std::make_unique<fem::ImplicitSolver>(model, fem::ImplicitSettings{.time_step = h, .newton = {}});
    step = [&] { reference->step(); };
  } else {
    solver = std::make_unique<xpbd::Solver>(
        model, xpbd::SolverSettings{.time_step = h, .iterations = 30, .method = xpbd::Method::kVbd});
    step = [&] { solver->step(); };
  }
  std::vector<double> signal{tip_signal(load, model.particles.x, rest_mesh.V, end)};
  const int steps = static_cast<int>(std::lround(duration / h));
  for (int n = 0; n < steps; ++n) {
    step();
    signal.push_back(tip_signal(load, model.particles.x, rest_mesh.V, end));
  }
  // Peaks of |s| between zero crossings: times and log amplitudes, fitted by least squares.
  std::vector<double> times, logs;
  for (size_t n = 1; n + 1 < signal.size(); ++n) {
    const double a = std::abs(signal[n]);
    if (a > std::abs(signal[n - 1]) && a >= std::abs(signal[n + 1]) && n > 2) {
      times.push_back(n * h);
      logs.push_back(std::log(a));
    }
  }
  EXPECT_GE(times.size(), 4u) << "too few peaks";
  const double count = static_cast<double>(times.size());
  double mt = 0.0, ml = 0.0;
  for (size_t k = 0; k < times.size(); ++k) {
    mt += times[k] / count;
    ml += logs[k] / count;
  }
  double stt = 0.0, stl = 0.0;
  for (size_t k = 0; k < times.size(); ++k) {
    stt += (times[k] - mt) * (times[k] - mt);
    stl += (times[k] - mt) * (logs[k] - ml);
  }
  const double half_period = (times.back() - times.front()) / (count - 1.0);
  return {std::numbers::pi / half_period, -stl / stt};
}

struct Case {
  const char* name;
  Load load;
  Integrator integrator;
};

class ModalDamping : public ::testing::TestWithParam<Case> {};

TEST_P(ModalDamping, DecaysAtTheRayleighRateOfItsMode) {
  const Case c = GetParam();
  // τ gives a damping ratio ζ = τω/2 of about 0.1 (bending, ω ≈ 20 rad/s) and 0.05 (twist).
  const double tau = c.load == Load::kBend ? 1e-2 : 1e-3;
  const double h = 1e-3, duration = c.load == Load::kBend ? 1.0 : 0.25;
  const Decay undamped = measure(c.load, c.integrator, 0.0, h, duration);
  const Decay damped = measure(c.load, c.integrator, tau, h, duration);
  const double expected = 0.5 * tau * undamped.omega * undamped.omega;
  const double physical = damped.rate - undamped.rate;
  RecordProperty("omega", std::to_string(undamped.omega));
  RecordProperty("rate_expected", std::to_string(expected));
  RecordProperty("rate_measured", std::to_string(physical));
  EXPECT_NEAR(physical, expected, 0.05 * expected)
      << "omega " << undamped.omega << " rad/s, undamped decay " << undamped.rate << " /s";
}

INSTANTIATE_TEST_SUITE_P(
    BarsAndSolvers, ModalDamping,
    ::testing::Values(Case{"bend_reference", Load::kBend, Integrator::kReference},
                      Case{"bend_vbd", Load::kBend, Integrator::kVbd},
                      Case{"twist_reference", Load::kTwist, Integrator::kReference},
                      Case{"twist_vbd", Load::kTwist, Integrator::kVbd}),
    [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace rice
