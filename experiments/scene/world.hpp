// What a scene run simulates (built by world_builder.hpp): the xpbd model of the grains and
// colliders, and for each grain what it was made from (its variant, swell P and rotation R)
// and where it was built, so a frame's pose places its render mesh. Grains wait parked far
// away, asleep, until an emitter (emitter.hpp) releases them into the scene.
#pragma once

#include <vector>

#include "grains/chawan.hpp"
#include "grains/collision_spheres.hpp"
#include "grains/grain_generator.hpp"
#include "xpbd/body.hpp"
#include "xpbd/model.hpp"

namespace rice::experiments {

/// One generated grain, instanced by many: its meshes and embedding, and its collision spheres.
struct GrainVariant {
  grains::Grain grain;
  grains::CollisionSpheres spheres;
};

struct World {
  /// bodies[g] is grain g. colliders[0] is the container (the chawan's distance grid or the
  /// plane z = 0), then the scene's analytic colliders, then its mesh colliders.
  xpbd::Model model;
  std::vector<GrainVariant> variants;
  std::vector<grains::GrainInstance> instances;  ///< per grain: its variant, swell P, rotation R
  /// Grain g's build point: its simulation mesh is its variant's, P R p + drops[g], and an
  /// emitter moves it there (plus an offset) when it releases it.
  std::vector<xpbd::Vec3> drops;
  std::vector<grains::Vertices> rest_vertices;  ///< simulation vertices at the build point
  std::vector<xpbd::Vec3> initial_centre;       ///< c₀: the centre there
  std::vector<xpbd::Quat> initial_orientation;  ///< the rigid bodies' q at the start
  /// The largest grain's length: its box's diagonal at the largest swell [m].
  double grain_length = 0.0;
  /// The thinnest variant's thickness T, its extent along z, unswollen [m].
  double grain_thickness = 0.0;
  int parking_row = 1;            ///< grains per row of parking places (an emitter's layer)
  grains::ChawanShape bowl;       ///< the chawan's sizes (also given on a plate: the plots use its rim)
  int first_mesh_collider = 1;    ///< model.colliders index of the scene's first mesh collider
  double rayleigh_time = 0.0;     ///< soft grains' τ from the soak (0: damping off) [s]
  double pull_off_in_weights = 0.0;  ///< cohesion: a bond's strength in the grain's weights
  int released = 0;               ///< grains [0, released) are in the scene, the rest parked

  int count() const { return static_cast<int>(instances.size()); }
  bool rigid() const { return !model.bodies.empty() && model.bodies.front().kind == xpbd::BodyKind::kRigid; }

  /// Where grain g waits until released: rows 2 m apart along x, far from everything.
  xpbd::Vec3 parking(int g) const { return xpbd::Vec3(2.0 * (1 + g / parking_row), 0.0, 0.0); }

  /// Moves parked grain g to its build point moved by `offset`, gives it `velocity`, and wakes
  /// it.
  void release(int g, const xpbd::Vec3& offset, const xpbd::Vec3& velocity = xpbd::Vec3::Zero());

  xpbd::Vec3 centre(int g) const;
  /// The velocity of grain g's centre of mass [m/s], and its speed.
  xpbd::Vec3 velocity(int g) const;
  double speed(int g) const { return velocity(g).norm(); }
  /// The highest centre of the grains released; -inf for none.
  double top() const;
  /// The centres of the grains released, in order.
  std::vector<xpbd::Vec3> released_centres() const;
  /// Grain g's render mesh now, through its embedding in its simulation mesh.
  grains::SurfaceMesh render_mesh(int g) const;
};

}  // namespace rice::experiments
