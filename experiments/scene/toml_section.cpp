// Reading one section of a scene file strictly; see toml_section.hpp.
#include "experiments/scene/toml_section.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>

#include "experiments/io/csv_table.hpp"

namespace rice::experiments {
namespace {

/// A value as a file would write it, for messages.
std::string shown(const toml::node& node) {
  if (const auto* text = node.as_string()) return '"' + text->get() + '"';
  if (const auto* number = node.as_floating_point()) return cell(number->get());
  std::ostringstream out;
  node.visit([&](const auto& value) { out << value; });
  return out.str();
}

double fallback_number(const SceneKey& key) {
  const double* value = std::get_if<double>(&key.fallback);
  return value ? *value : std::nan("");
}

}  // namespace

std::string source_line(const std::string& source, const toml::source_region& region) {
  return (region.path ? std::string(*region.path) : source) + ":" + std::to_string(region.begin.line);
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

TomlSection::TomlSection(const toml::table* table, std::string source, std::string name, std::string keys)
    : table_(table), source_(std::move(source)), name_(std::move(name)), keys_(std::move(keys)) {}

double TomlSection::checked_number(const std::string& key, const toml::node& node, bool whole) {
  const SceneKey& k = spec(key);
  std::optional<double> value;
  if (whole && node.is_integer()) value = static_cast<double>(*node.value<std::int64_t>());  // seeds past 2^53 too
  if (!whole && node.is_number()) value = node.value<double>();
  if (!value || !accepts(k, *value)) fail(node, key, expected(k));
  return *value;
}

double TomlSection::number(const std::string& key) { return number(key, fallback_number(spec(key))); }

double TomlSection::number(const std::string& key, double fallback) {
  const toml::node* node = find(key);
  return node ? checked_number(key, *node, false) : fallback;
}

long TomlSection::integer(const std::string& key) {
  const toml::node* node = find(key);
  if (!node) return static_cast<long>(fallback_number(spec(key)));
  checked_number(key, *node, true);
  return static_cast<long>(*node->value<std::int64_t>());  // exact, where the double may not be
}

bool TomlSection::flag(const std::string& key) {
  const toml::node* node = find(key);
  if (!node) return std::get<bool>(spec(key).fallback);
  if (!node->is_boolean()) fail(*node, key, expected(spec(key)));
  return *node->value<bool>();
}

std::string TomlSection::text(const std::string& key) {
  const toml::node* node = find(key);
  if (!node) {
    const std::string* fallback = std::get_if<std::string>(&spec(key).fallback);
    return fallback ? *fallback : std::string();
  }
  if (!node->is_string()) fail(*node, key, expected(spec(key)));
  return *node->value<std::string>();
}

std::string TomlSection::choice(const std::string& key) {
  const SceneKey& k = spec(key);
  const toml::node* node = find(key);
  if (!node) {
    const std::string* fallback = std::get_if<std::string>(&k.fallback);
    return fallback ? *fallback : std::string();
  }
  if (!node->is_string() || std::find(k.choices.begin(), k.choices.end(), *node->value<std::string>()) == k.choices.end())
    fail(*node, key, expected(k));
  return *node->value<std::string>();
}

xpbd::Vec3 TomlSection::vector3(const std::string& key) {
  const auto* fallback = std::get_if<std::array<double, 3>>(&spec(key).fallback);
  return vector3(key, fallback ? xpbd::Vec3((*fallback)[0], (*fallback)[1], (*fallback)[2]) : xpbd::Vec3::Zero());
}

xpbd::Vec3 TomlSection::vector3(const std::string& key, const xpbd::Vec3& fallback) {
  const SceneKey& k = spec(key);
  const toml::node* node = find(key);
  if (!node) return fallback;
  const toml::array* array = node->as_array();
  xpbd::Vec3 v = xpbd::Vec3::Zero();
  bool ok = array && array->size() == 3;
  for (size_t i = 0; ok && i < 3; ++i) {
    const std::optional<double> x = (*array)[i].is_number() ? (*array)[i].value<double>() : std::nullopt;
    ok = x && std::isfinite(*x) && std::abs(*x) <= k.range.high;
    if (ok) v[static_cast<Eigen::Index>(i)] = *x;
  }
  if (!ok) fail(*node, key, expected(k));
  return v;
}

void TomlSection::require(bool ok, const std::string& key, const std::string& what) const {
  if (!ok) fail(*table_->get(key), key, what);
}

void TomlSection::fail(const toml::node& node, const std::string& key, const std::string& what) const {
  throw SceneError(source_line(source_, node.source()) + ": [" + name_ + "] " + key + " = " + shown(node) +
                   ": expected " + what);
}

void TomlSection::fail_here(const std::string& what) const {
  throw SceneError(source_line(source_, table_ ? table_->source() : toml::source_region{}) + ": [" + name_ + "] " +
                   what);
}

void TomlSection::finish() const {
  if (!table_) return;
  for (auto&& [key, node] : *table_)
    if (std::find(asked_.begin(), asked_.end(), key.str()) == asked_.end())
      throw SceneError(source_line(source_, key.source()) + ": [" + name_ + "] has no key " + in_quotes(key.str()) +
                       "; its keys: " + joined(asked_));
}

const toml::node* TomlSection::find(const std::string& key) {
  spec(key);  // every key read is in the table (std::logic_error otherwise)
  asked_.push_back(key);
  return table_ ? table_->get(key) : nullptr;
}

}  // namespace rice::experiments
