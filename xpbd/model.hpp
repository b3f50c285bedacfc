// The physical system both solvers read (DESIGN.md, "The model shared by XPBD and the
// reference"): particles with positions, velocities and inverse masses, and the constraint
// sets with their compliances α and Rayleigh damping coefficients β. It holds data only; the
// XPBD solver and the reference FEM solver each bring their own bookkeeping.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "xpbd/body.hpp"
#include "xpbd/collider.hpp"
#include "xpbd/neo_hookean_constraints.hpp"
#include "xpbd/rigid_body.hpp"
#include "xpbd/tet_mesh.hpp"
#include "xpbd/types.hpp"

namespace rice::xpbd {

struct Particles {
  Positions x;                ///< #P by 3 positions [m]
  Positions v;                ///< #P by 3 velocities [m/s]
  Eigen::VectorXd w;          ///< #P inverse masses [1/kg]; 0 pins a particle
  int size() const { return static_cast<int>(x.rows()); }
};

/// C = |x_i − x_j| − L (distance_constraint.hpp).
struct DistanceConstraint {
  std::array<int, 2> particles;
  double rest_length;
  double compliance;  ///< α [m/N]
  double damping;     ///< β [N s/m], in D = ½ Ċᵀ β Ċ
};

/// C = V(x) − V0 (tet_volume_constraint.hpp).
struct TetVolumeConstraint {
  std::array<int, 4> particles;
  double rest_volume;
  double compliance;  ///< α [1/(Pa m³)]
  double damping;     ///< β
};

/// The elastic constraint pair (C_D, C_H) of one tetrahedron, of either material
/// (tet_constraint_pair.hpp evaluates it).
struct NeoHookeanTet {
  std::array<int, 4> particles;
  Mat3 Dm_inv;         ///< inverse rest edge matrix
  double rest_volume;  ///< V [m³]
  /// Neo-Hookean: parameters of the energy μ/2 tr FᵀF + λ/2 (det F − 1 − μ/λ)² [Pa]. Its
  /// linearisation at F = I has Lamé parameters (μ, λ − μ), so add_neo_hookean_tets stores
  /// λ = λ_Lamé + μ: a body then answers small loads as linear elasticity with (E, ν) does.
  /// Corotated: the same μ and λ, with the energy μ ‖F − R‖² + (λ − μ)/2 (det F − 1)².
  double mu, lambda;
  double beta_deviatoric, beta_hydrostatic;  ///< β_D, β_H
  /// τ [s] of the dissipation ½ τ Ė:𝒞:Ė on every strain rate (strain_rate_damping.hpp); 0: off.
  double strain_rate_damping = 0.0;
  TetMaterial material = TetMaterial::kStableNeoHookean;
  bool corotated() const { return material == TetMaterial::kCorotated; }
  double lambda_lame() const { return lambda - mu; }  ///< λ_L of the small-strain material
  /// α_D: 1/(μV), or 1/(2μV) for the corotated pair.
  double compliance_deviatoric() const { return 1.0 / ((corotated() ? 2.0 : 1.0) * mu * rest_volume); }
  /// α_H: 1/(λV), or 1/(λ_L V) for the corotated pair.
  double compliance_hydrostatic() const { return 1.0 / ((corotated() ? lambda_lame() : lambda) * rest_volume); }
  /// C_H = det F − this: γ = 1 + μ/λ, which makes the Neo-Hookean pair stress-free at rest; 1.
  double rest_determinant() const { return corotated() ? 1.0 : neo_hookean_gamma(mu, lambda); }
  /// U at F = I, subtracted so that rest has U = 0 (neo_hookean_rest_energy_density; 0).
  double rest_energy() const {
    return corotated() ? 0.0 : neo_hookean_rest_energy_density(mu, lambda) * rest_volume;
  }
};

/// Pulls particle i towards a target point: the vector constraint C = x_i − p (three scalar
/// constraints sharing one compliance). α = 0 holds it exactly.
struct Attachment {
  int particle;
  Vec3 target;
  double compliance;
};

/// Inequality constraint C = n·x − d ≥ 0 for every particle (rigid), with Coulomb friction
/// applied to positions (Macklin et al. 2014, "Unified Particle Physics", eq. 24).
struct GroundPlane {
  Vec3 normal{0.0, 0.0, 1.0};
  double offset = 0.0;
  double static_friction = 0.0;   ///< μ_s: tangential motion under μ_s·depth is removed
  double dynamic_friction = 0.0;  ///< μ_k: otherwise it shrinks by μ_k·depth
};

/// Contact between bodies (contact_solver.hpp).
struct ContactSettings {
  double static_friction = 0.0;   ///< μ_s between grains
  double dynamic_friction = 0.0;  ///< μ_k between grains, ≤ μ_s
  /// A sphere pair becomes a contact when its gap is below the distance its spheres can move
  /// in the substep plus this [m].
  double margin = 1e-5;
  /// Longest time between two broad phases [s]; the solver runs one every so many substeps.
  /// Boxes are padded by the distance a body can move in it (½ g t² alone is 0.12 mm at
  /// 5 ms), so a whole 30 fps frame would make every neighbouring sphere pair a candidate.
  double broad_phase_interval = 5e-3;
  /// Longest time between two updates of a soft body's sphere radii [s] (sphere_radius, from
  /// each sphere's tet's smallest stretch); between them the radii hold. Their eigenvalues
  /// were 13% of a soft onigiri's run when updated every substep. A strain that builds over
  /// an impact (~1 ms) or a press lags by at most this.
  double radius_interval = 5e-4;
  /// Cohesive bonds between bodies with bond_strength > 0 (cohesion_bonds.hpp); off costs nothing.
  bool cohesion = false;
  /// α of a bond [m/N]: 1e-4 stretches 1 µm under 10 mN. Under vertex block descent a bond
  /// between soft bodies is a spring no stiffer than particle_stiffness (particle_contacts.hpp).
  double bond_compliance = 1e-4;
  /// Two spheres closer than this [m] form a bond (1% of a grain's thickness), when they are
  /// a contact too (their gap within the margin and their motion).
  double bond_distance = 2e-5;
  /// A body pair whose bonds broke bonds again once its spheres have touched (within
  /// bond_distance) for this long [s] without a break, as cooked rice pressed back together
  /// sticks again; it bonds anew at once when it has separated first. INFINITY: never while
  /// touching (a pile churned by a fill then keeps most of its contacts unbonded).
  double bond_heal_time = INFINITY;
  /// k of contacts held in each particle's step under vertex block descent
  /// (particle_contacts.hpp) [N/m]: how hard a sweep pushes an overlap apart, and the step of
  /// the force's update each substep. Best near a grain tet's own stiffness (μ × edge ≈ 100 N/m
  /// at 100 kPa and 1 mm): on two grain-sized boxes pressed together (`rice study contact`)
  /// at one substep per frame and 20 sweeps, k = 300 left 5% error in the contact forces,
  /// 1e3 20%, 1e4 73% (the force steps overshoot), 100 37% (they build up too slowly).
  double particle_stiffness = 300.0;
};

/// Sleeping of resting bodies (sleeping.hpp); off costs nothing.
struct SleepSettings {
  bool enabled = false;
  double speed = 2e-3;  ///< a body is quiet in a step when its points move slower [m/s]
  int steps = 15;       ///< quiet steps before it sleeps
};

struct Model {
  Particles particles;
  /// Grains that touch: soft bodies own particles and tets above, rigid bodies a RigidBody.
  std::vector<Body> bodies;
  std::vector<RigidBody> rigid_bodies;
  std::vector<Collider> colliders;
  ContactSettings contact;
  SleepSettings sleep;
  std::vector<DistanceConstraint> distances;
  std::vector<TetVolumeConstraint> volumes;
  std::vector<NeoHookeanTet> neo_hookean;
  std::vector<Attachment> attachments;
  std::optional<GroundPlane> ground;
  Vec3 gravity{0.0, 0.0, -9.81};
  Positions external_forces;  ///< #P by 3 [N], or empty for none
};

/// Lamé parameters from Young's modulus E [Pa] and Poisson's ratio ν in (−1, 0.5).
struct LameParameters {
  double mu, lambda;
};
LameParameters lame_from_young_poisson(double young, double poisson);

/// Particles at the mesh vertices at rest, with lumped masses from density ρ [kg/m³].
Particles make_particles(const TetMesh& mesh, double density);

/// One elastic pair per tetrahedron, of `tet_material`, with the Lamé parameters `material`
/// at small strain (the energy's λ is material.lambda + material.mu, see NeoHookeanTet; the
/// corotated pair needs material.lambda > 0, a Poisson's ratio in (0, ½)). `rayleigh_time` τ [s] sets stiffness-proportional
/// damping β = τ/α for both constraints, so that γ = αβ/h = τ/h (XPBD eq. 26); it damps the
/// rates of C_D (‖F‖, or ‖F − R‖) and det F only. `strain_rate_time` τ_E [s] sets the damping of every strain
/// rate (NeoHookeanTet::strain_rate_damping), which needs 3λ + 2μ > 0.
void add_neo_hookean_tets(Model& model, const TetMesh& mesh, LameParameters material,
                          double rayleigh_time = 0.0, double strain_rate_time = 0.0,
                          TetMaterial tet_material = TetMaterial::kStableNeoHookean);

/// One distance constraint per unique tet edge. Each spring's compliance is
/// α = L² / (E V_e), V_e the volume of the tets around the edge shared among their six edges:
/// a rough spring-network stand-in for Young's modulus E (it is not a calibrated material).
void add_edge_springs(Model& model, const TetMesh& mesh, double young, double rayleigh_time = 0.0);

/// One volume constraint per tetrahedron with compliance α = 1 / (K V), K a bulk modulus.
void add_tet_volumes(Model& model, const TetMesh& mesh, double bulk_modulus,
                     double rayleigh_time = 0.0);

/// Pins particles (inverse mass 0, velocity 0).
void pin_particles(Model& model, const std::vector<int>& indices);

}  // namespace rice::xpbd
