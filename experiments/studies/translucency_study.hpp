// `rice study translucency`: the translucent rice model's table τ(d, cos θ) (shading/
// translucency.hpp, eq. T1) fitted per water content to the random-walk reference on real
// grain meshes, and how far the paper's CDRF and the new model each lie from that reference
// on grains the fit never saw (issue 24 §2: ≤ 20% RMS of the mean exitance on a grain).
//
// For each soak time (at one temperature): grains of every cultivar (`grains_per_cultivar`
// for the fit, as many others for the check), each lit by a sun from each of `directions`
// fixed directions spread over the sphere; the subsurface bake gives every vertex's M/E
// (shading/subsurface_bake.hpp), and the vertex its cos θ, mean curvature κ and thickness d
// (shading/thickness.hpp). τ is fitted to the fit grains' residuals M/E − A f_r. On the
// check grains, per grain and direction: the area-weighted RMS over vertices of each model
// against the bake, over the area-weighted mean M/E, and the bake's own noise (two seeds).
//
// Writes translucency_fit.csv (a row per water content, cultivar, grain and direction),
// translucency_table.csv (every node of every water content's τ; shading/data/translucency.csv
// is this file, shipped), translucency_table.png (τ against d), translucency_error.png (the
// two models against the reference at one water content) and run_info.txt.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "experiments/render/scene_pieces.hpp"

namespace rice::experiments {

struct TranslucencyStudySettings {
  double temperature_c = 5.0;                                  ///< Figure 13's water
  std::vector<double> soak_minutes = {15, 30, 60, 120, 240};
  std::vector<std::string> cultivars = {"japonica", "indica", "aromatic", "glutinous"};
  int grains_per_cultivar = 1;  ///< fitted; as many more are checked
  int directions = 8;
  long long photons = 300'000;  ///< per grain and direction
  double d_max_mm = 6.0;
  int d_nodes = 13, c_nodes = 9;
  double smoothing = 1e-4;
  /// shading normals and curvature smoothed over this ball (smooth_normals.hpp), as renders do
  double shading_radius_mm = 1e3 * kShadingRadius;
  double curvature_radius_mm = 1e3 * kCurvatureRadius;  ///< the curvature's, at most shading_radius_mm
  int curvature_rings = 2;        ///< the jet fit's neighbourhood for κ (curvature.hpp)
  std::uint64_t seed = 1;
};

/// Throws std::invalid_argument naming the option that is out of range.
void validate(const TranslucencyStudySettings& settings);

void translucency_study_command(const TranslucencyStudySettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
