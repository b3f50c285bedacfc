// Bodies that touch: each grain of a many-grain model is one body, soft (its own particles and
// Neo-Hookean tets in the shared model) or rigid (a RigidBody, no tet solves). Both collide
// through the same collision spheres: a rigid body carries their centres in its body frame, a
// soft body embeds each centre in one of its tets with barycentric weights, so the spheres
// follow the deformation. The contact code sees only the four operations at the end of this
// file and does not care which kind it touches.
//
// Why spheres: a union of 10–30 spheres fitted inside a grain (grains/collision_spheres.hpp)
// is a closed volume, so no edge or face can slip between vertices, and a sphere pair or a
// sphere against an analytic shape has a closed-form distance and normal. This is the
// multi-sphere model of grain mechanics (DEM) for elongated kernels such as rice.
#pragma once

#include <array>
#include <vector>

#include "xpbd/rigid_body.hpp"
#include "xpbd/tet_mesh.hpp"

namespace rice::xpbd {

struct Particles;
struct Model;
struct LameParameters;

enum class BodyKind { kSoft, kRigid };

/// Where a soft body holds a sphere's centre: Σ weights[k] x[particles[k]] over the corners of
/// the tet holding it. The operations below, for a soft body, on these four particles (the
/// contact sweeps call them through each contact's sides, contact_solver.hpp).
struct SphereAnchor {
  std::array<int, 4> particles{};
  Eigen::Vector4d weights = Eigen::Vector4d::Zero();
  /// Σ weights[k] x[particles[k]] (the centre, from positions; its velocity, from velocities).
  Vec3 at(const Positions& x) const {
    Vec3 c = Vec3::Zero();
    for (int k = 0; k < 4; ++k) c += weights[k] * x.row(particles[k]).transpose();
    return c;
  }
  /// How far the centre moved from x_previous to x.
  Vec3 displacement(const Positions& x, const Positions& x_previous) const {
    Vec3 d = Vec3::Zero();
    for (int k = 0; k < 4; ++k) d += weights[k] * (x.row(particles[k]) - x_previous.row(particles[k])).transpose();
    return d;
  }
  /// Σ b_k² w_k: Δx_k = w_k b_k p moves the centre by that times p (w the inverse masses).
  double inverse_mass(const Eigen::VectorXd& w) const {
    double sum = 0.0;
    for (int k = 0; k < 4; ++k) sum += weights[k] * weights[k] * w[particles[k]];
    return sum;
  }
  /// x_k += w_k b_k p: the impulse p applied at the centre (to positions or velocities).
  void apply(Positions& x, const Eigen::VectorXd& w, const Vec3& p) const {
    for (int k = 0; k < 4; ++k) x.row(particles[k]) += (w[particles[k]] * weights[k]) * p.transpose();
  }
};

/// The elastic material of a tet's constraint pair.
enum class TetMaterial {
  kStableNeoHookean,  ///< the paper's (neo_hookean_constraints.hpp)
  kCorotated,         ///< zero at rest, stable at far fewer XPBD substeps (corotated_constraints.hpp)
};

struct Body {
  BodyKind kind = BodyKind::kRigid;
  int rigid_body = -1;        ///< index into Model::rigid_bodies (rigid)
  int first_particle = 0;     ///< soft: its particles are [first_particle, first_particle + particle_count)
  int particle_count = 0;
  std::vector<double> radii;  ///< collision sphere radii [m]
  /// Pull-off force of a cohesive bond to this body [N]; 0: not cohesive
  /// (cohesion_bonds.hpp). A pair's bond holds up to the smaller of the two.
  double bond_strength = 0.0;
  bool asleep = false;  ///< sleeping.hpp: not integrated, infinite mass in contact
  int quiet_steps = 0;  ///< consecutive steps slower than the sleep speed
  bool moving = false;  ///< faster than the sleep speed over the last step (it wakes neighbours)
  /// Rigid: sphere centres in the body frame.
  std::vector<Vec3> local_centres;
  /// Soft: each centre's anchor, and the index in Model::neo_hookean of the tet holding it.
  std::vector<SphereAnchor> anchors;
  std::vector<int> anchor_tets;
  int sphere_count() const { return static_cast<int>(radii.size()); }
};

/// Collision spheres given in the mesh frame: one row of `centres` and one radius each.
struct SphereSet {
  Positions centres;
  Eigen::VectorXd radii;
};

/// Adds a rigid body made of `mesh` (mass properties from density ρ [kg/m³]) with its
/// collision spheres, at rest where the mesh lies. Returns the body's index.
int add_rigid_body(Model& model, const TetMesh& mesh, double density, const SphereSet& spheres);

/// Adds a soft body: the mesh's vertices as new particles (lumped masses), one elastic
/// pair per tet (add_neo_hookean_tets) and the collision spheres embedded in the tets that
/// hold their centres (the nearest tet for a centre outside the mesh). Returns its index.
/// `rayleigh_time` and `strain_rate_time`: the tets' two dampings; `tet_material` their
/// material (add_neo_hookean_tets).
int add_soft_body(Model& model, const TetMesh& mesh, double density, const LameParameters& material,
                  double rayleigh_time, const SphereSet& spheres, double strain_rate_time = 0.0,
                  TetMaterial tet_material = TetMaterial::kStableNeoHookean);

/// Centre of mass: the rigid body's x, or the mass-weighted mean of a soft body's particles.
Vec3 body_centre(const Model& model, const Body& body);

/// For each particle, the soft body that owns it, or −1 (#particles).
std::vector<int> soft_body_of_particle(const Model& model);

/// Rigid: the largest distance from the centre of mass to a point of its spheres [m] (0 for a
/// soft body, whose points are its particles).
double reach(const Body& body);

/// The operations contact needs, for either kind of body. `point` is a world point attached
/// to sphere s (a contact point on its surface).
Vec3 sphere_centre(const Model& model, const Body& body, int s);
/// Rigid: radii[s]. Soft: radii[s] times the smallest principal stretch σ_min of the tet
/// holding the centre, capped at 1, so a grain pressed thinner has thinner spheres; with
/// radii that kept their size, a stack of grains could not be compressed below the sum of
/// its sphere diameters without overlapping. In a tet turned inside out σ_min, signed, is ≤ 0:
/// the radius is 0.
double sphere_radius(const Model& model, const Body& body, int s);
/// Where the material point now at `point` was at the start of the substep.
Vec3 previous_point(const Model& model, const Body& body, int s, const Vec3& point,
                    const Positions& x_previous);
/// Inverse mass the body shows to a positional impulse along the unit vector n at `point`.
double inverse_mass_at(const Model& model, const Body& body, int s, const Vec3& point, const Vec3& n);
/// Applies the positional impulse p [kg m] at `point`.
void apply_impulse_at(Model& model, const Body& body, int s, const Vec3& point, const Vec3& p);
/// Material coordinates of the point of sphere s's body that is at `point`: body-frame
/// coordinates (rigid) or the offset from the sphere's centre (soft), taken at the current
/// positions, or at the substep's start when `x_previous` is given.
Vec3 material_coordinates(const Model& model, const Body& body, int s, const Vec3& point,
                          const Positions* x_previous = nullptr);
/// Where the material point with those coordinates is now.
Vec3 material_point(const Model& model, const Body& body, int s, const Vec3& coordinates);
/// Velocity of the material point at `point`.
Vec3 velocity_at(const Model& model, const Body& body, int s, const Vec3& point);
/// Applies the impulse p [kg m/s] at `point` to the velocities.
void apply_velocity_impulse_at(Model& model, const Body& body, int s, const Vec3& point, const Vec3& p);

}  // namespace rice::xpbd
