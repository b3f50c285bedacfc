// `rice figure 10` (paper Fig. 10): a block of cooked grains dropped onto a plate after three
// soak times at 10 °C (experiments/scenes/drop_cup.toml: settled and bonded in a cup that is
// then taken away). Wetter grains stick (water-content cohesion) and stay heaped; drier ones
// break up. Each soak time runs the scene into its own folder; figure10.csv and figure10.png
// give, per soak time, the footprint radius, the number of groups of touching grains
// (pile_measures.hpp), the heap's height, the grains' mean rebound and, for soft grains, the
// largest mean principal strain a frame saw after the drop (impact_observer.hpp). Soft grains
// are damped by the soak's water content (eq. 4) and bond by its cohesion.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rice::experiments {

struct Figure10Settings {
  std::filesystem::path scene = "experiments/scenes/drop_cup.toml";
  std::vector<double> soak_minutes{15.0, 60.0, 240.0};
  /// More `--set section.key=value` overrides for every run (a short variant: fewer grains).
  std::vector<std::string> overrides;
};

/// Throws std::invalid_argument for no soak times or one out of (0, 1e5].
void validate(const Figure10Settings& settings);

void figure10_command(const Figure10Settings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
