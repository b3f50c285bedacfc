// Reading scene files strictly (toml++), section by section; see scene_file.hpp.
#include "experiments/scene/scene_file.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "experiments/io/csv_table.hpp"
#include "experiments/scene/toml_section.hpp"
#include "grains/mesh_io.hpp"
#include "grains/mesh_topology.hpp"

namespace rice::experiments {
namespace {

const std::vector<std::string> kSections{"scene", "grains", "solver", "container", "emitter", "effects", "render"};

toml::table parse_toml(std::string_view text, const std::string& source) {
  try {
    return toml::parse(text, std::string_view(source));
  } catch (const toml::parse_error& e) {
    throw SceneError(source_line(source, e.source()) + ": " + std::string(e.description()));
  }
}

/// The table "colliders.N.key" names (N from 1, as messages number them), and its key.
std::pair<toml::table*, std::string> collider_override_target(toml::table& document, const std::string& path,
                                                              const std::string& source) {
  const size_t dot = path.find('.');
  toml::array* colliders = document["colliders"].as_array();
  const int count = colliders ? static_cast<int>(colliders->size()) : 0;
  int n = 0;
  try {
    size_t used = 0;
    n = dot == std::string::npos ? 0 : std::stoi(path.substr(0, dot), &used);
    if (used != dot) n = 0;
  } catch (const std::logic_error&) {
  }
  if (n < 1 || n > count)
    throw SceneError(source + ": expected colliders.N.key=value with N in [1, " + std::to_string(count) +
                     "], the scene's [[colliders]] in order");
  return {(*colliders)[n - 1].as_table(), path.substr(dot + 1)};
}

/// Applies "section.key=value" or "colliders.N.key=value" to the document.
void apply_override(toml::table& document, const std::string& assignment) {
  const std::string source = "--set " + assignment;
  const size_t equals = assignment.find('='), dot = assignment.find('.');
  if (equals == std::string::npos || dot == std::string::npos || dot > equals)
    throw SceneError(source + ": expected section.key=value");
  const std::string section = assignment.substr(0, dot), key = assignment.substr(dot + 1, equals - dot - 1);
  toml::table value = parse_toml("v = " + assignment.substr(equals + 1), source);
  toml::node& node = *value.get("v");
  const toml::source_region region = node.source();  // "--set ...", line 1, in messages
  if (section == "colliders") {
    auto [collider, collider_key] = collider_override_target(document, key, source);
    collider->insert_or_assign(toml::key(collider_key, region), std::move(node));
    return;
  }
  if (std::find(kSections.begin(), kSections.end(), section) == kSections.end())
    throw SceneError(source + ": there is no section " + in_quotes(section) + "; sections: " + joined(kSections) +
                     ", or colliders.N");
  toml::node* existing = document.get(section);
  if (existing && !existing->is_table()) throw SceneError(source + ": " + in_quotes(section) + " is not a section");
  if (!existing) existing = &document.insert_or_assign(section, toml::table{}).first->second;
  existing->as_table()->insert_or_assign(toml::key(key, region), std::move(node));
}

/// Every top-level entry is a known section, or the list of [[colliders]].
void check_sections(const toml::table& document, const std::string& source) {
  for (auto&& [key, node] : document) {
    if (key.str() == "colliders") {
      if (!node.is_array_of_tables())
        throw SceneError(source_line(source, key.source()) + ": 'colliders' must be a list of [[colliders]] tables");
      continue;
    }
    const bool known = std::find(kSections.begin(), kSections.end(), key.str()) != kSections.end();
    if (!known || !node.is_table())
      throw SceneError(source_line(source, key.source()) + ": " + in_quotes(key.str()) + " is not a section; sections: " +
                       joined(kSections) + ", [[colliders]]");
  }
}

void read_grains(TomlSection section, SceneGrains& g) {
  g.cultivar = section.choice("cultivar");
  g.count = static_cast<int>(section.integer("count"));
  g.variants = static_cast<int>(section.integer("variants"));
  g.seed = static_cast<std::uint64_t>(section.integer("seed"));
  g.body = section.choice("body") == "soft" ? xpbd::BodyKind::kSoft : xpbd::BodyKind::kRigid;
  g.young = section.number("young_pa");
  g.elasticity = section.choice("elasticity") == "corotated" ? xpbd::TetMaterial::kCorotated
                                                              : xpbd::TetMaterial::kStableNeoHookean;
  g.min_vertices = static_cast<int>(section.integer("min_vertices"));
  g.max_vertices = static_cast<int>(section.integer("max_vertices"));
  if (g.min_vertices > g.max_vertices) {
    if (section.has("max_vertices"))
      section.require(false, "max_vertices", "at least min_vertices (" + cell(g.min_vertices) + ")");
    section.require(false, "min_vertices", "at most max_vertices (" + cell(g.max_vertices) + ")");
  }
  g.vertex_mass_floor = section.number("vertex_mass_floor");
  g.poisson = section.number("poisson");
  section.require(g.elasticity != xpbd::TetMaterial::kCorotated || g.poisson > 0.0, "poisson",
                  "> 0 with elasticity = 'corotated' (its volume term's stiffness is the Lame lambda)");
  g.soak_minutes = section.number("soak_minutes");
  g.soak_temperature = section.number("soak_temperature_c");
  g.stickiness = section.number("stickiness");
  g.heal_time = section.number("heal_s");
  section.finish();
}

void read_solver(TomlSection section, SceneSolver& s, xpbd::BodyKind body) {
  s.fps = section.number("fps");
  s.frames = static_cast<int>(section.integer("frames"));
  s.substeps = static_cast<int>(section.integer("substeps"));
  s.iterations = static_cast<int>(section.integer("iterations"));
  s.radius_interval = section.number("radius_interval_s");
  s.checkpoint_every = static_cast<int>(section.integer("checkpoint_every"));
  s.vertex_block_descent = section.choice("method") == "vbd";
  s.vbd_strain_rate_damping = section.choice("vbd_damping") == "strain-rate";
  section.require(s.vertex_block_descent || !section.has("vbd_damping"), "vbd_damping",
                  "given only with method = 'vbd' (XPBD takes the paper's Rayleigh damping)");
  section.require(!s.vertex_block_descent || body == xpbd::BodyKind::kSoft, "method",
                  "'xpbd' for rigid grains (vertex block descent moves soft grains' particles)");
  section.finish();
}

void read_container(TomlSection section, SceneContainer& c) {
  c.kind = section.choice("kind") == "plate" ? Container::kPlate : Container::kChawan;
  c.grid_spacing = section.number("grid_spacing_m");
  c.scale = section.number("scale");
  section.finish();
}

void read_effects(TomlSection section, SceneEffects& e) {
  const bool friction = section.flag("friction");
  e.static_friction = section.number("static_friction");
  e.dynamic_friction = section.number("dynamic_friction");
  if (e.dynamic_friction > e.static_friction) {
    if (section.has("dynamic_friction"))
      section.require(false, "dynamic_friction", "at most static_friction (" + cell(e.static_friction) + ")");
    section.require(false, "static_friction", "at least dynamic_friction (" + cell(e.dynamic_friction) + ")");
  }
  if (!friction) e.static_friction = e.dynamic_friction = 0.0;
  e.cohesion = section.flag("cohesion");
  e.damping = section.flag("damping");
  e.sleeping = section.flag("sleeping");
  e.sleep_speed = section.number("sleep_speed_m_s");
  e.sleep_frames = static_cast<int>(section.integer("sleep_frames"));
  e.render_meshes = section.flag("render_meshes");
  e.paraview = section.flag("paraview");
  section.finish();
}

/// A pose (one, or a keyframe's): position_m, and the rotation as an axis and an angle in degrees.
xpbd::ColliderKeyframe read_pose(TomlSection& section, double time) {
  xpbd::ColliderKeyframe key;
  key.time = time;
  key.translation = section.vector3("position_m");
  const xpbd::Vec3 axis = section.vector3("axis");
  const double angle = section.number("angle_deg");
  section.require(axis.norm() > 0.0 || angle == 0.0, "axis", "a direction, not [0, 0, 0]");
  if (angle != 0.0) key.rotation = xpbd::Quat(Eigen::AngleAxisd(angle * std::numbers::pi / 180.0, axis.normalized()));
  return key;
}

/// `keyframes`, a list of poses at increasing times.
std::vector<xpbd::ColliderKeyframe> read_keyframes(TomlSection& section, const toml::node& keyframes,
                                                   const std::string& source, const std::string& name) {
  const toml::array* list = keyframes.as_array();
  if (!list || list->empty() || !list->is_array_of_tables())
    section.fail(keyframes, "keyframes", expected(scene_key("colliders", "keyframes")));
  std::vector<xpbd::ColliderKeyframe> motion;
  for (size_t k = 0; k < list->size(); ++k) {
    TomlSection key((*list)[k].as_table(), source, name + ".keyframes." + std::to_string(k + 1), "keyframes");
    const double time = key.number("time_s", motion.empty() ? 0.0 : NAN);
    if (std::isnan(time)) key.fail_here("needs time_s");
    if (!motion.empty())
      key.require(time > motion.back().time, "time_s",
                  "a time in s after the previous keyframe's (" + cell(motion.back().time) + " s)");
    motion.push_back(read_pose(key, time));
    motion.back().scale = key.number("size");
    key.finish();
  }
  return motion;
}

/// A closed mesh file named by `file`, a path from the scene file's folder, its coordinates
/// multiplied by `scale`.
grains::SurfaceMesh read_mesh_file(TomlSection& section, const std::filesystem::path& folder) {
  const toml::node* node = section.claim("file");
  if (!node) section.fail_here("needs file, a mesh file (.obj, .off, .ply)");
  if (!node->is_string()) section.fail(*node, "file", expected(scene_key("colliders", "file")));
  const std::filesystem::path path = folder / *node->value<std::string>();
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))  // not a device: the fuzz targets read names too
    section.fail(*node, "file", "a mesh file that exists (looked for " + path.string() + ")");
  grains::SurfaceMesh mesh;
  try {
    mesh = grains::read_surface_mesh(path);
    grains::require_closed_manifold(mesh, path.string());
  } catch (const std::exception& e) {
    section.fail(*node, "file", "a closed triangle mesh: " + std::string(e.what()));
  }
  mesh.V *= section.number("scale");
  return mesh;
}

/// The shape of a [[colliders]] and the sizes that shape has; a mesh's file, hollowness and grid.
std::optional<MeshCollider> read_shape(TomlSection& section, const std::string& source, xpbd::Collider& c) {
  const std::string shape = section.choice("shape");
  if (shape.empty()) section.fail_here("needs a shape: 'plane', 'sphere', 'box', 'capsule' or 'mesh'");
  const auto size = [&](const std::string& key) {
    const double v = section.number(key);
    if (std::isnan(v)) section.fail_here("a " + shape + " needs " + key);
    return v;
  };
  if (shape == "plane") c.shape = xpbd::ColliderShape::kHalfSpace;
  if (shape == "sphere") {
    c.shape = xpbd::ColliderShape::kSphere;
    c.radius = size("radius_m");
  }
  if (shape == "box") {
    c.shape = xpbd::ColliderShape::kBox;
    c.half_extents = section.vector3("half_extents_m");
    if (!(c.half_extents.minCoeff() > 0.0)) section.fail_here("a box needs half_extents_m, three sizes > 0");
  }
  if (shape == "capsule") {
    c.shape = xpbd::ColliderShape::kCapsule;
    c.radius = size("radius_m");
    c.half_length = size("half_length_m");
  }
  if (shape != "mesh") return std::nullopt;
  MeshCollider mesh;
  mesh.mesh = read_mesh_file(section, std::filesystem::path(source).parent_path());
  mesh.hollow = section.flag("hollow");
  mesh.grid_spacing = section.number("grid_spacing_m");
  return mesh;
}

/// One [[colliders]] table: its shape and sizes, its friction (by default the grains'), when it
/// is removed, and where it is: one pose, or keyframes. Analytic shapes go to scene.colliders,
/// meshes to scene.mesh_colliders; returns the mesh's index there, or -1.
int read_collider(const toml::table& table, const std::string& source, const std::string& name, Scene& scene) {
  TomlSection section(&table, source, name, "colliders");
  xpbd::Collider c;
  std::optional<MeshCollider> mesh = read_shape(section, source, c);
  c.removal_time = section.number("removed_at_s", INFINITY);
  c.static_friction = section.number("static_friction", scene.effects.static_friction);
  c.dynamic_friction = section.number("dynamic_friction", std::min(scene.effects.dynamic_friction, c.static_friction));
  if (c.dynamic_friction > c.static_friction)
    section.require(false, "dynamic_friction", "at most static_friction (" + cell(c.static_friction) + ")");
  c.force_limit = section.number("force_limit_n", INFINITY);
  const xpbd::Vec3 axis = section.vector3("yield_axis");
  section.require(axis.norm() > 0.0, "yield_axis", "a direction, not [0, 0, 0]");
  c.yield_axis = axis.normalized();
  c.yield_speed = section.number("yield_speed_m_s");
  const toml::node* keyframes = section.claim("keyframes");
  c.motion = keyframes ? read_keyframes(section, *keyframes, source, name) : std::vector{read_pose(section, 0.0)};
  const std::string material = section.choice("material");
  section.finish();
  if (!mesh) {
    scene.colliders.push_back(c);
    scene.collider_materials.push_back(material);
    return -1;
  }
  mesh->collider = c;
  mesh->material = material;
  scene.mesh_colliders.push_back(std::move(*mesh));
  return static_cast<int>(scene.mesh_colliders.size()) - 1;
}

/// Spout and clump: the opening; a spout's time; fill: the mould (`mesh_of_collider` maps each
/// [[colliders]] to its index among the meshes, -1 for an analytic one) and the rounds.
void read_emitter(TomlSection section, Scene& scene, const std::vector<int>& mesh_of_collider) {
  SceneEmitter& e = scene.emitter;
  const std::string kind = section.choice("kind");
  e.kind = kind == "fill" ? EmitterKind::kFill : kind == "clump" ? EmitterKind::kClump : EmitterKind::kSpout;
  if (e.kind == EmitterKind::kFill) {
    if (!section.has("mould")) section.fail_here("kind = 'fill' needs mould, the number of a [[colliders]] (1 for the first)");
    const long mould = section.integer("mould");
    const bool hollow_mesh = mould <= static_cast<long>(mesh_of_collider.size()) && mesh_of_collider[mould - 1] >= 0 &&
                             scene.mesh_colliders[mesh_of_collider[mould - 1]].hollow;
    section.require(hollow_mesh, "mould", "the number of a [[colliders]] with shape = 'mesh' and hollow = true");
    e.mould = mesh_of_collider[mould - 1];
    e.round_seconds = section.number("round_s");
    e.seconds = section.number("seconds");
  } else {
    e.height = section.number("height_m");
    e.radius = section.number("radius_m");
    if (e.kind == EmitterKind::kSpout) {
      const toml::node* seconds = section.claim("seconds");  // 0 once meant a clump: say what it is now
      if (seconds && seconds->value<double>() == 0.0)
        section.fail(*seconds, "seconds", expected(scene_key("emitter", "seconds")) + " (all at once: kind = 'clump')");
      e.seconds = section.number("seconds");
    }
  }
  section.finish();
}

SceneRender read_render(TomlSection section) {
  SceneRender r;
  r.width = static_cast<int>(section.integer("width"));
  r.height = static_cast<int>(section.integer("height"));
  r.samples_per_pixel = static_cast<int>(section.integer("samples_per_pixel"));
  r.integrator = section.choice("integrator");
  r.bounces = static_cast<int>(section.integer("bounces"));
  r.studio = section.choice("lighting") == "studio";
  r.key_irradiance = section.number("key_irradiance");
  r.fill_ratio = section.number("fill_ratio");
  r.sun_elevation_degrees = section.number("sun_elevation_deg");
  r.sun_azimuth_degrees = section.number("sun_azimuth_deg");
  r.sun_irradiance = section.number("sun_irradiance");
  r.sky_radiance = section.number("sky_radiance");
  r.ground = section.flag("ground");
  r.every_frame = section.flag("every_frame");
  r.video = section.flag("video");
  if (section.has("eye_m") || section.has("look_at_m")) {
    r.eye = section.vector3("eye_m");
    r.look_at = section.vector3("look_at_m");
    if (!section.has("eye_m") || !section.has("look_at_m")) section.fail_here("give both eye_m and look_at_m, or neither");
    section.require(*r.eye != *r.look_at, "look_at_m", "a point other than eye_m");
  }
  r.vertical_fov_degrees = section.number("fov_deg");
  section.finish();
  return r;
}

}  // namespace

Scene parse_scene(std::string_view text, const std::string& source, const std::vector<std::string>& overrides) {
  toml::table document = parse_toml(text, source);
  for (const std::string& o : overrides) apply_override(document, o);
  check_sections(document, source);
  const auto section = [&](const char* name) { return TomlSection(document[name].as_table(), source, name); };

  Scene scene;
  TomlSection meta = section("scene");
  scene.name = meta.text("name");
  if (!meta.has("name")) scene.name = std::filesystem::path(source).stem().string();
  scene.description = meta.text("description");
  meta.finish();
  read_grains(section("grains"), scene.grains);
  read_solver(section("solver"), scene.solver, scene.grains.body);
  read_container(section("container"), scene.container);
  read_effects(section("effects"), scene.effects);
  // Colliders after [effects]: their friction defaults to the grains'.
  std::vector<int> mesh_of_collider;
  if (const toml::array* colliders = document["colliders"].as_array())
    for (size_t c = 0; c < colliders->size(); ++c)
      mesh_of_collider.push_back(
          read_collider(*(*colliders)[c].as_table(), source, "colliders." + std::to_string(c + 1), scene));
  read_emitter(section("emitter"), scene, mesh_of_collider);
  if (document.get("render")) scene.render = read_render(section("render"));
  return scene;
}

std::string read_scene_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path.string() + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

Scene read_scene_file(const std::filesystem::path& path, const std::vector<std::string>& overrides) {
  return parse_scene(read_scene_text(path), path.string(), overrides);
}

}  // namespace rice::experiments
