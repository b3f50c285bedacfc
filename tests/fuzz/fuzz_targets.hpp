// What the fuzzers check: one entry per reader of outside input. Each entry reads the bytes
// as its format and holds the reader to its promises (grains/mesh_io.hpp,
// grains/absorption_table.hpp, experiments/scene/scene_file.hpp): bad input ends in a std::runtime_error whose message starts
// with the input's name; good input gives finite coordinates, indices in range, a size
// bounded by the input's, and a write–read round trip that changes no bit. A broken promise
// throws Finding; any other exception (std::bad_alloc, std::out_of_range, ...) escapes as it
// is. The libFuzzer binaries (fuzz_main.cpp) abort on both; the ordinary test suite
// (test_fuzz_inputs.cpp) replays the seed corpus and every input a fuzzer ever failed on.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace rice::fuzz {

/// An input that breaks a reader's promise.
class Finding : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

struct Target {
  const char* name;  ///< also the folder of its corpus and regressions
  void (*run)(std::string_view bytes);
};

/// Every fuzz target: obj, off, ply, medit (reader and writer round trip), absorption, scene
/// (experiments/scene/scene_file.hpp: values within the documented ranges, the same twice),
/// checkpoint (experiments/scene/checkpoint_file.hpp and the state reader).
const std::vector<Target>& targets();

/// The target called `name`; throws std::invalid_argument for an unknown name.
const Target& target_named(std::string_view name);

}  // namespace rice::fuzz
