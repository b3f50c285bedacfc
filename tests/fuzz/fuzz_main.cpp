// libFuzzer entry point for one fuzz target, chosen at compile time by RICE_FUZZ_TARGET
// (tests/fuzz/CMakeLists.txt builds one binary per target). A Finding or any other
// exception aborts, which libFuzzer reports with the input that caused it.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "tests/fuzz/fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const rice::fuzz::Target& target = rice::fuzz::target_named(RICE_FUZZ_TARGET);
  try {
    target.run(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const rice::fuzz::Finding& finding) {
    std::fprintf(stderr, "fuzz finding (%s): %s\n", target.name, finding.what());
    std::abort();
  }
  return 0;
}
