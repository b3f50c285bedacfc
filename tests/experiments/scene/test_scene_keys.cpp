// The table of scene keys (experiments/scene/scene_keys.hpp): its ranges' ends, the texts its
// messages use, validate() on a scene built in code, and that the reader reads and checks
// every key the table lists, in the section it lists it (a key the reader skipped would be
// refused as unknown instead).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>

#include "experiments/scene/scene.hpp"
#include "experiments/scene/scene_file.hpp"
#include "experiments/scene/scene_keys.hpp"

namespace rice::experiments {
namespace {

TEST(SceneKeys, RangesKeepTheirEndsOpenOrClosed) {
  const SceneKey& fps = scene_key("solver", "fps");  // (0, 1000]
  EXPECT_FALSE(accepts(fps, 0.0));
  EXPECT_TRUE(accepts(fps, 1e-9));
  EXPECT_TRUE(accepts(fps, 1000.0));
  EXPECT_FALSE(accepts(fps, std::nextafter(1000.0, 2000.0)));
  EXPECT_FALSE(accepts(fps, std::nan("")));
  EXPECT_FALSE(accepts(fps, INFINITY));
  const SceneKey& poisson = scene_key("grains", "poisson");  // (-1, 0.5)
  EXPECT_FALSE(accepts(poisson, 0.5));
  EXPECT_TRUE(accepts(poisson, 0.49));
  const SceneKey& count = scene_key("grains", "count");  // whole numbers only
  EXPECT_FALSE(accepts(count, 2.5));
  EXPECT_TRUE(accepts(count, 1.0));
  EXPECT_EQ(expected(count), "an integer in [1, 100000]");
  EXPECT_EQ(expected(poisson), "a number in (-1, 0.5)");
  EXPECT_EQ(expected(scene_key("grains", "seed")), "an integer in [0, 2^63 - 1]");
  EXPECT_EQ(expected(scene_key("grains", "young_pa")), "a number in [1000, 1e9]");
  EXPECT_EQ(expected(scene_key("grains", "body")), "one of 'rigid', 'soft'");
  EXPECT_THROW(scene_key("grains", "colour"), std::logic_error);
}

TEST(SceneKeys, ValidateNamesTheSectionTheKeyAndTheRange) {
  Scene scene;
  EXPECT_NO_THROW(validate(scene));
  scene.grains.count = 0;
  try {
    validate(scene);
    ADD_FAILURE() << "a scene of no grains was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "[grains] count = 0: expected an integer in [1, 100000]");
  }
  scene.grains.count = 10;
  scene.effects.dynamic_friction = 0.6;  // above the static 0.5
  EXPECT_THROW(validate(scene), std::invalid_argument);
  scene.effects.dynamic_friction = 0.4;
  scene.emitter.kind = EmitterKind::kFill;  // with no mould
  EXPECT_THROW(validate(scene), std::invalid_argument);
}

TEST(SceneKeys, TheReferenceListsEveryKeyOnceUnderASectionOfItsOwn) {
  std::set<std::string> sections;
  for (const SceneSection& s : scene_sections()) sections.insert(s.name);
  std::set<std::pair<std::string, std::string>> seen;
  const std::string reference = scene_keys_markdown();
  for (const SceneKey& key : scene_keys()) {
    EXPECT_TRUE(sections.count(key.section)) << key.section;
    EXPECT_TRUE(seen.insert({key.section, key.name}).second) << key.section << "." << key.name << " twice";
    EXPECT_FALSE(key.meaning.empty()) << key.name;
    EXPECT_NE(reference.find("| `" + key.name + "` |"), std::string::npos) << key.name;
  }
}

/// What a [[colliders]] needs before `name` is read: the shape that has it, and its sizes.
std::string collider_before(const std::string& name) {
  if (name == "shape") return "";
  if (name == "radius_m") return "shape = \"sphere\"\n";
  if (name == "half_extents_m") return "shape = \"box\"\n";
  if (name == "half_length_m") return "shape = \"capsule\"\nradius_m = 0.01\n";
  if (name == "file") return "shape = \"mesh\"\n";
  if (name == "scale" || name == "hollow" || name == "grid_spacing_m")
    return "shape = \"mesh\"\nfile = \"meshes/shari_mould.obj\"\n";
  return "shape = \"plane\"\n";
}

/// A scene that reaches `key` of its section and gives it an inline table, a value no key takes.
std::string scene_with_bad(const SceneKey& key) {
  const std::string bad = key.name + " = { wrong = 1 }\n";
  if (key.section == "colliders") return "[[colliders]]\n" + collider_before(key.name) + bad;
  if (key.section == "keyframes") {
    const std::string entry = key.name == "time_s" ? "" : "time_s = 0.0, ";
    return "[[colliders]]\nshape = \"plane\"\nkeyframes = [ { " + entry + key.name + " = { wrong = 1 } } ]\n";
  }
  if (key.section == "emitter" && (key.name == "mould" || key.name == "round_s"))
    return "[emitter]\nkind = \"fill\"\n" + std::string(key.name == "round_s" ? "mould = 1\n" : "") + bad +
           "[[colliders]]\nshape = \"mesh\"\nfile = \"meshes/shari_mould.obj\"\nhollow = true\n";
  return "[" + key.section + "]\n" + bad;
}

TEST(SceneKeys, TheReaderReadsAndChecksEveryKeyOfTheTable) {
  const std::string source = std::string(RICE_SCENES_DIR) + "/test.toml";  // mesh files from the scenes' folder
  for (const SceneKey& key : scene_keys()) {
    const std::string text = scene_with_bad(key);
    SCOPED_TRACE(text);
    try {
      parse_scene(text, source);
      ADD_FAILURE() << key.section << "." << key.name << " = { wrong = 1 } was accepted";
    } catch (const SceneError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("] " + key.name + " = { wrong = 1 }: expected"), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace rice::experiments
