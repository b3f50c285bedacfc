// The pour scene of issue 10 and the paper's Table 1 (800 japonica grains dropped into a
// chawan, 180 frames at 30 fps): procedural grains (K variants, instanced with their swell
// factor and rotation), their collision spheres, rigid or soft bodies, the chawan as a
// distance-grid collider, friction, water-content cohesion and sleeping. Poured onto a plate
// instead, the grains form a heap whose angle of repose is measured (angle_of_repose.hpp).
// Writes per frame the grains' transforms (rigid) or simulation positions (soft), optionally
// their deformed render meshes, `stats.csv` (per frame: wall time, awake grains, candidate
// pairs, contacts, bonds, penetration, kinetic energy, and the time split into broad phase,
// narrow phase, solves and sleeping), the final pile seen from the top and the side, for a
// filled mould its cut at half height (section.png, paper Fig. 16 b) and packing fraction,
// run_info.txt, and for rendering (`rice render --pour`) the variants' render meshes
// (variants/variant_k.ply) and grains.csv: each grain's variant, swell P, rotation R, drop
// point and initial centre c₀, so that a frame's pose (c, q) puts render vertex p at
// c + q (drop + P R p − c₀).
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "grains/mesh_types.hpp"
#include "xpbd/body.hpp"
#include "xpbd/collider.hpp"
#include "xpbd/penetration.hpp"

namespace rice::experiments {

/// Where the grains fall: into the chawan (grains/chawan.hpp), or onto a flat plate (the
/// ground plane) from a narrow spout, forming a heap.
enum class Container { kChawan, kPlate };

/// A closed triangle mesh as a collider (scene files' `shape = "mesh"`): a mould, a hand, a
/// plate. Its distance grid is sampled when the run starts.
struct MeshCollider {
  grains::SurfaceMesh mesh;    ///< in the collider's frame [m]
  double grid_spacing = 1e-3;  ///< [m]
  bool hollow = false;         ///< the room inside the mesh, the solid outside (a mould)
  xpbd::Collider collider;     ///< motion, friction, removal time; shape and grid set at the start
};

struct PourSettings {
  Container container = Container::kChawan;
  std::string cultivar = "japonica";
  int count = 800;
  int variants = 8;  ///< distinct generated grains, instanced
  xpbd::BodyKind body = xpbd::BodyKind::kRigid;
  int frames = 180;
  /// Grains leave the spout layer by layer, evenly over this time [s], from `spout_height`
  /// above the chawan's rim or above the plate; each waits, parked asleep far away, until its
  /// layer leaves. The chawan's spout is 0.6 of its inner radius wide, the plate's one grain.
  double pour_seconds = 1.5;
  double spout_height = 0.02;  ///< [m]
  /// Radius of the spout's opening [m]; 0: the container's (plate: 1.1 grain lengths, a narrow
  /// stream; chawan: 0.6 of the bowl's inner radius less a grain length). With pour_seconds = 0
  /// every layer leaves at once, stacked a cell apart: a clump dropped whole.
  double spout_radius = 0.0;
  double fps = 30.0;
  /// 0: 80 for rigid grains, which keeps the resting pile's penetrations under 5% of a grain's
  /// thickness (measured: 20 left 29%, 40 left 6.5%), and 480 for soft ones at 30 fps, under
  /// the Neo-Hookean pair's stability limit on the grains' sliver tets at E = 100 kPa
  /// (measured: one soft grain in the chawan bounces for ever at 240 substeps and sleeps
  /// within 30 frames at 480; 100 soft grains keep ringing with 3.4e-5 J at 240 and 3.5e-6 J
  /// at 360, and at 480 all but 7 sleep by frame 90; README "Known limits").
  int substeps = 0;
  int iterations = 1;
  /// Soft grains' tets by vertex block descent (xpbd::Method::kVbd) instead of XPBD's
  /// projections. Experimental: contacts are terms of each particle's step, but cohesive bonds
  /// stay projections after each sweep, and with them a pile gains energy (README "Known
  /// limits"; without cohesion it settles).
  bool vertex_block_descent = false;
  double young = 1e5;  ///< soft grains [Pa]: cooked rice kernels are soft (0.1–1 MPa; ESTIMATE)
  double poisson = 0.3;
  double soak_minutes = 120.0;     ///< sets damping (soft) and cohesion
  double soak_temperature = 10.0;  ///< [°C]
  /// Pull-off force of two touching grains at the reference soak, in grain weights
  /// (grains::Cultivar::stickiness); NaN: the cultivar's.
  double stickiness = std::numeric_limits<double>::quiet_NaN();
  double static_friction = 0.5, dynamic_friction = 0.4;  ///< grain–grain and grain–bowl (ESTIMATE)
  bool cohesion = true;
  bool damping = true;  ///< soft grains' Rayleigh damping τ from the soak (eq. 4); off: τ = 0
  bool sleeping = true;
  bool render_meshes = false;  ///< also write each frame's deformed render meshes (large)
  double grid_spacing = 1e-3;  ///< chawan distance grid [m]
  /// The chawan's sizes times this (1: a rice bowl 12 cm across; 800 grains only cover its
  /// bottom, 0.5 heaps them).
  double chawan_scale = 1.0;
  std::uint64_t seed = 1;
  /// More colliders beside the container (scene files): planes, spheres, boxes and capsules,
  /// each with its keyframed motion, so a hand or a mould can press and withdraw.
  std::vector<xpbd::Collider> colliders;
  std::vector<MeshCollider> mesh_colliders;
  /// ≥ 0: no spout; the grains fill mesh_colliders[fill_mould] (hollow) in rounds
  /// `fill_round_seconds` apart: each round puts grains, along the world's axes, at the points
  /// of a lattice of their bounding boxes inside it that no grain is near, lowest first
  /// (mould_fill.hpp).
  int fill_mould = -1;
  double fill_round_seconds = 0.5;
};

/// Throws std::invalid_argument naming the setting and its range.
void validate(const PourSettings& settings);

/// settings.substeps, or its default for the body kind when 0.
int substeps_per_frame(const PourSettings& settings);

struct PourResult {
  double simulation_seconds = 0.0;
  int awake = 0;  ///< grains awake at the end
  xpbd::Penetration penetration;  ///< the deepest overlaps at the end
  /// Plate only: the heap's angle of repose [°] and its apex above the lowest centre [m]; NaN
  /// in a bowl or for grains scattered one deep.
  double angle_of_repose_degrees = 0.0, heap_height = 0.0;
  /// The pile from above (pile_measures.hpp): the radius holding 90% of the grains' centres
  /// [m], and the groups of grains that touch (within 0.1 mm).
  double footprint_radius = 0.0;
  int clusters = 0;
  /// The highest grain centre [m] at the end, and just before the first collider's removal
  /// (a mould taken away; NaN when none is removed): whether the shape stands.
  double top = 0.0, top_before_removal = 0.0;
  /// A mould's fill or the chawan (paper Fig. 16 b, Fig. 15): the pile cut half way from the
  /// room's floor to the top centre (section.png), and the share of the room there that grains
  /// cover.
  double section_height = 0.0, packing_fraction = 0.0;
  /// Grains in the mould's room or within the bowl's rim at the end (-1: a plate).
  int in_container = -1;
};

/// Runs the scene and writes its files into `folder`.
PourResult pour_command(const PourSettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
