// `rice study tet-quality`: how a grain simulation mesh's tet quality sets XPBD's stable
// substep. Japonica grains are meshed by Mesh_3 with each of several settings (the default's
// exudation alone, then sliver perturbation, ODT or Lloyd smoothing, tighter bounds); for each
// mesh the study measures its smallest dihedral angle and radius–edge ratio, and the fewest
// substeps per 1/60 s frame at which XPBD keeps the grain at rest on the ground
// (simulate_grain_at_rest, grain_substep_study.hpp), searched over a list of counts, beside
// the count at which a substep is one mean edge's P-wave crossing time. Writes
// tet_quality.csv, tet_quality.png (fewest stable substeps against smallest dihedral angle)
// and run_info.txt.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace rice::experiments {

struct TetQualityStudySettings {
  std::vector<int> substeps{20, 40, 60, 80, 120, 160, 240, 320, 480, 640};  ///< searched, increasing
  std::vector<std::uint64_t> seeds{3, 4, 5};  ///< of the grains
  int iterations = 5;  ///< XPBD's K
  int frames = 60;
  double young = 1e5;  ///< [Pa]
};

/// Throws std::invalid_argument naming the setting and its range.
void validate(const TetQualityStudySettings& settings);

void tet_quality_study_command(const TetQualityStudySettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
