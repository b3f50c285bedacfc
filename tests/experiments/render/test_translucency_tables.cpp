// The translucent model's tables as files (experiments/render/translucency_tables.hpp): the
// shipped one reads, blends between its water contents and sits on one grid; a file with a
// hole in its grid or uneven nodes is refused, naming itself.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "experiments/render/translucency_tables.hpp"

namespace rice::experiments {
namespace {

std::filesystem::path write_table(const std::string& name, const std::string& text) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / ("rice_" + name + ".csv");
  std::ofstream(path) << text;
  return path;
}

TEST(TranslucencyTables, TheShippedOneReadsAndBlendsBetweenWaterContents) {
  const std::vector<TranslucencyAtWater>& tables = shipped_translucency();
  ASSERT_GE(tables.size(), 2u);
  for (std::size_t k = 1; k < tables.size(); ++k) EXPECT_GT(tables[k].absorption_percent, tables[k - 1].absorption_percent);
  const TranslucencyAtWater &a = tables[0], &b = tables[1];
  const double middle = 0.5 * (a.absorption_percent + b.absorption_percent);
  const auto tau = translucency_at(tables, middle);
  EXPECT_NEAR((*tau)(1e-3, -0.5), 0.5 * (a.table(1e-3, -0.5) + b.table(1e-3, -0.5)), 1e-12);
  EXPECT_EQ(translucency_at(tables, 0.0)->values(), a.table.values());  // the nearest outside the range
  EXPECT_TRUE(translucent_rice_material(middle).translucency);
}

TEST(TranslucencyTables, AHoleInTheGridOrUnevenNodesAreRefused) {
  const std::string header = "soak_minutes,absorption_percent,d_mm,cos_theta,tau\n";
  const std::string full = header + "15,10,0,-1,0.1\n15,10,0,1,0.2\n15,10,2,-1,0.3\n15,10,2,1,0.4\n";
  EXPECT_EQ(read_translucency_tables(write_table("full", full)).size(), 1u);
  const std::filesystem::path hole = write_table("hole", header + "15,10,0,-1,0.1\n15,10,0,1,0.2\n15,10,2,-1,0.3\n");
  EXPECT_THROW(read_translucency_tables(hole), std::runtime_error);
  try {
    read_translucency_tables(hole);
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("rice_hole.csv"), std::string::npos) << e.what();
  }
  const std::string uneven = header + "15,10,0,-1,0\n15,10,0,1,0\n15,10,1,-1,0\n15,10,1,1,0\n15,10,3,-1,0\n15,10,3,1,0\n";
  EXPECT_THROW(read_translucency_tables(write_table("uneven", uneven)), std::runtime_error);
}

}  // namespace
}  // namespace rice::experiments
