// One procedural grain from a recipe and a seed (paper §4.1–4.3): parametric or user base
// surface → porous level set → render mesh (volumeToMesh) and simulation tet mesh (Mesh_3) →
// embedding → swell factor P applied to both meshes (eq. 2). And instances: a large set of
// grains as K generated variants re-used with random rotations and swell factors.
#pragma once

#include <Eigen/Geometry>

#include <cstdint>
#include <optional>
#include <vector>

#include "grains/base_shape.hpp"
#include "grains/collision_spheres.hpp"
#include "grains/cultivar.hpp"
#include "grains/embedding.hpp"
#include "grains/porous_level_set.hpp"
#include "grains/simulation_mesh.hpp"
#include "grains/template_cage.hpp"

namespace rice::grains {

struct GrainRecipe {
  Cultivar cultivar;
  /// A closed manifold surface in the grain frame [m] replacing the parametric base shape
  /// (the cultivar then supplies only the swell range).
  std::optional<SurfaceMesh> base_mesh;
  BaseShapeResolution base_resolution;
  PorosityParameters porosity;
  /// volumeToMesh adaptivity in [0, 1]; 0.05 keeps the mesh volume within 1% of the level
  /// set's on every cultivar (0.2 lost 3% on slender basmati grains).
  double mesh_adaptivity = 0.05;
  SimulationMeshParameters simulation;
  /// When set, the simulation mesh is a template cage enclosing the base surface
  /// (template_cage.hpp) instead of Mesh_3's tetrahedralisation of it.
  std::optional<TemplateCageParameters> cage;
  /// Density of a cooked grain's material [kg/m³]: about 1.1e3 (cooked rice kernels sink in
  /// water, and their water content of ~60% puts them between water and starch, 1.5e3);
  /// an ESTIMATE.
  double density = 1.1e3;
};

/// Throws std::invalid_argument for a bad recipe (naming the parameter), including a base
/// mesh that is not closed and manifold (naming the edge or vertex).
void validate(const GrainRecipe& recipe);

struct GrainTimings {
  double level_set = 0.0, render_mesh = 0.0, simulation_mesh = 0.0, embedding = 0.0;  ///< [s]
  double total() const { return level_set + render_mesh + simulation_mesh + embedding; }
};

struct Grain {
  GrainShape shape;        ///< sampled dimensions and P (for a user base mesh: its extent)
  PorousLevelSet level_set;  ///< before the swell factor (grain frame, P = 1)
  SurfaceMesh render;      ///< swollen, grain frame
  VolumeMesh simulation;   ///< swollen, grain frame
  SurfaceMesh base;        ///< the base surface the meshes follow, swollen, grain frame
  bool caged = false;      ///< the simulation mesh is a template cage (larger than the grain)
  Embedding embedding;     ///< render vertices in the simulation tets
  /// Density to give the simulation mesh's lumped masses so that they total ρ·V_render (the
  /// porous render volume): ρ V_render / V_simulation [kg/m³].
  double simulation_density = 0.0;
  GrainTimings timings;
};

/// Builds one grain; `swell` overrides the sampled P when given (instances use 1).
Grain make_grain(const GrainRecipe& recipe, std::uint64_t seed, std::optional<double> swell = std::nullopt);

/// The grain's collision spheres: fitted to its simulation mesh, or, for a cage, to its base
/// surface.
CollisionSpheres fit_grain_collision_spheres(const Grain& grain);

/// One grain of a large set: which variant, its swell factor and its orientation.
struct GrainInstance {
  int variant = 0;
  double swell = 1.0;
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
};

/// `count` instances of `variants` variants: variant drawn uniformly, P uniform in
/// the cultivar's range, rotations uniform on SO(3) (Shoemake's method).
std::vector<GrainInstance> make_instances(int count, int variants, const Cultivar& cultivar, RandomStream& random);

}  // namespace rice::grains
