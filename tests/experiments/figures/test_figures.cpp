// The figure and table drivers built on scene files, on short variants: figure 10 runs the drop
// scene at each soak time and tabulates the piles; table 1 runs its four scenes beside the
// paper's times, and a bad override runs and writes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "experiments/figures/figure10.hpp"
#include "experiments/figures/table1.hpp"
#include "experiments/scene/scene_file.hpp"

namespace rice::experiments {
namespace {

TEST(Figure10, RunsTheDropSceneAtEachSoakTimeAndTabulatesThePiles) {
  const std::filesystem::path out = std::filesystem::path(RICE_TEST_SCRATCH) / "figure10";
  std::filesystem::remove_all(out);
  Figure10Settings s;
  s.scene = std::filesystem::path(RICE_SCENES_DIR) / "drop.toml";
  s.soak_minutes = {15.0, 240.0};
  s.overrides = {"grains.count=12", "grains.variants=2", "solver.frames=4", "render.width=32", "render.height=24",
                 "render.samples_per_pixel=1"};
  figure10_command(s, out);
  std::ifstream table(out / "figure10.csv");
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(table, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), 3u);  // header and one row per soak time
  EXPECT_TRUE(rows[0].starts_with("soak_minutes,footprint_radius_m,clusters,rebound_height_m,peak_principal_strain,"));
  // the scene's grains are soft: their strain is measured (a rigid run writes nan)
  std::stringstream row(rows[2]);
  std::string cell;
  for (int column = 0; column < 5; ++column) std::getline(row, cell, ',');
  EXPECT_TRUE(std::isfinite(std::stod(cell))) << rows[2];
  EXPECT_TRUE(std::filesystem::exists(out / "soak_240min" / "scene.toml"));
}

TEST(Table1, RunsTheFourScenesAndSetsTheirTimesBesideThePapers) {
  const std::filesystem::path out = std::filesystem::path(RICE_TEST_SCRATCH) / "table1";
  std::filesystem::remove_all(out);
  Table1Settings s;
  s.scenes = RICE_SCENES_DIR;
  s.overrides = {"grains.count=0"};
  EXPECT_THROW(table1_command(s, out), SceneError);
  EXPECT_FALSE(std::filesystem::exists(out));  // a bad scene: nothing run, nothing written
  s.overrides = {"grains.count=12", "grains.variants=2", "solver.frames=3", "render.width=32", "render.height=24",
                 "render.samples_per_pixel=1"};
  table1_command(s, out);
  std::ifstream table(out / "table1.csv");
  std::string line;
  std::vector<std::string> rows;
  while (std::getline(table, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), 5u);  // the header and shari, chawan, onigiri, bunny
  EXPECT_TRUE(rows[1].starts_with("14,shari,12,12,270,3,"));  // grains, grains placed, the paper's, frames
  EXPECT_TRUE(rows[4].starts_with("17,bunny,12,12,3600,3,"));
  for (const std::string& row : rows) EXPECT_EQ(std::count(row.begin(), row.end(), ','), 17) << row;
  EXPECT_TRUE(std::filesystem::exists(out / "table1.md"));
  // each scene also ran by vertex block descent and with rigid grains, in folders of their own
  const auto text = [](const std::filesystem::path& file) {
    std::ifstream in(file);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_NE(text(out / "shari_vbd" / "scene.toml").find("#   solver.method=\"vbd\""), std::string::npos);
  EXPECT_NE(text(out / "shari_rigid" / "scene.toml").find("#   grains.body=\"rigid\""), std::string::npos);
  std::ifstream ended(out / "table1_runs.csv");
  rows.clear();
  while (std::getline(ended, line)) rows.push_back(line);
  ASSERT_EQ(rows.size(), 13u);  // the header and three runs of each scene
  EXPECT_TRUE(rows[2].starts_with("shari,soft by VBD 10x5,12,")) << rows[2];  // 12 grains in

  EXPECT_TRUE(std::filesystem::exists(out / "onigiri" / "render" / "render.png"));
}

}  // namespace
}  // namespace rice::experiments
