// A scene as its file describes it: one struct per section of the file (scene_file.hpp reads
// one; scene_keys.hpp lists every key with its type, default, range and meaning). The
// defaults below are the scene files' defaults: a test reads an empty file and compares.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "grains/mesh_types.hpp"
#include "xpbd/body.hpp"
#include "xpbd/collider.hpp"
#include "xpbd/model.hpp"

namespace rice::experiments {

/// Where the grains land: into the chawan (grains/chawan.hpp), or onto a flat plate (the
/// ground plane).
enum class Container { kChawan, kPlate };

/// How the grains enter the scene (emitter.hpp).
enum class EmitterKind {
  kSpout,  ///< a stream: layer after layer over `seconds`
  kClump,  ///< every layer at once, stacked: a clump dropped whole
  kFill,   ///< a hollow mesh collider filled in rounds (mould_fill.hpp)
};

/// [grains]: what the grains are.
struct SceneGrains {
  std::string cultivar = "japonica";
  int count = 800;
  int variants = 8;  ///< distinct generated grains, instanced
  std::uint64_t seed = 1;
  xpbd::BodyKind body = xpbd::BodyKind::kRigid;
  double young = 1e5;  ///< soft grains [Pa]: cooked rice kernels are soft (0.1–1 MPa; ESTIMATE)
  /// Soft grains' tets: the paper's stable Neo-Hookean pair, or the corotated pair, the same
  /// material at small strain. A corotated grain is stable under XPBD from 20 substeps a frame
  /// and drops run 1.8x faster at 160 than the pair at 480, but its piles do not fall asleep
  /// (heap: 294 of 300 grains awake at the end, against 93), so the paper's pair stays the
  /// default (docs/known-limits.md).
  xpbd::TetMaterial elasticity = xpbd::TetMaterial::kStableNeoHookean;
  /// Vertex range of a soft grain's simulation mesh (grains::SimulationMeshParameters).
  int min_vertices = 20, max_vertices = 60;
  /// Soft grains' lightest vertex mass, a fraction of their mean, keeping each grain's mass and
  /// centre of mass (xpbd/vertex_mass_floor.hpp); 0: the lumped masses as they are. At 0.5
  /// chawan_serving turns no tet inside out (7 at one frame at 0), and the table-1 bunny's
  /// seeds 1-3 hold 27-47% fewer inverted tet-frames (docs/known-limits.md#scale).
  double vertex_mass_floor = 0.5;
  double poisson = 0.3;
  double soak_minutes = 120.0;     ///< sets damping (soft) and cohesion
  double soak_temperature = 10.0;  ///< [°C]
  /// Pull-off force of two touching grains at the reference soak, in grain weights
  /// (grains::Cultivar::stickiness); NaN: the cultivar's.
  double stickiness = std::nan("");
  /// (xpbd::ContactSettings::bond_heal_time) [s]; NaN: never while touching.
  double heal_time = std::nan("");
};

/// [solver]: how time advances.
struct SceneSolver {
  double fps = 30.0;
  int frames = 180;
  /// 0: 80 for rigid grains, which keeps the resting pile's penetrations under 5% of a grain's
  /// thickness (measured: 20 left 29%, 40 left 6.5%); for soft ones at 30 fps, 160 for
  /// corotated tets and 480 for the stable Neo-Hookean pair, under its stability limit on the
  /// grains' sliver tets at E = 100 kPa (measured: one soft grain in the chawan bounces for
  /// ever at 240 substeps and sleeps within 30 frames at 480; docs/known-limits.md).
  int substeps = 0;
  int iterations = 1;
  /// Soft grains: how long their sphere radii hold between updates [s]
  /// (xpbd::ContactSettings::radius_interval; 0: every substep).
  double radius_interval = xpbd::ContactSettings{}.radius_interval;
  /// Soft grains' tets by vertex block descent (xpbd::Method::kVbd) instead of XPBD's
  /// projections; contacts, friction and cohesive bonds are terms of its particles' steps
  /// (xpbd/particle_contacts.hpp).
  bool vertex_block_descent = false;
  /// Vertex block descent: the soak's damping time τ (eq. 4) as the convex strain-rate
  /// damping (xpbd/strain_rate_damping.hpp), or false: as the paper's Rayleigh damping of the
  /// Neo-Hookean constraints, which vertex block descent minimises with a line search and
  /// which gains energy at τ ≫ h. XPBD always takes the paper's.
  bool vbd_strain_rate_damping = true;
  /// A checkpoint (checkpoint.hpp) every this many frames; 0: after the first frame that ends
  /// 30 s of wall time after the last one, and on Ctrl-C or SIGTERM either way.
  int checkpoint_every = 0;
};

/// [container]: what holds the grains.
struct SceneContainer {
  Container kind = Container::kChawan;
  double grid_spacing = 1e-3;  ///< the chawan's distance grid [m]
  /// The chawan's sizes times this (1: a rice bowl 12 cm across; 800 grains only cover its
  /// bottom, 0.45 heaps them).
  double scale = 1.0;
};

/// [emitter]: how the grains enter.
struct SceneEmitter {
  EmitterKind kind = EmitterKind::kSpout;
  /// Spout and clump: the opening's height above the chawan's rim or the plate [m], its radius
  /// [m] (0: the container's: on a plate 1.1 grain lengths, a narrow stream; in a chawan 0.6 of
  /// the bowl's inner radius less a grain length), and the time over which its layers leave
  /// (a spout's; a clump's leave at once).
  double height = 0.02, radius = 0.0, seconds = 1.5;
  /// Fill: the hollow mesh collider filled (an index into Scene::mesh_colliders), in rounds
  /// `round_seconds` apart for `seconds` (or until the mould is removed).
  int mould = -1;
  double round_seconds = 0.05;
};

/// [effects]: what is simulated; what is off costs nothing.
struct SceneEffects {
  double static_friction = 0.5, dynamic_friction = 0.4;  ///< grain–grain and grain–container (ESTIMATE); 0: off
  bool cohesion = true;  ///< water-content bonds between touching grains
  bool damping = true;   ///< soft grains' Rayleigh damping τ from the soak (eq. 4); off: τ = 0
  bool sleeping = true;
  /// A grain sleeps once every point of it moved slower than `sleep_speed` [m/s] over each of
  /// `sleep_frames` frames in a row (xpbd::SleepSettings). `rice study sleep` puts 3 to 30
  /// frames within the noise floor of a run without sleeping (the heap's and the rice cooker's
  /// settled shapes) and 5 at 0.55 of 15's time in the cooker (docs/studies.md#sleep).
  double sleep_speed = xpbd::SleepSettings{}.speed;
  int sleep_frames = 5;
  bool render_meshes = false;  ///< also write each frame's deformed render meshes (large)
  bool paraview = false;       ///< also write each frame's grains for ParaView (paraview_observer.hpp)
};

/// A closed triangle mesh as a collider (`shape = "mesh"`): a mould, a lid, a hand. Its
/// distance grid is sampled when the run starts.
struct MeshCollider {
  grains::SurfaceMesh mesh;    ///< in the collider's frame [m]
  double grid_spacing = 1e-3;  ///< [m]
  bool hollow = false;         ///< the room inside the mesh, the solid outside (a mould)
  xpbd::Collider collider;     ///< motion, friction, removal time; shape and grid set at the start
  std::string material = "plastic";  ///< how it is drawn (collider_drawing.hpp)
};

/// [render]: the last frame rendered after the simulation (rigid grains), by `rice render`'s
/// renderer with the CDRF at the grains' water content.
struct SceneRender {
  int width = 640, height = 480;
  int samples_per_pixel = 16;
  std::string integrator = "cdrf";  ///< cdrf, translucent or path
  int bounces = 0;
  bool studio = true;  ///< lighting = "studio"; false: "sun"
  double key_irradiance = 3.0, fill_ratio = 0.25;
  double sun_elevation_degrees = 50.0, sun_azimuth_degrees = -30.0;
  double sun_irradiance = 3.0;  ///< 0: no sun
  double sky_radiance = 0.3;
  bool ground = true;
  /// The camera, when the file gives one; otherwise it frames the grains.
  std::optional<xpbd::Vec3> eye, look_at;
  double vertical_fov_degrees = 30.0;
  /// Also every frame, into render_frames/frame_NNNN.png, with the last frame's camera.
  bool every_frame = false;
  /// Also render_frames/render.mp4 of every frame (implies every_frame).
  bool video = false;
};

struct Scene {
  std::string name;  ///< default: the file's stem
  std::string description;
  SceneGrains grains;
  SceneSolver solver;
  SceneContainer container;
  SceneEmitter emitter;
  SceneEffects effects;
  /// Colliders beside the container: planes, spheres, boxes and capsules, each with its
  /// keyframed motion, so a hand or a mould can press and withdraw; and meshes.
  std::vector<xpbd::Collider> colliders;
  std::vector<std::string> collider_materials;  ///< colliders[k]'s, how it is drawn (collider_drawing.hpp)
  std::vector<MeshCollider> mesh_colliders;
  std::optional<SceneRender> render;  ///< none: no [render] section
};

/// The checks the reader makes, for a scene built in code: throws std::invalid_argument naming
/// the section and key, the value and the range (scene_keys.hpp).
void validate(const Scene& scene);

/// scene.solver.substeps, or its default for the body kind when 0.
int substeps_per_frame(const Scene& scene);

/// Whether any of the scene's colliders beside the container, analytic or mesh, has `property`.
bool any_collider(const Scene& scene, const std::function<bool(const xpbd::Collider&)>& property);

}  // namespace rice::experiments
