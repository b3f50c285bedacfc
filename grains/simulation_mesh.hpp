// Low-resolution tetrahedral simulation mesh of a grain (paper §4.3: the dynamics run on a
// coarse mesh, the render mesh rides on it), made by CGAL's Mesh_3 from the closed base
// surface: Delaunay refinement to the size criteria below, then, as chosen, a global
// optimiser (ODT or Lloyd smoothing), sliver perturbation and sliver exudation. Tets come out
// positively oriented; none is inverted or flat (checked, and an error if violated). Slivers
// matter: XPBD's stable substep falls with a tet's smallest dihedral angle
// (`rice study tet-quality`).
#pragma once

#include <cstdint>
#include <functional>

#include "grains/mesh_types.hpp"

namespace rice::grains {

/// Mesh_3 criteria relative to the grain's bounding box, so one setting fits every cultivar
/// (from bold japonica to basmati, seven times longer than thick). Mesh_3's vertex count for
/// fixed criteria varies about fourfold with its random initial points, so the size and
/// distance bounds are scaled together (by 1.2 per try, then by bisection, then with the next
/// seed; up to 24 tries) until the count lies in [min_vertices, max_vertices].
struct SimulationMeshParameters {
  int min_vertices = 20;
  int max_vertices = 60;
  double edge_size = 0.6;         ///< facet and cell size bound, fraction of (L W T)^(1/3)
  double facet_distance = 0.2;    ///< surface approximation error bound, fraction of T
  double facet_angle_degrees = 25.0;
  double radius_edge_ratio = 3.0;
  double exude_sliver_degrees = 10.0;  ///< exudation target for the smallest dihedral angle (0: off)
  /// Mesh_3's global optimisers, run before perturbation and exudation, each for at most
  /// `optimiser_iterations` iterations (no time limit, so the mesh is deterministic).
  enum class Optimiser { kNone, kOdt, kLloyd };
  Optimiser optimiser = Optimiser::kNone;
  int optimiser_iterations = 50;
  double perturb_sliver_degrees = 0.0;  ///< sliver perturbation target (0: off)
};

/// "none", "odt" or "lloyd".
const char* optimiser_name(SimulationMeshParameters::Optimiser optimiser);

/// Throws std::invalid_argument naming the parameter and its accepted range.
void validate(const SimulationMeshParameters& parameters);

/// Tetrahedralises the inside of the closed surface `surface`; deterministic given `seed`.
/// When no try lands in the vertex range, the try nearest it is returned.
VolumeMesh make_simulation_mesh(const SurfaceMesh& surface, const SimulationMeshParameters& parameters,
                                std::uint64_t seed);

/// Tetrahedralises the inside of `surface` with Mesh_3's size bounds (the radii of facets'
/// surface Delaunay balls and of cells' circumspheres; a regular tet's is √6/4 of its edge)
/// given as a field `size(p)` [m]: a mesh graded towards where a study needs detail (a
/// contact). `facet_distance` [m] bounds the surface's approximation error; `parameters`'
/// angle, radius–edge ratio and exudation apply, its size bounds and vertex range do not.
/// Deterministic given `seed`.
VolumeMesh make_graded_mesh(const SurfaceMesh& surface, const std::function<double(const Vec3&)>& size,
                            double facet_distance, const SimulationMeshParameters& parameters, std::uint64_t seed);

}  // namespace rice::grains
