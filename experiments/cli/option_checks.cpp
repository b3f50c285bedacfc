// Option checks; see option_checks.hpp.
#include "experiments/cli/option_checks.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

#include "experiments/io/csv_table.hpp"

namespace rice::experiments {

CLI::Validator number_in(double low, double high, Ends ends) {
  const std::string range = std::string(ends == Ends::kOpenLow ? "(" : "[") + cell(low) + ", " +
                            cell(high) + (ends == Ends::kOpenHigh ? ")" : "]");
  return CLI::Validator(
      [=](std::string& input) -> std::string {
        double value = 0.0;
        try {
          size_t used = 0;
          value = std::stod(input, &used);
          if (used != input.size()) return "'" + input + "' is not a number";
        } catch (const std::exception&) {
          return "'" + input + "' is not a number in " + range;
        }
        const bool above = ends == Ends::kOpenLow ? value > low : value >= low;
        const bool below = ends == Ends::kOpenHigh ? value < high : value <= high;
        if (!std::isfinite(value) || !above || !below) return input + " is outside " + range;
        return {};
      },
      "in " + range);
}

CLI::Validator seed_value() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        std::uint64_t value = 0;
        const auto [end, error] = std::from_chars(input.data(), input.data() + input.size(), value);
        if (error != std::errc{} || end != input.data() + input.size())
          return "'" + input + "' is not a seed (an integer in [0, 2^64 - 1])";
        return {};
      },
      "in [0, 2^64 - 1]");
}

}  // namespace rice::experiments
