// One section of a scene file read strictly (toml++): each key's type, range and default come
// from the table of scene keys (scene_keys.hpp); a value that does not fit, and at the end any
// key nobody asked for, throws a SceneError naming the file, the line, the section and the key.
#pragma once

#include <toml++/toml.h>

#include <string>
#include <vector>

#include "experiments/scene/scene_file.hpp"
#include "experiments/scene/scene_keys.hpp"
#include "xpbd/types.hpp"

namespace rice::experiments {

/// "file:line" of a place in the scene text.
std::string source_line(const std::string& source, const toml::source_region& region);

/// `text` in single quotes, for messages.
std::string in_quotes(std::string_view text);

/// The words separated by ", ", for messages.
std::string joined(const std::vector<std::string>& words);

class TomlSection {
 public:
  /// `table` may be null (the file has no such section: every key takes its default). `name`
  /// is how messages call it ("colliders.2"); `keys` the section of the key table
  /// ("colliders").
  TomlSection(const toml::table* table, std::string source, std::string name, std::string keys);
  TomlSection(const toml::table* table, std::string source, const std::string& name)
      : TomlSection(table, std::move(source), name, name) {}

  /// The key's value, or its default from the table (or `fallback` where the table's default
  /// depends on the scene; NaN for a required key that is absent, when `fallback` is not given).
  double number(const std::string& key);
  double number(const std::string& key, double fallback);
  long integer(const std::string& key);
  bool flag(const std::string& key);
  std::string text(const std::string& key);
  /// "" for an absent key without a default.
  std::string choice(const std::string& key);
  xpbd::Vec3 vector3(const std::string& key);
  xpbd::Vec3 vector3(const std::string& key, const xpbd::Vec3& fallback);

  bool has(const std::string& key) const { return table_ && table_->get(key); }
  /// The key's node, counted as known (its reader checks it); null when absent.
  const toml::node* claim(const std::string& key) { return find(key); }
  /// Throws when `ok` is false: "[section] key = value: expected `what`" (the key must be in
  /// the file).
  void require(bool ok, const std::string& key, const std::string& what) const;
  [[noreturn]] void fail(const toml::node& node, const std::string& key, const std::string& what) const;
  /// Throws "[section] what" at the section's own line.
  [[noreturn]] void fail_here(const std::string& what) const;
  /// Throws for a key in the file that nobody asked for, listing those asked.
  void finish() const;

 private:
  const toml::node* find(const std::string& key);
  const SceneKey& spec(const std::string& key) const { return scene_key(keys_, key); }
  double checked_number(const std::string& key, const toml::node& node, bool whole);

  const toml::table* table_;
  std::string source_, name_, keys_;
  std::vector<std::string> asked_;
};

}  // namespace rice::experiments
