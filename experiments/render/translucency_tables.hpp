// The translucent rice model's tables, τ(d, cos θ) per water content, as `rice study
// translucency` writes them (translucency_table.csv) and as the testbed ships them
// (shading/data/translucency.csv), and the model's material at any water content: the
// table blended linearly between the two fitted water contents around it.
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "shading/material.hpp"
#include "shading/translucency.hpp"

namespace rice::experiments {

struct TranslucencyAtWater {
  double absorption_percent = 0.0;
  shading::TranslucencyTable table;
};

/// Every water content's table, in increasing W. Throws std::runtime_error naming the file
/// for a missing column or a water content whose nodes do not fill one grid shared by all.
std::vector<TranslucencyAtWater> read_translucency_tables(const std::filesystem::path& path);

/// The tables shipped with the testbed, read once.
const std::vector<TranslucencyAtWater>& shipped_translucency();

/// τ at water absorption W: linear between the fitted contents around it, the nearest one's
/// outside their range.
std::shared_ptr<const shading::TranslucencyTable> translucency_at(const std::vector<TranslucencyAtWater>& tables,
                                                                  double absorption_percent);

/// The translucent rice model at W: rice_material (the paper's CDRF) with the shipped τ.
shading::Material translucent_rice_material(double absorption_percent);

}  // namespace rice::experiments
