// pile.png of a pour: its grains' centres from the top and from the side, with the heap's
// least-squares flank on a plate (angle_of_repose.hpp; heap_profile.csv beside it), the
// bowl's rim and inside wall in a chawan, or nothing more in a mould (its walls shape the pile,
// so no flank is fitted). Reads final_centres.csv (and bowl_outline.csv for a
// bowl) from the folder, as gnuplot does, so the plot can be redrawn from the files.
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "experiments/pile/angle_of_repose.hpp"
#include "xpbd/types.hpp"

namespace rice::experiments {

/// What holds the pile.
enum class PileHolder {
  kPlate,  ///< a heap on a plate, its flank fitted
  kBowl,   ///< a chawan, its rim and inside wall drawn
  kMould,  ///< a mould filled ([emitter] kind = "fill"): its walls, not a flank, shape the pile
};

struct PilePlotSettings {
  PileHolder holder = PileHolder::kPlate;
  bool cohesion = true;      ///< named in the heap's title
  double rim_radius = 0.0;   ///< the bowl's [m]
  double ring_width = 0.0;   ///< of the heap profile's rings [m] (half a grain length)
};

/// Writes pile.png (and heap_profile.csv on a plate); returns the fitted heap, none in a bowl or
/// a mould or for grains scattered one deep (no flank to fit).
std::optional<HeapProfile> write_pile_plot(const std::filesystem::path& folder, const std::vector<xpbd::Vec3>& centres,
                                           const PilePlotSettings& settings);

}  // namespace rice::experiments
