// The scene-file keys; see scene_keys.hpp.
#include "experiments/scene/scene_keys.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "experiments/io/csv_table.hpp"
#include "experiments/render/collider_drawing.hpp"
#include "experiments/scene/scene.hpp"
#include "grains/cultivar.hpp"
#include "xpbd/model.hpp"

namespace rice::experiments {
namespace {

constexpr double kLargestSeed = static_cast<double>(INT64_MAX);

KeyRange closed(double low, double high) { return {low, high}; }
KeyRange open_low(double low, double high) { return {low, high, true, false}; }
KeyRange open(double low, double high) { return {low, high, true, true}; }

SceneKey number(std::string section, std::string name, KeyRange range, KeyDefault fallback, std::string meaning,
                std::string note = "") {
  return {std::move(section), std::move(name), KeyType::kNumber, range, {}, std::move(fallback), std::move(note),
          std::move(meaning)};
}

SceneKey integer(std::string section, std::string name, KeyRange range, KeyDefault fallback, std::string meaning,
                 std::string note = "") {
  SceneKey key = number(std::move(section), std::move(name), range, std::move(fallback), std::move(meaning),
                        std::move(note));
  key.type = KeyType::kInteger;
  return key;
}

SceneKey flag(std::string section, std::string name, bool fallback, std::string meaning) {
  return {std::move(section), std::move(name), KeyType::kFlag, {}, {}, fallback, "", std::move(meaning)};
}

SceneKey text(std::string section, std::string name, KeyDefault fallback, std::string meaning, std::string note = "") {
  return {std::move(section), std::move(name), KeyType::kText, {}, {}, std::move(fallback), std::move(note),
          std::move(meaning)};
}

SceneKey choice(std::string section, std::string name, std::vector<std::string> choices, KeyDefault fallback,
                std::string meaning, std::string note = "") {
  return {std::move(section), std::move(name), KeyType::kChoice, {}, std::move(choices), std::move(fallback),
          std::move(note), std::move(meaning)};
}

SceneKey vector3(std::string section, std::string name, double bound, KeyDefault fallback, std::string meaning,
                 std::string note = "") {
  return {std::move(section), std::move(name), KeyType::kVector3, closed(-bound, bound), {}, std::move(fallback),
          std::move(note), std::move(meaning)};
}

std::vector<SceneKey> scene_and_grain_keys() {
  return {
      text("scene", "name", {}, "the scene's name, in messages and tables", "the file's stem"),
      text("scene", "description", std::string(), "one line saying what the scene shows"),
      choice("grains", "cultivar", grains::cultivar_names(), std::string("japonica"),
             "the cultivar's shape, size and stickiness (grains/cultivar.hpp)"),
      integer("grains", "count", closed(1, 100000), 800.0, "grains in the scene"),
      integer("grains", "variants", closed(1, 1000), 8.0,
              "distinct generated grains; each grain is an instance of one, with its own swell P and rotation"),
      integer("grains", "seed", closed(0, kLargestSeed), 1.0, "every random choice of the scene flows from it"),
      choice("grains", "body", {"rigid", "soft"}, std::string("rigid"),
             "rigid bodies, or soft tet meshes"),
      choice("grains", "elasticity", {"neo-hookean", "corotated"}, std::string("neo-hookean"),
             "soft grains' tet material: the paper's stable Neo-Hookean pair, or the corotated pair, the same at "
             "small strain and stable under XPBD at a third of the substeps (docs/known-limits.md)"),
      number("grains", "young_pa", closed(1e3, 1e9), 1e5, "soft grains' Young's modulus [Pa]"),
      integer("grains", "min_vertices", closed(4, 1000), 20.0,
              "the fewest vertices of a grain's simulation mesh (Mesh_3, grains/simulation_mesh.hpp): soft grains' tets; "
              "rigid grains' collision spheres fit its surface"),
      integer("grains", "max_vertices", closed(4, 1000), 60.0,
              "the most vertices of a grain's simulation mesh; a coarser mesh takes larger XPBD steps"),
      number("grains", "vertex_mass_floor", closed(0, 0.9), 0.5,
             "soft grains' lightest vertex mass, a fraction of their mean, keeping each grain's mass and centre of "
             "mass: a coarse mesh's light tip is what one XPBD sweep turns inside out (0: the lumped masses)"),
      number("grains", "poisson", open(-1, 0.5), 0.3, "soft grains' Poisson's ratio"),
      number("grains", "soak_minutes", open_low(0, 1e5), 120.0,
             "soaking time [min]: with the temperature it sets the water content, hence the damping (eq. 4) and "
             "the cohesion"),
      number("grains", "soak_temperature_c", closed(0, 100), 10.0, "soaking water's temperature [°C]"),
      number("grains", "stickiness", closed(0, 1000), {},
             "pull-off force of two touching grains at the reference soak, in grain weights", "the cultivar's"),
      number("grains", "heal_s", closed(0, 1e4), {},
             "two grains whose bond broke stick again once they have touched this long [s]", "never while touching"),
  };
}

std::vector<SceneKey> solver_container_emitter_keys() {
  return {
      number("solver", "fps", open_low(0, 1000), 30.0, "frames per second"),
      integer("solver", "frames", closed(1, 100000), 180.0, "frames simulated"),
      integer("solver", "substeps", closed(0, 10000), 0.0, "substeps per frame; 0: 80 for rigid grains, 160 for soft corotated ones, 480 for soft Neo-Hookean ones"),
      integer("solver", "iterations", closed(1, 1000), 1.0, "Gauss–Seidel sweeps per substep"),
      number("solver", "radius_interval_s", closed(0, 0.1), xpbd::ContactSettings{}.radius_interval,
             "soft grains: the longest time their collision spheres' radii (from each tet's smallest stretch) hold "
             "between updates [s]; 0: every substep"),
      integer("solver", "checkpoint_every", closed(0, 100000), 0.0,
              "a checkpoint every this many frames, for rice run --resume (also on Ctrl-C and SIGTERM)",
              "every 30 s of wall time"),
      choice("solver", "vbd_damping", {"strain-rate", "constraint"}, std::string("strain-rate"),
             "vbd: the soak's damping time (eq. 4) as the convex strain-rate damping, or as the paper's Rayleigh "
             "damping of the constraints (XPBD always takes the paper's)"),
      choice("solver", "method", {"xpbd", "vbd"}, std::string("xpbd"),
             "soft grains by XPBD or by vertex block descent (vbd: soft grains only)"),
      choice("container", "kind", {"chawan", "plate"}, std::string("chawan"),
             "a chawan (rice bowl, a distance-grid collider) or a plate (the ground plane)"),
      number("container", "grid_spacing_m", closed(2e-4, 1e-2), 1e-3, "the chawan's distance grid [m]"),
      number("container", "scale", closed(0.1, 10), 1.0, "the chawan's sizes times this (1: 12 cm across)"),
      choice("emitter", "kind", {"spout", "clump", "fill"}, std::string("spout"),
             "spout: a stream of layers over `seconds`; clump: every layer at once, stacked; fill: grains dropped "
             "into a hollow mesh collider in rounds"),
      number("emitter", "height_m", closed(0, 10), 0.02, "spout and clump: the opening above the chawan's rim or the plate [m]"),
      number("emitter", "radius_m", closed(0, 1), 0.0,
             "spout and clump: the opening's radius [m]; 0: the container's (a plate: 1.1 grain lengths; a chawan: 0.6 "
             "of its inner radius less a grain length)"),
      number("emitter", "seconds", open_low(0, 1e4), 1.5,
             "spout: the time over which its layers leave [s] (all at once: kind = 'clump'); fill: the time its "
             "rounds go on"),
      integer("emitter", "mould", closed(1, 1000), {},
              "fill: the number of the [[colliders]] to fill (1 for the first), a mesh with hollow = true",
              "required"),
      number("emitter", "round_s", open_low(0, 1e3), 0.05,
             "fill: the time between rounds [s]; each round drops grains, randomly turned, at the free points of a "
             "lattice 1.1 grain lengths apart, shifted at random each round, lowest first"),
  };
}

std::vector<SceneKey> effect_and_render_keys() {
  return {
      flag("effects", "friction", true, "Coulomb friction between grains and with the colliders; false: both coefficients 0"),
      number("effects", "static_friction", closed(0, 10), 0.5, "μs, grains and colliders"),
      number("effects", "dynamic_friction", closed(0, 10), 0.4, "μk, at most static_friction"),
      flag("effects", "cohesion", true, "water-content bonds between touching grains"),
      flag("effects", "damping", true, "soft grains' Rayleigh damping from the soak (eq. 4); false: none"),
      flag("effects", "sleeping", true, "grains at rest sleep until something touches them"),
      number("effects", "sleep_speed_m_s", open_low(0, 1), SceneEffects{}.sleep_speed,
             "a grain is at rest in a frame when every point of it moved slower than this [m/s]"),
      integer("effects", "sleep_frames", closed(1, 10000), static_cast<double>(SceneEffects{}.sleep_frames),
              "frames at rest in a row before a grain sleeps"),
      flag("effects", "render_meshes", false, "also write each frame's deformed render meshes (frames/*.ply, large)"),
      flag("effects", "paraview", false,
           "also write each frame's grains as points for ParaView (paraview/*.vtp, grains.pvd): velocity, awake, bonds"),
      integer("render", "width", closed(16, 16384), 640.0, "image width [pixels]"),
      integer("render", "height", closed(16, 16384), 480.0, "image height [pixels]"),
      integer("render", "samples_per_pixel", closed(1, 1 << 20), 16.0, "samples per pixel"),
      choice("render", "integrator", {"cdrf", "translucent", "path"}, std::string("cdrf"),
             "cdrf: the paper's shading; translucent: with the light through the grain; path: the reference path "
             "tracer (docs/rendering.md measures each against it)"),
      integer("render", "bounces", closed(0, 64), 0.0,
              "cdrf, translucent: bounces of light between grains and surfaces (0: direct light)"),
      choice("render", "lighting", {"studio", "sun"}, std::string("studio"),
             "studio: a soft key light and a fill (warm white), a table and a backdrop; sun: the sun and the sky over "
             "a grey ground"),
      number("render", "key_irradiance", closed(0, 1e3), 3.0, "studio: the key light's irradiance at the grains"),
      number("render", "fill_ratio", closed(0, 10), 0.25, "studio: the fill's irradiance over the key's"),
      number("render", "sun_elevation_deg", closed(-90, 90), 50.0, "the sun's elevation [°]"),
      number("render", "sun_azimuth_deg", closed(-360, 360), -30.0, "the sun's azimuth [°], from +x towards +y"),
      number("render", "sun_irradiance", closed(0, 1e3), 3.0, "the sun's irradiance at normal incidence; 0: no sun"),
      number("render", "sky_radiance", closed(0, 1e3), 0.3, "the uniform sky's radiance"),
      flag("render", "ground", true, "the studio's table and backdrop, or the sun's grey plane under the grains"),
      flag("render", "every_frame", false, "also render every frame into render_frames/, with the last frame's camera"),
      flag("render", "video", false, "also render every frame, render_frames/render.mp4 (H.264, by ffmpeg) and contact_sheet.png"),
      vector3("render", "eye_m", 1e3, {}, "the camera's position [m] (give look_at_m too)", "framed on the grains"),
      vector3("render", "look_at_m", 1e3, {}, "the point the camera looks at [m] (give eye_m too)", "framed on the grains"),
      number("render", "fov_deg", open(0, 180), 30.0, "the vertical field of view [°]"),
  };
}

/// A pose: where a collider is (one pose) or where it passes at a keyframe's time.
std::vector<SceneKey> pose_keys(const std::string& section) {
  return {
      vector3(section, "position_m", 1e3, std::array<double, 3>{0, 0, 0}, "the collider frame's origin [m]"),
      vector3(section, "axis", 1e3, std::array<double, 3>{0, 0, 1}, "the axis of its rotation"),
      number(section, "angle_deg", closed(-360, 360), 0.0, "the rotation's angle about `axis` [°]"),
  };
}

std::vector<SceneKey> collider_keys() {
  std::vector<SceneKey> keys{
      choice("colliders", "shape", {"plane", "sphere", "box", "capsule", "mesh"}, {},
             "plane (the solid below its local z = 0), sphere, box, capsule (along its local z) or a closed mesh",
             "required"),
      number("colliders", "radius_m", open_low(0, 10), {}, "sphere and capsule: the radius [m]", "required"),
      vector3("colliders", "half_extents_m", 10, {}, "box: half its sizes [m], each > 0", "required"),
      number("colliders", "half_length_m", open_low(0, 10), {}, "capsule: half its axis's length [m]", "required"),
      {"colliders", "file", KeyType::kFile, {}, {}, {}, "required",
       "mesh: a closed .obj, .off or .ply file, its path from the scene file's folder"},
      number("colliders", "scale", open_low(0, 1e3), 1.0, "mesh: its coordinates times this"),
      flag("colliders", "hollow", false, "mesh: the room inside it, the solid outside (a mould)"),
      number("colliders", "grid_spacing_m", closed(2e-4, 1e-2), 1e-3, "mesh: its distance grid's spacing [m]"),
      choice("colliders", "material", collider_material_names(), std::string("plastic"),
             "how renders draw it: white plastic, pale wood, brushed steel or glazed white ceramic"),
      number("colliders", "removed_at_s", open_low(0, 1e4), {}, "the time it is taken away [s] (a mould lifted off)",
             "never"),
      number("colliders", "static_friction", closed(0, 10), {}, "μs against the grains", "the grains'"),
      number("colliders", "dynamic_friction", closed(0, 10), {}, "μk against the grains, at most static_friction",
             "the grains'"),
      number("colliders", "force_limit_n", open_low(0, 1e6), {},
             "the most it pushes with along −yield_axis [N]; pushed back harder, it gives way as a hand does",
             "none: it follows its keyframes whatever the force"),
      vector3("colliders", "yield_axis", 1e3, std::array<double, 3>{0.0, 0.0, 1.0},
              "with force_limit_n: the way it gives (world; made unit length)"),
      number("colliders", "yield_speed_m_s", open_low(0, 100), 0.01,
             "with force_limit_n: how fast it gives at twice its limit and returns with no load [m/s]"),
  };
  for (SceneKey& key : pose_keys("colliders")) keys.push_back(std::move(key));
  keys.push_back({"colliders", "keyframes", KeyType::kKeyframes, {}, {}, {}, "one pose (position_m, axis, angle_deg)",
                  "poses at increasing times instead of one pose: a hand that presses and withdraws"});
  keys.push_back(number("keyframes", "time_s", closed(0, 1e4), {}, "the keyframe's time [s], after the previous one's",
                        "0 for the first; required after"));
  for (SceneKey& key : pose_keys("keyframes")) keys.push_back(std::move(key));
  keys.push_back(number("keyframes", "size", open_low(0, 10), 1.0,
                        "the collider's size then, times its own, about its frame's origin: a mould that closes"));
  return keys;
}

std::string type_name(const SceneKey& key) {
  switch (key.type) {
    case KeyType::kNumber: return "number";
    case KeyType::kInteger: return "integer";
    case KeyType::kFlag: return "true or false";
    case KeyType::kText: return "text";
    case KeyType::kChoice: return "choice";
    case KeyType::kVector3: return "[x, y, z]";
    case KeyType::kFile: return "file name";
    case KeyType::kKeyframes: return "list of tables";
  }
  return "?";
}

/// The shortest text of `value` with a plain exponent: "1e9", "2e-4", "0.3".
std::string readable_number(double value) {
  std::string text = cell(value);
  const size_t e = text.find('e');
  if (e == std::string::npos) return text;
  size_t digits = e + 1;
  if (text[digits] == '+') text.erase(digits, 1);
  if (text[digits] == '-') ++digits;
  while (text[digits] == '0' && digits + 1 < text.size()) text.erase(digits, 1);
  return text;
}

/// A range's end as people write it: integers whole ("100000"; the largest seed, 2^63 - 1, is
/// no double), numbers as readable_number writes them.
std::string end_text(const SceneKey& key, double value) {
  if (key.type == KeyType::kInteger)
    return value >= kLargestSeed ? "2^63 - 1" : std::to_string(static_cast<long long>(value));
  return readable_number(value);
}

std::string range_text(const SceneKey& key) {
  const KeyRange& r = key.range;
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
  std::string text = r.open_low ? "(" : "[";
  for (const std::string& piece : {end_text(key, r.low), std::string(", "), end_text(key, r.high)}) text += piece;
  return text + (r.open_high ? ")" : "]");
}

std::string default_text(const SceneKey& key) {
  if (!key.default_note.empty()) return key.default_note;
  struct Shown {
    std::string operator()(std::monostate) const { return "none"; }
    std::string operator()(double v) const { return readable_number(v); }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(const std::string& v) const { return "\"" + v + "\""; }
    std::string operator()(const std::array<double, 3>& v) const {
      std::string text = "[";  // appended: see range_text
      for (size_t i = 0; i < 3; ++i) (text += i ? ", " : "") += readable_number(v[i]);
      return text + "]";
    }
  };
  return std::visit(Shown{}, key.fallback);
}

std::string quoted_choices(const SceneKey& key, const std::string& quote) {
  std::string out;
  for (const std::string& c : key.choices) out += (out.empty() ? "" : ", ") + quote + c + quote;
  return out;
}

}  // namespace

const std::vector<SceneSection>& scene_sections() {
  static const std::vector<SceneSection> sections{
      {"scene", "[scene]", "What the scene is called and shows"},
      {"grains", "[grains]", "What the grains are: cultivar, number, body and water content"},
      {"solver", "[solver]", "How time advances"},
      {"container", "[container]", "What holds the grains"},
      {"emitter", "[emitter]", "How the grains enter the scene"},
      {"effects", "[effects]", "What is simulated; what is off costs nothing"},
      {"render", "[render]",
       "The last frame rendered after the simulation with the CDRF at the grains' water content (rigid grains); no "
       "section, no render"},
      {"colliders", "[[colliders]]", "Any number of colliders beside the container, each with its pose or keyframes"},
      {"keyframes", "keyframes = [{ ... }, ...] of a [[colliders]]", "One pose of a moving collider"},
  };
  return sections;
}

const std::vector<SceneKey>& scene_keys() {
  static const std::vector<SceneKey> keys = [] {
    std::vector<SceneKey> all;
    for (auto part : {scene_and_grain_keys(), solver_container_emitter_keys(), effect_and_render_keys(), collider_keys()})
      for (SceneKey& key : part) all.push_back(std::move(key));
    return all;
  }();
  return keys;
}

const SceneKey& scene_key(std::string_view section, std::string_view name) {
  const auto& keys = scene_keys();
  const auto it = std::find_if(keys.begin(), keys.end(),
                               [&](const SceneKey& k) { return k.section == section && k.name == name; });
  if (it == keys.end())
    throw std::logic_error("scene keys: no key '" + std::string(name) + "' in [" + std::string(section) + "]");
  return *it;
}

bool accepts(const SceneKey& key, double value) {
  const KeyRange& r = key.range;
  if (!std::isfinite(value)) return false;
  if (key.type == KeyType::kInteger && value != std::floor(value)) return false;
  return (r.open_low ? value > r.low : value >= r.low) && (r.open_high ? value < r.high : value <= r.high);
}

std::string expected(const SceneKey& key) {
  switch (key.type) {
    case KeyType::kNumber: return "a number in " + range_text(key);
    case KeyType::kInteger: return "an integer in " + range_text(key);
    case KeyType::kFlag: return "true or false";
    case KeyType::kText: return "a text in quotes";
    case KeyType::kChoice: return "one of " + quoted_choices(key, "'");
    case KeyType::kVector3: return "three numbers [x, y, z] within ±" + readable_number(key.range.high);
    case KeyType::kFile: return "a file name in quotes";
    case KeyType::kKeyframes: return "a list of { time_s = ..., position_m = [...] }";
  }
  return "?";
}

void check(const SceneKey& key, double value) {
  if (!accepts(key, value))
    throw std::invalid_argument("[" + key.section + "] " + key.name + " = " + cell(value) + ": expected " +
                                expected(key));
}

std::string scene_keys_markdown() {
  std::string out =
      "# Scene-file keys\n\n"
      "Every key a scene file (`experiments/scenes/*.toml`, run by `rice run SCENE.toml --out DIR`) may hold. "
      "This page is printed by `rice scene-keys` from the reader's own table "
      "(`experiments/scene/scene_keys.cpp`), and a test fails when it differs; regenerate it with "
      "`build/experiments/rice scene-keys > docs/scene-keys.md`. Every key is optional unless its default says "
      "\"required\"; a key that is not listed, a value of the wrong type or out of range stops the run before any "
      "work, naming the file, line and key. `--set section.key=value` overrides a key, and "
      "`--set colliders.N.key=value` one of the N-th [[colliders]] (from 1).\n";
  for (const SceneSection& section : scene_sections()) {
    out += "\n## " + section.heading + "\n\n" + section.meaning + ".\n\n";
    out += "| key | type | default | range | meaning |\n|---|---|---|---|---|\n";
    for (const SceneKey& key : scene_keys()) {
      if (key.section != section.name) continue;
      const bool ranged = key.type == KeyType::kNumber || key.type == KeyType::kInteger;
      const std::string range = ranged                           ? range_text(key)
                                : key.type == KeyType::kChoice   ? quoted_choices(key, "`")
                                : key.type == KeyType::kVector3 ? "each within ±" + readable_number(key.range.high)
                                                                 : "";
      out += "| `" + key.name + "` | " + type_name(key) + " | " + default_text(key) + " | " + range + " | " +
             key.meaning + " |\n";
    }
  }
  return out;
}

}  // namespace rice::experiments
