// The angle of repose (angle_of_repose.hpp): exact on a sampled cone, refused without a flank,
// fitted on a plate and not in a mould (pile_plot.hpp), and measured on heaps poured from a spout
// onto a plate: the dry heap's angle lies between 20° and 40° (issue 10), and water-content
// cohesion raises it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/pile/angle_of_repose.hpp"
#include "experiments/pile/pile_plot.hpp"
#include "experiments/scene/scene_run.hpp"

namespace rice::experiments {
namespace {

using xpbd::Vec3;

/// Points filling a cone of half-angle 90° − θ: height H − r tan θ above z = 1 cm, the
/// highest of each column on the surface.
std::vector<Vec3> cone(double angle_degrees, double height) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double slope = std::tan(angle_degrees * M_PI / 180.0), radius = height / slope;
  std::vector<Vec3> points;
  for (int k = 0; k < 20000; ++k) {
    const double r = radius * std::sqrt(unit(random)), phi = 2 * M_PI * unit(random);
    const double surface = height - slope * r;
    points.emplace_back(r * std::cos(phi) + 0.3, r * std::sin(phi) - 0.2, 0.01 + surface * (k % 5 == 0 ? 1.0 : unit(random)));
  }
  points.emplace_back(0.3, -0.2, 0.01);           // the lowest centre
  points.emplace_back(0.3, -0.2, 0.01 + height);  // and the apex, on the axis
  return points;
}

TEST(AngleOfRepose, IsExactOnASampledCone) {
  for (const double angle : {20.0, 35.0, 60.0}) {
    const HeapProfile heap = heap_profile(cone(angle, 0.02), 1e-3);
    EXPECT_NEAR(heap.angle_degrees, angle, 0.5);
    EXPECT_DOUBLE_EQ(heap.apex_height, 0.02);
  }
}

TEST(AngleOfRepose, RefusesAHeapWithoutAFlank) {
  EXPECT_THROW(heap_profile({}, 1e-3), std::invalid_argument);
  EXPECT_THROW(heap_profile(cone(30.0, 0.02), 0.0), std::invalid_argument);
  EXPECT_THROW(heap_profile({Vec3(0, 0, 0), Vec3(1e-4, 0, 0.01)}, 1e-3), std::invalid_argument);
}

TEST(AngleOfRepose, IsFittedOnAPlateAndNotInAMouldWhoseWallsShapeThePile) {
  // The same centres (a 30° cone) as a heap on a plate and as rice in a mould: a mould's pile
  // has no flank of its own, so pile.png shows it from the top and the side only.
  const std::vector<Vec3> centres = cone(30.0, 0.02);
  CsvTable table({"grain", "x", "y", "z", "r"});
  for (size_t g = 0; g < centres.size(); ++g)
    table.add_row({cell(static_cast<long>(g)), cell(centres[g].x()), cell(centres[g].y()), cell(centres[g].z()), "0"});
  for (const PileHolder holder : {PileHolder::kPlate, PileHolder::kMould}) {
    const bool plate = holder == PileHolder::kPlate;
    const auto folder = std::filesystem::path(RICE_TEST_SCRATCH) / (plate ? "pile-plate" : "pile-mould");
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    write_file_atomically(folder / "final_centres.csv", table.text());
    const std::optional<HeapProfile> fitted = write_pile_plot(folder, centres, {.holder = holder, .ring_width = 1e-3});
    EXPECT_EQ(fitted.has_value(), plate);
    if (fitted) {
      EXPECT_NEAR(fitted->angle_degrees, 30.0, 0.5);
    }
    EXPECT_EQ(std::filesystem::exists(folder / "heap_profile.csv"), plate);
    EXPECT_TRUE(std::filesystem::exists(folder / "pile.gp"));
  }
  // A pot's layer, 1 cm high and 20 cm across, is drawn from the side with its height
  // stretched; to scale it was a line of ticks. The bunny-high cone stays to scale.
  std::vector<Vec3> layer;
  for (int k = 0; k < 400; ++k) layer.emplace_back(-0.1 + 5e-4 * k, 0.0, 0.001 + 2.5e-5 * k);
  const auto side_view = [&](const std::vector<Vec3>& centres) {
    const auto folder = std::filesystem::path(RICE_TEST_SCRATCH) / "pile-side";
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    write_pile_plot(folder, centres, {.holder = PileHolder::kMould});
    std::ifstream in(folder / "pile.gp");
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_NE(side_view(layer).find("set size noratio\nset title 'From the side (height stretched)'"), std::string::npos);
  EXPECT_EQ(side_view(centres).find("height stretched"), std::string::npos);
}

TEST(AngleOfRepose, CohesionRaisesTheAngleOfAPouredHeap) {
  // 400 rigid japonica grains, five a layer from a spout 5 cm above a plate over 3.5 s, then
  // 2.5 s to settle; the same pour with and without the water-content bonds (the main job's
  // heap and heap-dry steps). Heaps of 300 grains, four rings of flank, gave dry angles from
  // 19° to 29° as the pour's pace changed by 4%.
  Scene scene;
  scene.container.kind = Container::kPlate;
  scene.grains.count = 400;
  scene.solver.frames = 180;
  scene.emitter.seconds = 3.5;
  scene.emitter.height = 0.05;
  const std::filesystem::path folder = std::filesystem::path(RICE_TEST_SCRATCH) / "heap";
  scene.effects.cohesion = false;
  const SceneResult dry = run_scene(scene, folder / "dry");
  scene.effects.cohesion = true;
  const SceneResult sticky = run_scene(scene, folder / "sticky");
  EXPECT_GT(dry.angle_of_repose_degrees, 20.0);
  EXPECT_LT(dry.angle_of_repose_degrees, 40.0);
  EXPECT_GT(sticky.angle_of_repose_degrees, dry.angle_of_repose_degrees + 5.0);
  EXPECT_GT(sticky.heap_height, dry.heap_height);
  RecordProperty("angle_dry_degrees", std::to_string(dry.angle_of_repose_degrees));
  RecordProperty("angle_sticky_degrees", std::to_string(sticky.angle_of_repose_degrees));
}

}  // namespace
}  // namespace rice::experiments
