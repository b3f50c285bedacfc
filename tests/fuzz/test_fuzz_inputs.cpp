// Replays every fuzz input the repository keeps through its target (fuzz_targets.hpp): the
// seed corpus (corpus/<target>/, valid files) and every input a fuzzer once failed on, kept
// after its fix (regressions/<target>/). Part of the ordinary suite, so the sanitizer build
// replays them too.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <typeinfo>
#include <vector>

#include "tests/fuzz/fuzz_targets.hpp"

#ifndef RICE_FUZZ_DIR
#error "RICE_FUZZ_DIR must name tests/fuzz (set by tests/CMakeLists.txt)"
#endif

namespace rice::fuzz {
namespace {

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs every file of `folder` through `target`; returns how many there were.
int replay(const Target& target, const std::filesystem::path& folder) {
  if (!std::filesystem::is_directory(folder)) return 0;
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (!entry.is_regular_file() || entry.path().filename().string().starts_with(".")) continue;
    ++count;
    try {
      target.run(read_bytes(entry.path()));
    } catch (const std::exception& e) {
      ADD_FAILURE() << entry.path() << ": " << typeid(e).name() << ": " << e.what();
    }
  }
  return count;
}

class FuzzInputs : public testing::TestWithParam<std::string> {};

TEST_P(FuzzInputs, SeedCorpusAndPastFindingsKeepTheReadersPromises) {
  const Target& target = target_named(GetParam());
  const std::filesystem::path folder = RICE_FUZZ_DIR;
  EXPECT_GT(replay(target, folder / "corpus" / target.name), 0) << "no seed corpus for " << target.name;
  replay(target, folder / "regressions" / target.name);
}

// Every target in the one list (fuzz_targets.cpp), so that a new target is replayed too.
std::vector<std::string> target_names() {
  std::vector<std::string> names;
  for (const Target& target : targets()) names.emplace_back(target.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzInputs, testing::ValuesIn(target_names()),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace rice::fuzz
