// The render study's second scene: a heap of japonica grains (from 4 generated variants),
// each dropped straight down at a random tilt onto the ground or the grains below until one
// of its vertices touches (a height field of the vertices placed so far), seen close up from
// 40° above: a crop of a heap, where light passes between and through grains. Not a
// simulation: it needs no solver, and gaps between grains are what it is for.
#pragma once

#include <cstdint>

#include "experiments/render/grain_plate.hpp"

namespace rice::experiments {

/// Builds `grains` grains from `seed` into `heap` (grains material 0, the ground 1; the scene
/// is committed after), with the plate's sun and sky.
void build_grain_heap(GrainPlate& heap, int grains, std::uint64_t seed);

}  // namespace rice::experiments
