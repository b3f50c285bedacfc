// A floor under a soft body's lumped vertex masses. Lumping gives a vertex a quarter of each tet
// around it, so the tip of a coarse grain mesh that only one or two small tets reach weighs a
// twentieth of the mean vertex. An embedded contact sphere near it (xpbd::SphereAnchor) then puts
// nearly all of its correction on that vertex, which the one Gauss–Seidel sweep of a substep moves
// through the opposite face: the inverted tets of the fills (docs/known-limits.md#scale). Raising
// light vertices to a fraction of the mean keeps the body's mass and centre of mass, so that its
// translation and its weight's torque are unchanged; its inertia moves by up to ±20%, within the
// lumping's own error on such meshes (1.3–2.5 times the solid's).
#pragma once

#include <Eigen/Core>

#include "xpbd/model.hpp"

namespace rice::xpbd {

/// Masses m' near `masses` with m'_i ≥ f·m̄ (m̄ the mean mass), Σ m'_i = Σ m_i and
/// Σ m'_i x_i = Σ m_i x_i (x_i the rows of `positions`): Dykstra's alternating projections
/// between that box and that affine set (both convex; their limit is the least-squares nearest
/// such m'), stopped at the first iterate of the affine set that meets the floor to a relative
/// 1e-9. `masses` come back unchanged when none is below the floor. Throws
/// std::invalid_argument for f outside [0, 1) or a mass not positive and finite, and std::runtime_error
/// when the projections do not meet (no such m').
Eigen::VectorXd floored_masses(const Eigen::VectorXd& masses, const Positions& positions, double f);

/// Gives the particles of soft body `body` the floored masses of their lumped ones (f as above).
void floor_vertex_masses(Model& model, int body, double f);

}  // namespace rice::xpbd
