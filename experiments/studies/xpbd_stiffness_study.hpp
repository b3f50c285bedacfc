// `rice study xpbd-stiffness`: the XPBD paper's experiment (Macklin et al. 2016, §7.1). A
// tet-meshed cantilever, clamped at one end, sags under gravity to rest at a fixed time step
// with 5..100 iterations per substep. XPBD's rest deflection should not depend on the
// iteration count; PBD's does, because its stiffness per projection compounds with K.
#pragma once

#include <filesystem>
#include <vector>

namespace rice::experiments {

struct StiffnessStudySettings {
  std::vector<int> iterations{5, 10, 20, 50, 100};
  double length = 0.1;             ///< cantilever length [m]
  double width = 0.02;             ///< square section side [m]
  int cells_along = 10;            ///< cubes along the length (2×2 across)
  double young = 3e5;              ///< E [Pa]
  double poisson = 0.3;
  double density = 1000.0;         ///< ρ [kg/m³]
  double time_step = 1.0 / 60.0;   ///< one frame [s]
  int substeps = 50;               ///< fixed h = time_step / substeps for every run
  double pbd_stiffness = 1.0;      ///< k of the PBD runs
  double settle_velocity_scale = 0.8;  ///< v ← s·v after each frame, to reach rest sooner
  double rest_speed = 1e-6;        ///< [m/s] largest particle speed that counts as rest
  int rest_frames = 10;            ///< ... for this many frames in a row
  int max_frames = 600;
};

struct StiffnessRun {
  std::string method;  ///< "xpbd-neo-hookean", "xpbd-springs", "pbd-springs"
  int iterations = 0;
  double tip_deflection = 0.0;  ///< downward displacement of the free end's axis [m]
  int frames = 0;
  bool reached_rest = false;
  double wall_seconds = 0.0;
};

/// Runs every method at every iteration count.
std::vector<StiffnessRun> run_stiffness_study(const StiffnessStudySettings& settings);

/// (max − min) / mean of the tip deflection over the runs of one method.
double relative_spread(const std::vector<StiffnessRun>& runs, const std::string& method);

/// Throws std::invalid_argument naming the setting that is out of range.
void validate(const StiffnessStudySettings& settings);

/// Runs the study and writes stiffness.csv, stiffness.png and run_info.txt to `folder`;
/// prints the table and the spreads on stdout.
void stiffness_study_command(const StiffnessStudySettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
