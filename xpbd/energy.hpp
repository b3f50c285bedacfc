// Energies of the shared model, used for diagnostics and by the tests: kinetic, gravitational
// and elastic U(x) = Σ ½ Cᵀ α⁻¹ C over the compliant constraints (DESIGN.md). The elastic
// energy of the Neo-Hookean pair is measured from its rest value, so a body at rest has U = 0.
#pragma once

#include "xpbd/model.hpp"

namespace rice::xpbd {

/// Σ ½ m |v|² over free particles (pinned particles carry no kinetic energy).
double kinetic_energy(const Particles& particles);

/// The particles' kinetic energy plus ½ m|v|² + ½ ωᵀIω of every movable rigid body.
double kinetic_energy(const Model& model);

/// −Σ m g·x over free particles and movable rigid bodies (zero at the origin).
double gravitational_energy(const Model& model);

/// Σ ½ C²/α over compliant constraints (α > 0); rigid constraints (α = 0) store none.
double elastic_energy(const Model& model);

/// ∇U(x), #P by 3: the elastic forces are its negative. Pinned particles included.
Positions elastic_energy_gradient(const Model& model);

/// Largest particle speed |v|.
double max_speed(const Particles& particles);

}  // namespace rice::xpbd
