// Checks of the `rice` options' values while parsing (CLI11 validators): a number must be
// finite and in its range, a seed an integer in [0, 2^64 - 1]; CLI11 names the option in the
// message. The option sweep test (tests/experiments/cli) walks every number option through them.
#pragma once

#include <CLI/CLI.hpp>

namespace rice::experiments {

/// Which ends of a range are open.
enum class Ends { kClosed, kOpenLow, kOpenHigh };

/// A number option: finite and in [low, high] (or with the ends `ends` opens).
CLI::Validator number_in(double low, double high, Ends ends = Ends::kClosed);

/// A seed: an integer in [0, 2^64 - 1] (CLI11 alone wraps -1 around).
CLI::Validator seed_value();

}  // namespace rice::experiments
