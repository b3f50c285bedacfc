// Release points inside a mould (scene files' `[emitter] kind = "fill"`, fill_emitter.hpp): the
// centres of a lattice of boxes inside the room of a collider (a hollow mesh), lowest first,
// each layer shifted half a box in x and y from the one below, and the points no grain is
// near yet (free_points). The fill jitters them and drops grains from them round by round.
#pragma once

#include <vector>

#include "xpbd/collider.hpp"

namespace rice::experiments {

/// Centres of boxes of size `cell` (x, y, z in the world) on a lattice over the collider's
/// distance grid at its pose at time 0, odd layers shifted by half a cell in x and y and every
/// box by `shift` cells (each in [0, 1)): the points whose box corners and centre all lie in the
/// room (φ > 0, the centre at least half the smallest side in), layer by layer from the bottom.
/// Throws std::invalid_argument for a collider without a grid, a cell that is not positive or a
/// shift outside [0, 1).
std::vector<xpbd::Vec3> mould_lattice(const xpbd::Collider& mould, const xpbd::Vec3& cell,
                                      const xpbd::Vec3& shift = xpbd::Vec3::Zero());

/// The lattice points farther than `clearance` from every centre in `occupied`, in order.
std::vector<xpbd::Vec3> free_points(const std::vector<xpbd::Vec3>& lattice, const std::vector<xpbd::Vec3>& occupied,
                                    double clearance);

}  // namespace rice::experiments
