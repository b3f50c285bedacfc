// Reading scene files strictly (toml++); see scene_file.hpp.
#include "experiments/scene/scene_file.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>

#include "grains/cultivar.hpp"
#include "grains/mesh_io.hpp"
#include "grains/mesh_topology.hpp"

namespace rice::experiments {
namespace {

std::string at(const std::string& source, const toml::source_region& region) {
  return (region.path ? std::string(*region.path) : source) + ":" + std::to_string(region.begin.line);
}

/// The shortest text that reads back as `value` (csv_table.hpp's cell(), which this reader does
/// not link: it stands alone for the fuzz targets).
std::string number_text(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

std::string in_quotes(std::string_view text) {
  std::string out(1, '\'');  // appended, not "'" + text: gcc 12 warns falsely (-Wrestrict) on that
  out.append(text);
  out.push_back('\'');
  return out;
}

std::string joined(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

/// A value as a file would write it, for messages.
std::string shown(const toml::node& node) {
  if (const auto* text = node.as_string()) return '"' + text->get() + '"';
  if (const auto* number = node.as_floating_point()) return number_text(number->get());
  std::ostringstream out;
  node.visit([&](const auto& value) { out << value; });
  return out.str();
}

/// Reads the keys of one section; finish() refuses any key nobody asked for.
class Section {
 public:
  Section(const toml::table* table, std::string source, std::string name)
      : table_(table), source_(std::move(source)), name_(std::move(name)) {}

  double number(const std::string& key, double fallback, const std::function<bool(double)>& accepts,
                const std::string& expected) {
    const toml::node* node = find(key);
    if (!node) return fallback;
    const std::optional<double> value = node->is_number() ? node->value<double>() : std::nullopt;
    if (!value || !std::isfinite(*value) || !accepts(*value)) fail(*node, key, expected);
    return *value;
  }
  double number_in(const std::string& key, double fallback, double low, double high) {
    return number(key, fallback, [&](double v) { return v >= low && v <= high; },
                  "a number in [" + number_text(low) + ", " + number_text(high) + "]");
  }
  long integer_in(const std::string& key, long fallback, long low, long high) {
    const toml::node* node = find(key);
    if (!node) return fallback;
    const std::optional<std::int64_t> value = node->is_integer() ? node->value<std::int64_t>() : std::nullopt;
    if (!value || *value < low || *value > high)
      fail(*node, key, "an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]");
    return static_cast<long>(*value);
  }
  /// Three numbers [x, y, z], each within ±bound.
  xpbd::Vec3 vector3(const std::string& key, const xpbd::Vec3& fallback, double bound) {
    const toml::node* node = find(key);
    if (!node) return fallback;
    const toml::array* array = node->as_array();
    xpbd::Vec3 v = xpbd::Vec3::Zero();
    bool ok = array && array->size() == 3;
    for (size_t k = 0; ok && k < 3; ++k) {
      const std::optional<double> x = (*array)[k].is_number() ? (*array)[k].value<double>() : std::nullopt;
      ok = x && std::isfinite(*x) && std::abs(*x) <= bound;
      if (ok) v[static_cast<Eigen::Index>(k)] = *x;
    }
    if (!ok) fail(*node, key, "three numbers [x, y, z] within ±" + number_text(bound));
    return v;
  }
  bool flag(const std::string& key, bool fallback) {
    const toml::node* node = find(key);
    if (!node) return fallback;
    if (!node->is_boolean()) fail(*node, key, "true or false");
    return *node->value<bool>();
  }
  std::string text(const std::string& key, const std::string& fallback) {
    const toml::node* node = find(key);
    if (!node) return fallback;
    if (!node->is_string()) fail(*node, key, "a text in quotes");
    return *node->value<std::string>();
  }
  std::string choice(const std::string& key, const std::string& fallback, const std::vector<std::string>& options) {
    const toml::node* node = find(key);
    if (!node) return fallback;
    std::vector<std::string> names;
    for (const std::string& o : options) names.push_back(in_quotes(o));
    if (!node->is_string() || std::find(options.begin(), options.end(), *node->value<std::string>()) == options.end())
      fail(*node, key, "one of " + joined(names));
    return *node->value<std::string>();
  }
  bool has(const std::string& key) const { return table_ && table_->get(key); }
  /// The key's node, counted as known (its reader checks it); null when absent.
  const toml::node* claim(const std::string& key) { return find(key); }
  /// Throws when `ok` is false, naming the key (which must be in the file).
  void require(bool ok, const std::string& key, const std::string& expected) const {
    if (!ok) fail(*table_->get(key), key, expected);
  }
  /// Throws a SceneError at the value's line: "[section] key = value: expected ...".
  [[noreturn]] void fail(const toml::node& node, const std::string& key, const std::string& expected) const {
    throw SceneError(at(source_, node.source()) + ": [" + name_ + "] " + key + " = " + shown(node) + ": expected " +
                     expected);
  }
  /// Throws a SceneError at the section's own line: "[section] what".
  [[noreturn]] void fail_here(const std::string& what) const {
    throw SceneError(at(source_, table_->source()) + ": [" + name_ + "] " + what);
  }
  void finish() const {
    if (!table_) return;
    for (auto&& [key, node] : *table_)
      if (std::find(asked_.begin(), asked_.end(), key.str()) == asked_.end())
        throw SceneError(at(source_, key.source()) + ": [" + name_ + "] has no key " + in_quotes(key.str()) +
                         "; its keys: " + joined(asked_));
  }

 private:
  const toml::node* find(const std::string& key) {
    asked_.push_back(key);
    return table_ ? table_->get(key) : nullptr;
  }

  const toml::table* table_;
  std::string source_, name_;
  std::vector<std::string> asked_;
};

const std::vector<std::string> kSections{"scene", "grains", "solver", "container", "emitter", "effects", "render"};

toml::table parse_toml(std::string_view text, const std::string& source) {
  try {
    return toml::parse(text, std::string_view(source));
  } catch (const toml::parse_error& e) {
    throw SceneError(at(source, e.source()) + ": " + std::string(e.description()));
  }
}

/// Applies "section.key=value" to the document.
void apply_override(toml::table& document, const std::string& assignment) {
  const std::string source = "--set " + assignment;
  const size_t equals = assignment.find('='), dot = assignment.find('.');
  if (equals == std::string::npos || dot == std::string::npos || dot > equals)
    throw SceneError(source + ": expected section.key=value");
  const std::string section = assignment.substr(0, dot), key = assignment.substr(dot + 1, equals - dot - 1);
  if (std::find(kSections.begin(), kSections.end(), section) == kSections.end())
    throw SceneError(source + ": there is no section " + in_quotes(section) + "; sections: " + joined(kSections));
  toml::table value = parse_toml("v = " + assignment.substr(equals + 1), source);
  toml::node* existing = document.get(section);
  if (existing && !existing->is_table()) throw SceneError(source + ": " + in_quotes(section) + " is not a section");
  if (!existing) existing = &document.insert_or_assign(section, toml::table{}).first->second;
  toml::node& node = *value.get("v");
  const toml::source_region region = node.source();  // "--set ...", line 1, in messages
  existing->as_table()->insert_or_assign(toml::key(key, region), std::move(node));
}

/// A keyframe: time_s, position_m, and the rotation as an axis and an angle in degrees.
xpbd::ColliderKeyframe read_pose(Section& section, double time) {
  xpbd::ColliderKeyframe key;
  key.time = time;
  key.translation = section.vector3("position_m", xpbd::Vec3::Zero(), 1e3);
  const xpbd::Vec3 axis = section.vector3("axis", xpbd::Vec3::UnitZ(), 1e3);
  const double angle = section.number_in("angle_deg", 0.0, -360.0, 360.0);
  section.require(axis.norm() > 0.0 || angle == 0.0, "axis", "a direction, not [0, 0, 0]");
  if (angle != 0.0) key.rotation = xpbd::Quat(Eigen::AngleAxisd(angle * std::numbers::pi / 180.0, axis.normalized()));
  return key;
}

/// A closed mesh file named by `key`, a path from the scene file's folder, its coordinates
/// multiplied by `scale`.
grains::SurfaceMesh read_mesh_file(Section& section, const std::string& key, const std::filesystem::path& folder) {
  const toml::node* node = section.claim(key);
  if (!node) section.fail_here("needs " + key + ", a mesh file (.obj, .off, .ply)");
  if (!node->is_string()) section.fail(*node, key, "a file name in quotes");
  const std::filesystem::path path = folder / *node->value<std::string>();
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))  // not a device: the fuzz targets read names too
    section.fail(*node, key, "a mesh file that exists (looked for " + path.string() + ")");
  grains::SurfaceMesh mesh;
  try {
    mesh = grains::read_surface_mesh(path);
    grains::require_closed_manifold(mesh, path.string());
  } catch (const std::exception& e) {
    section.fail(*node, key, "a closed triangle mesh: " + std::string(e.what()));
  }
  mesh.V *= section.number("scale", 1.0, [](double v) { return v > 0.0 && v <= 1e3; }, "a number in (0, 1e3]");
  return mesh;
}

/// One [[colliders]] table: its shape and the sizes that shape has (a mesh: its file), its
/// friction (by default the grains'), when it is removed, and where it is: one pose, or
/// `keyframes`, a list of poses at increasing times. Analytic shapes go to p.colliders, meshes
/// to p.mesh_colliders; returns the mesh's index there, or -1.
int read_collider(const toml::table& table, const std::string& source, const std::string& name, PourSettings& p) {
  Section section(&table, source, name);
  xpbd::Collider c;
  const std::string shape = section.choice("shape", "", {"plane", "sphere", "box", "capsule", "mesh"});
  if (shape.empty()) section.fail_here("needs a shape: 'plane', 'sphere', 'box', 'capsule' or 'mesh'");
  const auto positive = [](double v) { return v > 0.0 && v <= 10.0; };
  const auto size = [&](const std::string& key) {
    const double v = section.number(key, 0.0, positive, "a number in (0, 10]");
    if (v == 0.0) section.fail_here("a " + shape + " needs " + key);
    return v;
  };
  if (shape == "plane") c.shape = xpbd::ColliderShape::kHalfSpace;
  if (shape == "sphere") {
    c.shape = xpbd::ColliderShape::kSphere;
    c.radius = size("radius_m");
  }
  if (shape == "box") {
    c.shape = xpbd::ColliderShape::kBox;
    c.half_extents = section.vector3("half_extents_m", xpbd::Vec3::Zero(), 10.0);
    if (!(c.half_extents.minCoeff() > 0.0)) section.fail_here("a box needs half_extents_m, three sizes > 0");
  }
  if (shape == "capsule") {
    c.shape = xpbd::ColliderShape::kCapsule;
    c.radius = size("radius_m");
    c.half_length = size("half_length_m");
  }
  std::optional<MeshCollider> mesh;
  if (shape == "mesh") {
    mesh.emplace();
    mesh->mesh = read_mesh_file(section, "file", std::filesystem::path(source).parent_path());
    mesh->hollow = section.flag("hollow", false);
    mesh->grid_spacing = section.number_in("grid_spacing_m", mesh->grid_spacing, 2e-4, 1e-2);
  }
  c.removal_time = section.number("removed_at_s", INFINITY, [](double t) { return t > 0.0 && t <= 1e4; },
                                  "a time in (0, 1e4] s");
  c.static_friction = section.number_in("static_friction", p.static_friction, 0.0, 10.0);
  c.dynamic_friction = section.number_in("dynamic_friction", std::min(p.dynamic_friction, c.static_friction), 0.0, 10.0);
  if (c.dynamic_friction > c.static_friction)
    section.require(false, "dynamic_friction", "at most static_friction (" + number_text(c.static_friction) + ")");
  const toml::node* keyframes = section.claim("keyframes");
  if (!keyframes) {
    c.motion = {read_pose(section, 0.0)};
  } else {
    const toml::array* list = keyframes->as_array();
    if (!list || list->empty() || !list->is_array_of_tables())
      section.fail(*keyframes, "keyframes", "a list of { time_s = ..., position_m = [...] }");
    c.motion.clear();
    for (size_t k = 0; k < list->size(); ++k) {
      const toml::table& entry = *(*list)[k].as_table();
      Section key(&entry, source, name + ".keyframes." + std::to_string(k + 1));
      const double previous = c.motion.empty() ? -INFINITY : c.motion.back().time;
      const double time = key.number("time_s", c.motion.empty() ? 0.0 : NAN,
                                     [&](double t) { return t > previous && t <= 1e4; },
                                     "a time in s after the previous keyframe's, at most 1e4");
      if (std::isnan(time)) key.fail_here("needs time_s");
      c.motion.push_back(read_pose(key, time));
      key.finish();
    }
  }
  section.finish();
  if (!mesh) {
    p.colliders.push_back(c);
    return -1;
  }
  mesh->collider = c;
  p.mesh_colliders.push_back(std::move(*mesh));
  return static_cast<int>(p.mesh_colliders.size()) - 1;
}

}  // namespace

SceneDescription parse_scene(std::string_view text, const std::string& source, const std::vector<std::string>& overrides) {
  toml::table document = parse_toml(text, source);
  for (const std::string& o : overrides) apply_override(document, o);
  for (auto&& [key, node] : document) {
    if (key.str() == "colliders") {
      if (!node.is_array_of_tables())
        throw SceneError(at(source, key.source()) + ": 'colliders' must be a list of [[colliders]] tables");
      continue;
    }
    const bool known = std::find(kSections.begin(), kSections.end(), key.str()) != kSections.end();
    if (!known || !node.is_table())
      throw SceneError(at(source, key.source()) + ": " + in_quotes(key.str()) + " is not a section; sections: " +
                       joined(kSections) + ", [[colliders]]");
  }
  const auto section = [&](const char* name) { return Section(document[name].as_table(), source, name); };

  SceneDescription scene;
  PourSettings& p = scene.pour;
  Section meta = section("scene");
  scene.name = meta.text("name", std::filesystem::path(source).stem().string());
  scene.description = meta.text("description", "");
  meta.finish();

  Section grains = section("grains");
  p.cultivar = grains.choice("cultivar", p.cultivar, grains::cultivar_names());
  p.count = static_cast<int>(grains.integer_in("count", p.count, 1, 100000));
  p.variants = static_cast<int>(grains.integer_in("variants", p.variants, 1, 1000));
  p.seed = static_cast<std::uint64_t>(grains.integer_in("seed", static_cast<long>(p.seed), 0, INT64_MAX));
  const std::string body = grains.choice("body", "rigid", {"rigid", "soft"});
  p.body = body == "soft" ? xpbd::BodyKind::kSoft : xpbd::BodyKind::kRigid;
  p.young = grains.number_in("young_pa", p.young, 1e3, 1e9);
  p.poisson = grains.number("poisson", p.poisson, [](double v) { return v > -1.0 && v < 0.5; }, "a number in (-1, 0.5)");
  p.soak_minutes = grains.number("soak_minutes", p.soak_minutes, [](double v) { return v > 0.0 && v <= 1e5; },
                                 "a number in (0, 1e5]");
  p.soak_temperature = grains.number_in("soak_temperature_c", p.soak_temperature, 0.0, 100.0);
  p.stickiness = grains.number_in("stickiness", p.stickiness, 0.0, 1000.0);
  grains.finish();

  Section solver = section("solver");
  p.fps = solver.number("fps", p.fps, [](double v) { return v > 0.0 && v <= 1000.0; }, "a number in (0, 1000]");
  p.frames = static_cast<int>(solver.integer_in("frames", p.frames, 1, 100000));
  p.substeps = static_cast<int>(solver.integer_in("substeps", p.substeps, 0, 10000));
  p.iterations = static_cast<int>(solver.integer_in("iterations", p.iterations, 1, 1000));
  p.vertex_block_descent = solver.choice("method", "xpbd", {"xpbd", "vbd"}) == "vbd";
  solver.require(!p.vertex_block_descent || p.body == xpbd::BodyKind::kSoft, "method",
                 "'xpbd' for rigid grains (vertex block descent moves soft grains' particles)");
  solver.finish();

  Section container = section("container");
  p.container = container.choice("kind", "chawan", {"chawan", "plate"}) == "plate" ? Container::kPlate
                                                                                   : Container::kChawan;
  p.grid_spacing = container.number_in("grid_spacing_m", p.grid_spacing, 2e-4, 1e-2);
  p.chawan_scale = container.number_in("scale", p.chawan_scale, 0.1, 10.0);
  container.finish();

  Section effects = section("effects");
  const bool friction = effects.flag("friction", true);
  p.static_friction = effects.number_in("static_friction", p.static_friction, 0.0, 10.0);
  p.dynamic_friction = effects.number_in("dynamic_friction", p.dynamic_friction, 0.0, 10.0);
  if (p.dynamic_friction > p.static_friction) {
    if (effects.has("dynamic_friction"))
      effects.require(false, "dynamic_friction", "at most static_friction (" + number_text(p.static_friction) + ")");
    effects.require(false, "static_friction", "at least dynamic_friction (" + number_text(p.dynamic_friction) + ")");
  }
  if (!friction) p.static_friction = p.dynamic_friction = 0.0;
  p.cohesion = effects.flag("cohesion", p.cohesion);
  p.damping = effects.flag("damping", p.damping);
  p.sleeping = effects.flag("sleeping", p.sleeping);
  p.render_meshes = effects.flag("render_meshes", p.render_meshes);
  effects.finish();

  // Colliders after [effects]: their friction defaults to the grains'.
  std::vector<int> mesh_of_collider;
  if (const toml::array* colliders = document["colliders"].as_array())
    for (size_t c = 0; c < colliders->size(); ++c)
      mesh_of_collider.push_back(
          read_collider(*(*colliders)[c].as_table(), source, "colliders." + std::to_string(c + 1), p));

  Section emitter = section("emitter");
  if (emitter.choice("kind", "spout", {"spout", "fill"}) == "fill") {
    const long mould = emitter.integer_in("mould", 0, 1, std::max<long>(1, static_cast<long>(mesh_of_collider.size())));
    if (mould == 0 || mould > static_cast<long>(mesh_of_collider.size()))
      emitter.fail_here("kind = 'fill' needs mould, the number of a [[colliders]] (1 for the first)");
    p.fill_mould = mesh_of_collider[mould - 1];
    if (p.fill_mould < 0 || !p.mesh_colliders[p.fill_mould].hollow)
      emitter.require(false, "mould", "the number of a [[colliders]] with shape = 'mesh' and hollow = true");
    p.fill_round_seconds = emitter.number("round_s", p.fill_round_seconds, [](double v) { return v > 0.0 && v <= 1e3; },
                                          "a time in (0, 1e3] s");
  } else {
    p.spout_height = emitter.number_in("height_m", p.spout_height, 0.0, 10.0);
    p.spout_radius = emitter.number_in("radius_m", p.spout_radius, 0.0, 1.0);
    p.pour_seconds = emitter.number_in("seconds", p.pour_seconds, 0.0, 1e4);
  }
  emitter.finish();

  if (document.get("render")) {
    Section render = section("render");
    SceneRender r;
    r.width = static_cast<int>(render.integer_in("width", r.width, 16, 16384));
    r.height = static_cast<int>(render.integer_in("height", r.height, 16, 16384));
    r.samples_per_pixel = static_cast<int>(render.integer_in("samples_per_pixel", r.samples_per_pixel, 1, 1 << 20));
    r.sun_elevation_degrees = render.number_in("sun_elevation_deg", r.sun_elevation_degrees, -90.0, 90.0);
    r.sun_azimuth_degrees = render.number_in("sun_azimuth_deg", r.sun_azimuth_degrees, -360.0, 360.0);
    r.sun_irradiance = render.number_in("sun_irradiance", r.sun_irradiance, 0.0, 1e3);
    r.sky_radiance = render.number_in("sky_radiance", r.sky_radiance, 0.0, 1e3);
    r.ground = render.flag("ground", r.ground);
    r.every_frame = render.flag("every_frame", r.every_frame);
    if (render.has("eye_m") || render.has("look_at_m")) {
      r.eye = render.vector3("eye_m", xpbd::Vec3::Zero(), 1e3);
      r.look_at = render.vector3("look_at_m", xpbd::Vec3::Zero(), 1e3);
      if (!render.has("eye_m") || !render.has("look_at_m")) render.fail_here("give both eye_m and look_at_m, or neither");
      render.require(*r.eye != *r.look_at, "look_at_m", "a point other than eye_m");
    }
    r.vertical_fov_degrees = render.number("fov_deg", r.vertical_fov_degrees, [](double v) { return v > 0.0 && v < 180.0; },
                                           "a number in (0, 180)");
    if (p.body != xpbd::BodyKind::kRigid) render.fail_here("is for rigid grains: a soft pour cannot be rendered yet");
    render.finish();
    scene.render = r;
  }

  return scene;
}

std::string read_scene_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path.string() + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

SceneDescription read_scene_file(const std::filesystem::path& path, const std::vector<std::string>& overrides) {
  return parse_scene(read_scene_text(path), path.string(), overrides);
}

}  // namespace rice::experiments
