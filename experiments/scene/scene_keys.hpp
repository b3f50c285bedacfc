// The one table of every key a scene file may hold: its section, type, default, range and
// meaning. The reader (scene_file.hpp) takes each key's range and default from it, validate()
// (scene.hpp) its ranges, and `rice scene-keys` prints it as the scene-file reference
// (docs/scene-keys.md, checked by a test), so the three cannot drift apart.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace rice::experiments {

enum class KeyType {
  kNumber,     ///< a finite number in its range
  kInteger,    ///< an integer in its range
  kFlag,       ///< true or false
  kText,       ///< a text in quotes
  kChoice,     ///< one of `choices`
  kVector3,    ///< [x, y, z], each within ±range.high
  kFile,       ///< a file name, from the scene file's folder
  kKeyframes,  ///< a list of { time_s, position_m, axis, angle_deg } tables
};

/// [low, high], either end open.
struct KeyRange {
  double low = 0.0, high = 0.0;
  bool open_low = false, open_high = false;
};

/// A key's value when the file leaves it out: none (std::monostate: required, or said by
/// `default_note`), a number (numbers and integers), a flag, a text (texts and choices) or
/// three numbers.
using KeyDefault = std::variant<std::monostate, double, bool, std::string, std::array<double, 3>>;

struct SceneKey {
  std::string section;  ///< "grains"; "colliders" for [[colliders]]; "keyframes" for a collider's
  std::string name;
  KeyType type = KeyType::kNumber;
  KeyRange range;                    ///< numbers, integers; vectors: each within ±high
  std::vector<std::string> choices;  ///< kChoice
  KeyDefault fallback;
  std::string default_note;  ///< shown instead of the fallback where it depends on the scene
  std::string meaning;
};

struct SceneSection {
  std::string name;     ///< as the file spells it: "grains", "colliders", "keyframes"
  std::string heading;  ///< "[grains]", "[[colliders]]", "keyframes = [...] of a [[colliders]]"
  std::string meaning;
};

/// Every section, in the order the reference lists them.
const std::vector<SceneSection>& scene_sections();

/// Every key, section by section.
const std::vector<SceneKey>& scene_keys();

/// The key `name` of `section`; throws std::logic_error for a key not in the table.
const SceneKey& scene_key(std::string_view section, std::string_view name);

/// Whether `value` lies in the key's range (numbers and integers; integers must be whole).
bool accepts(const SceneKey& key, double value);

/// What the key takes, for messages: "a number in (0, 1000]", "one of 'rigid', 'soft'".
std::string expected(const SceneKey& key);

/// Throws std::invalid_argument "[section] name = value: expected ..." when the key does not
/// accept `value`.
void check(const SceneKey& key, double value);

/// The scene-file reference: every section and key as Markdown tables.
std::string scene_keys_markdown();

}  // namespace rice::experiments
