// `rice study convergence` (issue 3, §3): what XPBD's accuracy costs in time, measured
// against the reference solver (fem_reference/) on the same model at the same step h.
//
// For each scene (convergence_scenes.hpp), with and without Rayleigh damping:
//  1. reference trajectories: backward Euler by Newton at h = frame / N for every N, solved to
//     a tight relative gradient tolerance;
//  2. XPBD over N substeps per frame × K iterations per substep, with and without the
//     primal-residual correction (xpbd/solver.hpp; method "xpbd-primal"), vertex block
//     descent (method "vbd", N ≤ 16) on the same grid, and PBD on a springs model against its
//     own reference, for contrast. Damped scenes come twice: with each constraint's Rayleigh
//     damping (all methods) and with the strain-rate damping (vertex block descent only). Error: RMS vertex distance to the reference
//     over the frames of the trajectory, relative to the bar's length. Cost: wall time per
//     simulated second (runs execute side by side, one per core, each single-threaded);
//  3. one-step figures from reference states every few frames: the distance of XPBD's step to
//     the Newton solution of the same step, XPBD's primal residual ‖M(x − x̃) − ∇Cᵀλ‖ and its
//     constraint residual ‖C + α̃λ + γ∇CΔx‖ (xpbd/solver.hpp). These show where XPBD converges
//     to backward Euler and where it stops short;
//  4. a mesh-resolution axis: three resolutions, a subset of (N, K) each.
// Writes convergence.csv (every run), convergence.png (error against cost with the Pareto
// front), convergence_resolution.png, run_info.txt, and prints the table of errors.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "experiments/studies/convergence_scenes.hpp"

namespace rice::experiments {

struct ConvergenceSettings {
  BarSettings bar;
  double rayleigh_time = 2e-3;  ///< τ of the damped runs [s], for both kinds of damping
  double duration = 0.5;        ///< simulated time [s]
  double frame = 1.0 / 60.0;    ///< [s]
  std::vector<int> substeps{1, 2, 4, 8, 16, 32, 64};
  std::vector<int> iterations{1, 2, 5, 10, 20, 50};
  std::vector<int> resolutions{1, 2, 4};  ///< cubes across the section (5× along)
  /// Vertex block descent runs at N ≤ this only (it is for large steps; at N = 64 and K = 50 a
  /// run would take tens of seconds).
  int max_vbd_substeps = 16;
  int grid_resolution = 2;                ///< the full (N, K) grid runs at this resolution
  std::vector<int> resolution_substeps{4, 16};      ///< (N, K) subset at the other resolutions
  std::vector<int> resolution_iterations{5, 20};
  int sample_every = 5;               ///< frames between one-step samples
  double reference_tolerance = 1e-8;  ///< Newton's relative gradient tolerance

  /// A reduced run for CI (well under a minute): 0.1 s, N ∈ {1, 4, 16}, K ∈ {1, 5, 20}, two
  /// resolutions.
  static ConvergenceSettings quick();
};

/// One row of convergence.csv.
struct ConvergenceRun {
  std::string scene, model, method;  ///< "xpbd", "xpbd-primal", "pbd", "vbd" or "reference"
  std::string damping;               ///< "none", "constraint" or "strain-rate" (damping_name)
  int resolution = 0, tets = 0;
  double rayleigh_time = 0.0;        ///< τ of the damping [s]
  int substeps = 0, iterations = 0;  ///< iterations: K, or mean Newton iterations per step
  double wall_per_sim_second = 0.0;
  bool failed = false;               ///< the run threw (non-finite state); errors are NaN
  double trajectory_error = 0.0;     ///< RMS vertex distance over frames / L
  double max_frame_error = 0.0;      ///< largest per-frame RMS distance / L
  double step_distance = 0.0;        ///< mean one-step RMS distance to Newton / L
  double primal_residual = 0.0;      ///< mean ‖g‖ of the one-step samples [kg m]
  double constraint_residual = 0.0;  ///< mean ‖C + α̃λ + γ∇CΔx‖ of the samples
  bool pareto = false;               ///< on the error–cost front of its method and panel
};

std::vector<ConvergenceRun> run_convergence_study(const ConvergenceSettings& settings);

/// Throws std::invalid_argument when the settings cannot make a study (duration under one
/// frame, empty grids, the grid resolution not among the resolutions).
void validate(const ConvergenceSettings& settings);

void convergence_study_command(const ConvergenceSettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
