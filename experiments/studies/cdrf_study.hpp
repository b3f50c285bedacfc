// `rice study cdrf`: the CDRF's σ0 fitted to our own subsurface-scattering reference, per
// water content (paper §4.4, eq. 8), and what the CDRF gives up against that reference.
//
// For each soak time (at one temperature) the water-content model gives the absorption W and
// the grain's optics (grains/water_content.hpp); a random walk (shading/random_walk.hpp)
// lights spheres of several radii and tallies their exitance against θ; σ0 and the albedo A
// are fitted to all radii at once (shading/sigma0_fit.hpp). Then ln σ0 = s0 + s1 W and
// A = a0 + a1 W are fitted across the water contents (GSL linear least squares): the laws
// WaterContentModel::scattering_sigma0 and cdrf_albedo hold.
//
// Writes cdrf_fit.csv (a row per water content), cdrf_profiles.csv (a row per θ bin and
// radius: reference ± standard error, fitted CDRF), grain_profiles.csv (per water content,
// cos θ and κ bin: reference and CDRF on the grain), cdrf_profiles.png, grain_profiles.png,
// sigma0_law.png and
// run_info.txt (the laws' constants, RMS errors, times).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include "grains/water_content.hpp"
#include "shading/curvature.hpp"
#include "shading/random_walk.hpp"
#include "shading/sigma0_fit.hpp"

namespace rice::experiments {

struct CdrfStudySettings {
  double temperature_c = 5.0;                                    ///< Figure 13's water
  std::vector<double> soak_minutes = {15, 30, 60, 120, 240};     ///< five absorptions
  std::vector<double> radii_mm = {0.5, 1.0, 2.0, 4.0};           ///< κ from 2.5 to 0.25 /mm
  long long photons = 200'000;                                   ///< per sphere
  long long grain_photons = 1'000'000;                           ///< on the grain mesh; 0: none
  int bins = 36;
  std::uint64_t seed = 1;
};

/// The reference at one water content and the σ0 fitted to it.
struct WaterContentFit {
  double soak_minutes = 0.0, absorption_percent = 0.0;
  grains::GrainOptics optics;
  std::vector<shading::ExitanceProfile> spheres;  ///< one per radius
  std::vector<shading::ExitanceSample> samples;   ///< all spheres' bins
  shading::Sigma0Fit fit;
  double max_error = 0.0;       ///< largest |A f_r − M/E| over the samples
  double mean_exitance = 0.0;   ///< mean M/E over the samples
  double reference_seconds = 0.0;
};

/// Random walks on the settings' spheres at water absorption W [%], and σ0 fitted to all of
/// them; `sphere_done` is called after each sphere.
WaterContentFit fit_water_content(double absorption_percent, const CdrfStudySettings& settings,
                                  const std::function<void()>& sphere_done = {});

/// The CDRF with a sphere-fitted σ0 and albedo on a grain mesh, against the random walk
/// baked on that mesh under a sun along +z: vertices binned by (cos θ, κ), each bin's
/// area-weighted mean exitance a sample.
struct GrainCheck {
  std::vector<shading::ExitanceSample> samples;  ///< reference bins
  std::vector<double> cdrf;                      ///< A f_r(θ, σ0 max(κ, 0)) at each bin
  double rms = 0.0, mean_exitance = 0.0, bake_seconds = 0.0;
};
GrainCheck check_on_grain(const WaterContentFit& fit, const shading::MeshVertices& V, const shading::MeshTriangles& F,
                          long long photons, std::uint64_t seed);

/// Throws std::invalid_argument naming the option that is out of range.
void validate(const CdrfStudySettings& settings);

void cdrf_study_command(const CdrfStudySettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
