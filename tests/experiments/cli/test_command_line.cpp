// Every number option of every `rice` subcommand, swept with NaN, infinities, negative, zero
// and huge values. Each value is either refused before any work (while parsing, or by the
// command's validation, which writes nothing) with a message naming the option, or accepted
// by both. NaN, infinities and 1e300 are always refused, and so is 2^31 - 1 for an integer
// option, but for --seed, where every 64-bit value is a seed.
#include <CLI/CLI.hpp>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "experiments/cli/command_line.hpp"

namespace rice::experiments {
namespace {

// Subcommand paths that run something ("study convergence", "grains", ...).
void collect_commands(CLI::App* app, std::vector<std::string> path, std::vector<std::vector<std::string>>& out) {
  const std::vector<CLI::App*> children = app->get_subcommands({});
  if (children.empty() && !path.empty()) out.push_back(path);
  for (CLI::App* child : children) {
    std::vector<std::string> longer = path;
    longer.push_back(child->get_name());
    collect_commands(child, longer, out);
  }
}

CLI::App* find_command(CLI::App* app, const std::vector<std::string>& path) {
  for (const std::string& name : path) app = app->get_subcommand(name);
  return app;
}

bool takes_a_number(const CLI::Option* option) {
  const std::string type = option->get_type_name();  // "INT", "FLOAT:in [0, 1]", ...
  return option->get_type_size() != 0 &&
         (type.starts_with("INT") || type.starts_with("UINT") || type.starts_with("FLOAT"));
}

struct Outcome {
  bool accepted = false;
  std::string message;  // when refused
};

// Parses `rice words...` and validates, as `rice` does before any work.
Outcome parse_and_validate(std::vector<std::string> words) {
  words.insert(words.begin(), "rice");
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  CommandLine command_line;
  try {
    command_line.app().parse(static_cast<int>(argv.size()), argv.data());
    command_line.validate();
  } catch (const std::exception& e) {
    return {false, e.what()};
  }
  return {true, {}};
}

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// What a command needs besides the option swept, so that only that option can be refused.
std::vector<std::string> required_arguments(const std::vector<std::string>& path) {
  if (path == std::vector<std::string>{"render"}) return {"--meshes", RICE_TEST_MESH};
  if (path == std::vector<std::string>{"merge-crops"}) return {RICE_TEST_SCRATCH};
  if (path == std::vector<std::string>{"study", "soft-curvature"} || path == std::vector<std::string>{"study", "soft-instances"} ||
      path == std::vector<std::string>{"study", "frame-cost"} || path == std::vector<std::string>{"point-cache"})
    return {"--run", RICE_TEST_SCRATCH};
  if (path == std::vector<std::string>{"study", "scale"}) return {"--scene", RICE_SCENES_DIR "/drop.toml"};
  if (path == std::vector<std::string>{"study", "sleep"}) return {"--scene", RICE_SCENES_DIR "/rice_cooker.toml"};
  if (path == std::vector<std::string>{"study", "hard-cases"}) return {"--scenes", RICE_SCENES_DIR};
  return {};
}

TEST(CommandLine, EveryNumberOptionRefusesBadValuesNamingTheOption) {
  const std::vector<std::string> always_refused = {"nan", "-nan", "inf", "-inf", "1e300", "-1e300"};
  const std::vector<std::string> maybe_valid = {"-1", "0", "1e-300"};
  const std::string huge_integer = "2147483647";

  CommandLine probe;
  std::vector<std::vector<std::string>> commands;
  collect_commands(&probe.app(), {}, commands);
  int swept = 0;
  const auto sweep = [&](const std::vector<std::string>& path, const CLI::Option* option, bool global) {
    ++swept;
    const std::string name = option->get_name();
    const auto check = [&](const std::string& value, bool must_refuse) {
      const std::vector<std::string> words =
          joined(global ? joined({name, value}, path) : joined(path, {name, value}), required_arguments(path));
      const Outcome outcome = parse_and_validate(words);
      const std::string where = "rice " + testing::PrintToString(words);
      if (must_refuse) {
        EXPECT_FALSE(outcome.accepted) << where << " was accepted";
      }
      if (!outcome.accepted) {
        EXPECT_NE(outcome.message.find(name), std::string::npos) << where << ": '" << outcome.message << "'";
      }
    };
    for (const std::string& value : always_refused) check(value, true);
    for (const std::string& value : maybe_valid) check(value, false);
    const bool integer = !std::string(option->get_type_name()).starts_with("FLOAT");
    check(huge_integer, integer && name != "--seed" && name != "--seeds");
  };
  for (const auto& path : commands) {
    for (const CLI::Option* option : find_command(&probe.app(), path)->get_options())
      if (takes_a_number(option)) sweep(path, option, false);
  }
  for (const CLI::Option* option : probe.app().get_options())  // global options, with one command
    if (takes_a_number(option)) sweep(commands.front(), option, true);
  EXPECT_GE(swept, 35) << "the sweep found too few options: is the enumeration broken?";
}

TEST(CommandLine, ValidCommandLinesPassAndCrossOptionRulesAreChecked) {
  EXPECT_TRUE(parse_and_validate({"grains", "--count", "3"}).accepted);
  EXPECT_TRUE(parse_and_validate({"--threads", "2", "study", "convergence", "--duration", "0.1"}).accepted);
  // Each option in range, the two out of order: refused by validation, before any work.
  const Outcome swell = parse_and_validate({"grains", "--swell-min", "1.4", "--swell-max", "1.1"});
  EXPECT_FALSE(swell.accepted);
  EXPECT_NE(swell.message.find("swell"), std::string::npos) << swell.message;
  const Outcome seed = parse_and_validate({"figure", "9", "--seed", "-1"});  // CLI11 alone wraps it around
  EXPECT_FALSE(seed.accepted);
  EXPECT_NE(seed.message.find("--seed"), std::string::npos) << seed.message;
  const Outcome damping = parse_and_validate({"study", "oscillator", "--damping", "25"});
  EXPECT_FALSE(damping.accepted);
  EXPECT_NE(damping.message.find("--damping"), std::string::npos) << damping.message;
}

}  // namespace
}  // namespace rice::experiments
