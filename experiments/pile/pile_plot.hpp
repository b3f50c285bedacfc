// pile.png of a pour: its grains' centres from the top and from the side, with the heap's
// least-squares flank on a plate (angle_of_repose.hpp; heap_profile.csv beside it) or the
// bowl's rim and inside wall in a chawan. Reads final_centres.csv (and bowl_outline.csv for a
// bowl) from the folder, as gnuplot does, so the plot can be redrawn from the files.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "experiments/pile/angle_of_repose.hpp"
#include "xpbd/types.hpp"

namespace rice::experiments {

struct PilePlotSettings {
  bool plate = true;         ///< a heap on a plate; otherwise grains in a bowl
  bool cohesion = true;      ///< named in the heap's title
  double rim_radius = 0.0;   ///< the bowl's [m]
  double ring_width = 0.0;   ///< of the heap profile's rings [m] (half a grain length)
};

/// Writes pile.png (and heap_profile.csv on a plate); returns the fitted heap, none in a bowl
/// or for grains scattered one deep (no flank to fit).
std::optional<HeapProfile> write_pile_plot(const std::filesystem::path& folder, const std::vector<xpbd::Vec3>& centres,
                                           const PilePlotSettings& settings);

}  // namespace rice::experiments
