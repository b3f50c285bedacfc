// `rice study grain-substeps`: the largest stable substep of one soft grain, and what a large
// substep costs in accuracy, for XPBD and vertex block descent (xpbd/solver.hpp). A japonica
// grain (E = 100 kPa, ν = 0.3) is set on the ground at rest, or dropped onto it, and stepped
// for `frames` frames at 60 fps with N substeps per frame. It touches the ground with its
// particles (a ground plane), or, as in a scene, with its collision spheres (a half-space
// collider and the contact solver). A run is stable when it stays finite, no tet inverts and
// the grain is at rest at the end (no particle moved faster than 1 mm/s over the last frame);
// its error is the RMS distance of its final particles to those of the finest stable
// vertex-block-descent run (or XPBD run, where none is), relative to the grain's length. Writes grain_substeps.csv, grain_substeps.png and run_info.txt.
#pragma once

#include <filesystem>
#include <vector>

#include "grains/grain_generator.hpp"
#include "xpbd/solver.hpp"

namespace rice::experiments {

/// One run of the study: the grain set on the ground at rest and stepped.
struct GrainRestRun {
  xpbd::Method method;
  int substeps, iterations;
  bool finite = true;
  double fastest = 0.0;       ///< fastest particle over the last frame, |Δx| / (1/60 s) [m/s]
  double volume_ratio = 0.0;  ///< smallest tet volume over its rest volume at the end
  double wall = 0.0;          ///< [s per simulated second]
  xpbd::Positions x;          ///< final positions
  bool stable() const { return finite && volume_ratio > 0.0 && fastest < 1e-3; }
};

/// How the grain meets the ground.
struct GrainRestSetup {
  double young = 1e5;  ///< [Pa]; ν = 0.3
  int frames = 60;     ///< of 1/60 s
  double drop_height = 0.0;  ///< the grain's lowest point above the ground at the start [m]
  /// true: the grain's collision spheres touch a half-space collider through the contact
  /// solver, as in a scene; false: its particles touch a ground plane.
  bool on_spheres = false;
};

/// N = `substeps` per frame, K = `iterations`, on one thread; ground friction 0.5 / 0.4.
GrainRestRun simulate_grain_at_rest(const grains::Grain& grain, const GrainRestSetup& setup, xpbd::Method method,
                                    int substeps, int iterations);

struct GrainSubstepStudySettings {
  std::vector<int> substeps{1, 2, 5, 10, 20, 40, 80, 160, 320, 480};  ///< per 1/60 s frame
  std::vector<int> xpbd_iterations{5};
  std::vector<int> vbd_iterations{5, 20};
  GrainRestSetup setup;
  unsigned seed = 3;   ///< of the grain
  /// Mesh_3's vertex range for the grain's simulation mesh (SimulationMeshParameters).
  int min_vertices = 20, max_vertices = 60;
  int cage_stations = 0;  ///< > 0: a template cage of that many stations instead (template_cage.hpp)
};

/// Throws std::invalid_argument naming the setting and its range.
void validate(const GrainSubstepStudySettings& settings);

void grain_substep_study_command(const GrainSubstepStudySettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
