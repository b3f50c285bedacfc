// Soaking-table CSV reader (see absorption_table.hpp).
#include "grains/absorption_table.hpp"

#include <charconv>
#include <fstream>
#include <istream>
#include <stdexcept>

#ifndef RICE_GRAINS_DATA_DIR
#error "RICE_GRAINS_DATA_DIR must name grains/data (set by grains/CMakeLists.txt)"
#endif

namespace rice::grains {
namespace {

constexpr const char* kHeader = "temperature_c,soak_minutes,absorption_percent";

// One CSV cell as a number for which `in_range` holds; `range` says what that is.
template <class InRange>
double number_cell(std::string_view text, const char* column, InRange in_range, const char* range,
                   const std::string& where) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size())
    throw std::runtime_error(where + ": " + column + " '" + std::string(text) + "' is not a number");
  if (!in_range(value))
    throw std::runtime_error(where + ": " + column + " " + std::string(text) + " " + range);
  return value;
}

}  // namespace

std::vector<AbsorptionSample> read_absorption_table(std::istream& in, const std::string& name) {
  std::vector<AbsorptionSample> samples;
  std::string line;
  bool header = false;
  for (long number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    const std::string where = name + ":" + std::to_string(number);
    if (!header) {
      if (line != kHeader) throw std::runtime_error(where + ": expected header " + kHeader);
      header = true;
      continue;
    }
    const size_t first = line.find(','), second = first == std::string::npos ? first : line.find(',', first + 1);
    if (second == std::string::npos || line.find(',', second + 1) != std::string::npos)
      throw std::runtime_error(where + ": expected three comma-separated numbers");
    const std::string_view row(line);
    AbsorptionSample sample;
    sample.temperature_c = number_cell(
        row.substr(0, first), "temperature_c", [](double t) { return t >= 0.0 && t <= 100.0; },
        "must be in [0, 100] (liquid water)", where);
    sample.soak_minutes = number_cell(
        row.substr(first + 1, second - first - 1), "soak_minutes", [](double t) { return t > 0.0 && t <= 1e5; },
        "must be positive and at most 1e5", where);
    sample.absorption_percent = number_cell(
        row.substr(second + 1), "absorption_percent", [](double w) { return w > 0.0 && w <= 1000.0; },
        "must be positive and at most 1000", where);
    samples.push_back(sample);
  }
  if (samples.empty()) throw std::runtime_error(name + ": no data rows");
  return samples;
}

std::vector<AbsorptionSample> read_absorption_table(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  return read_absorption_table(in, path.string());
}

std::filesystem::path default_absorption_table() {
  return std::filesystem::path(RICE_GRAINS_DATA_DIR) / "soaking_absorption.csv";
}

}  // namespace rice::grains
