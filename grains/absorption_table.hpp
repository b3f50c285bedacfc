// The soaking table the water-content model is fitted to: water absorption W (% of dry
// weight) of rice soaked at a water temperature for a time. A CSV with the header
// temperature_c,soak_minutes,absorption_percent; lines starting with '#' are comments.
//
// The reader treats its input as untrusted (it is fuzzed, tests/fuzz/): every row has
// exactly three numbers in physical ranges, or it throws std::runtime_error whose message
// starts with the name and line and says what was wrong.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace rice::grains {

/// One measured (or estimated) point of a soaking curve.
struct AbsorptionSample {
  double temperature_c = 0.0;       ///< water temperature, liquid: [0, 100] °C
  double soak_minutes = 0.0;        ///< (0, 1e5] min
  double absorption_percent = 0.0;  ///< (0, 1000] % of the dry weight
};

std::vector<AbsorptionSample> read_absorption_table(std::istream& in, const std::string& name);
std::vector<AbsorptionSample> read_absorption_table(const std::filesystem::path& path);

/// The table shipped with the testbed (grains/data/soaking_absorption.csv).
std::filesystem::path default_absorption_table();

}  // namespace rice::grains
