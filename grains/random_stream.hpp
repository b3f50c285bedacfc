// The one source of randomness of the grains module: a 64-bit Mersenne Twister (its output
// sequence is fixed by the C++ standard) with uniform and normal variates computed here
// rather than by std::*_distribution, whose algorithms differ between standard libraries.
// Same seed, same numbers, on every platform.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rice::grains {

class RandomStream {
 public:
  explicit RandomStream(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1), 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  /// Uniform in [low, high).
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  /// Normal variate by the Box–Muller transform.
  double normal(double mean, double standard_deviation) {
    const double u1 = 1.0 - uniform();  // in (0, 1]
    const double u2 = uniform();
    return mean + standard_deviation * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
  /// A seed for an independent child stream (one per grain, so grains can be built in
  /// parallel and in any order).
  std::uint64_t child_seed() { return engine_(); }

  /// The engine's state in the standard's text form, for checkpoints; set_state reads it back
  /// and throws std::runtime_error for text that is not one.
  std::string state() const {
    std::ostringstream out;
    out << engine_;
    return out.str();
  }
  void set_state(const std::string& text) {
    std::istringstream in(text);
    std::mt19937_64 engine;
    if (!(in >> engine)) throw std::runtime_error("not a random stream's state");
    engine_ = engine;
  }

 private:
  std::mt19937_64 engine_;
};

}  // namespace rice::grains
