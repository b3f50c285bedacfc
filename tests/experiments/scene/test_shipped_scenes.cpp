// Every scene file shipped in experiments/scenes reads, lays its grains out and runs a frame
// as it is (only the frame count is overridden, and the render left out: the renderer has its
// own tests): a scene whose emitter refuses its own settings fails here, not in the hands of
// its first user.
#include <gtest/gtest.h>

#include <filesystem>

#include "experiments/scene/scene_file.hpp"
#include "experiments/scene/scene_run.hpp"

namespace rice::experiments {
namespace {

namespace fs = std::filesystem;

TEST(ShippedScenes, EachRunsAFrameAsItShips) {
  int scenes = 0;
  for (const auto& entry : fs::directory_iterator(RICE_SCENES_DIR)) {
    if (entry.path().extension() != ".toml") continue;
    ++scenes;
    const fs::path out = fs::path(RICE_TEST_SCRATCH) / ("shipped-" + entry.path().stem().string());
    fs::remove_all(out);
    EXPECT_NO_THROW({
      Scene scene = read_scene_file(entry.path(), {"solver.frames=1"});
      scene.render.reset();
      run_scene(scene, out);
    }) << entry.path();
    EXPECT_TRUE(fs::exists(out / "stats.csv")) << entry.path();
  }
  EXPECT_EQ(scenes, 10);
}

}  // namespace
}  // namespace rice::experiments
