// `rice reproduce` (experiments/reproduce.hpp) with a stand-in for `rice`: every step runs
// once and writes its stamp; a second run skips them all; --force and --only choose what
// runs; a step that reads another's output reruns when that one ran, and one that reads a
// scene file when the file changes; a failing step stops the run naming it; out/index.md
// holds each command, its figures, videos and tables.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "experiments/io/atomic_file.hpp"
#include "experiments/cli/reproduce.hpp"

namespace rice::experiments {
namespace {

/// A `rice` that writes a figure and a table into the step's --out folder and records the call.
struct FakeRice {
  std::vector<std::string> ran;  ///< the --out folders' names, in order
  std::string failing;           ///< a folder name whose step fails
  int operator()(const std::vector<std::string>& arguments) {
    const auto out = std::find(arguments.begin(), arguments.end(), "--out");
    EXPECT_NE(out, arguments.end());
    const std::filesystem::path folder = *(out + 1);
    ran.push_back(folder.filename().string());
    if (folder.filename() == failing) return 3;
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "plot.png") << "png";
    std::ofstream(folder / "data.csv") << "x\n1\n";
    std::ofstream(folder / "frame_0001.png") << "png";  // a video's frame: not listed
    std::ofstream(folder / "render.mp4") << "mp4";
    return 0;
  }
};

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(Reproduce, RunsEachStepOnceThenSkipsWhatIsUpToDate) {
  const std::filesystem::path out = std::filesystem::path(RICE_TEST_SCRATCH) / "reproduce";
  std::filesystem::remove_all(out);
  const std::filesystem::path scenes = out / "scenes";
  std::filesystem::create_directories(scenes);
  write_file_atomically(scenes / "press.toml", "# a press\n");
  ReproduceSettings settings;
  settings.scenes = scenes;
  const size_t steps = reproduce_steps(out, false, scenes).size();
  FakeRice rice;
  const auto call = [&](const std::vector<std::string>& a) { return rice(a); };
  reproduce_command(settings, out, call);
  EXPECT_EQ(rice.ran.size(), steps);
  const std::string index = read(out / "index.md");
  const std::string table1 = "rice table 1 --scenes " + scenes.string() + " --out " + (out / "table1").string();
  EXPECT_NE(index.find("`" + table1 + "` — ran in"), std::string::npos) << index;
  EXPECT_NE(index.find("![table1/plot.png](table1/plot.png)"), std::string::npos);
  EXPECT_NE(index.find("[table1/data.csv](table1/data.csv)"), std::string::npos);
  EXPECT_NE(index.find("Video: [table1/render.mp4](table1/render.mp4)"), std::string::npos);
  EXPECT_EQ(index.find("frame_0001.png"), std::string::npos) << "a video's frames fill the index";

  rice.ran.clear();
  reproduce_command(settings, out, call);  // everything is up to date
  EXPECT_TRUE(rice.ran.empty());
  EXPECT_NE(read(out / "index.md").find("up to date (skipped)"), std::string::npos);

  write_file_atomically(scenes / "press.toml", "# a harder press\n");  // a scene file edited...
  reproduce_command(settings, out, call);  // ...reruns the steps that read it
  // the renders of table 1's runs and the curvature study of the press too
  EXPECT_EQ(rice.ran, (std::vector<std::string>{"table1", "press", "soft-curvature", "render-chawan", "frame-cost",
                                                "video-shari", "video-chawan", "video-onigiri", "video-bunny"}));

  rice.ran.clear();
  ReproduceSettings only = settings;
  only.only = {"table1"};
  reproduce_command(only, out, call);  // table 1 reruns only when forced...
  EXPECT_TRUE(rice.ran.empty());
  only.force = true;
  reproduce_command(only, out, call);
  EXPECT_EQ(rice.ran, std::vector<std::string>{"table1"});
  only.force = false;
  only.only = {"table1", "render-chawan"};
  std::filesystem::remove(out / "table1" / "reproduce.stamp");
  rice.ran.clear();
  reproduce_command(only, out, call);  // ...and the render of its chawan's last frame follows it
  EXPECT_EQ(rice.ran, (std::vector<std::string>{"table1", "render-chawan"}));

  ReproduceSettings all = settings;
  all.force = true;
  rice.failing = "figure9";
  rice.ran.clear();
  try {
    reproduce_command(all, out, call);
    ADD_FAILURE() << "a failing step must stop the run";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("step 'figure9' failed (exit status 3)"), std::string::npos) << e.what();
  }
  EXPECT_EQ(rice.ran.back(), "figure9");
  EXPECT_THROW(validate(ReproduceSettings{.only = {"figure99"}}), std::invalid_argument);
  // --full reaches the commands that have the paper's settings: table 1.
  for (const bool full : {false, true})
    for (const ReproduceStep& step : reproduce_steps(out, full, scenes)) {
      if (step.folder.filename() == "table1") {
        EXPECT_EQ(std::count(step.arguments.begin(), step.arguments.end(), "--full"), full ? 1 : 0);
      }
    }
}

}  // namespace
}  // namespace rice::experiments
