// A scene run's frames read back for rendering (experiments/render/run_frames.hpp): a soft
// run's grains, carried through their embeddings, are the render meshes the run itself wrote
// (frames/frame_NNNN.ply), and its frames render; a frame whose rows do not match the grains'
// simulation meshes is refused, naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "experiments/render/render_command.hpp"
#include "experiments/render/run_frames.hpp"
#include "experiments/scene/render_mesh_observer.hpp"
#include "experiments/scene/scene_run.hpp"
#include "grains/mesh_io.hpp"

namespace rice::experiments {
namespace {

namespace fs = std::filesystem;

/// A short soft run on a plate, with its render meshes written every frame, in a folder of
/// the test's own: CTest runs these tests in parallel processes, and a shared folder was
/// removed by one while another read it ("grains.csv: cannot be read").
fs::path soft_run() {
  static const fs::path folder = [] {
    Scene scene;
    scene.container.kind = Container::kPlate;
    scene.emitter.kind = EmitterKind::kClump;
    scene.grains.body = xpbd::BodyKind::kSoft;
    scene.grains.count = 3;
    scene.grains.variants = 2;
    scene.solver.frames = 3;
    scene.effects.render_meshes = true;
    const fs::path out = fs::path(RICE_TEST_SCRATCH) /
                         ("run-frames-soft-" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(out);
    run_scene(scene, out);
    return out;
  }();
  return folder;
}

TEST(RunFrames, ASoftRunsGrainsAreTheRenderMeshesTheRunWrote) {
  const fs::path run = soft_run();
  const RunVariants variants = read_run_variants(run);
  ASSERT_EQ(variants.simulation.size(), 2u);
  const NumericCsv grains_csv = read_numeric_csv(run / "grains.csv");
  const std::vector<SoftGrain> soft = soft_run_grains(grains_csv, read_numeric_csv(run_frame_path(run, 3)), variants);
  ASSERT_EQ(soft.size(), 3u);
  std::vector<grains::SurfaceMesh> meshes;
  for (const SoftGrain& grain : soft) meshes.push_back(grain.mesh);
  const grains::SurfaceMesh ours = merged(meshes);
  const grains::SurfaceMesh written = grains::read_surface_mesh(run / "frames" / "frame_0003.ply");
  ASSERT_EQ(ours.V.rows(), written.V.rows());
  EXPECT_EQ(ours.F, written.F);
  EXPECT_LT((ours.V - written.V).cwiseAbs().maxCoeff(), 1e-12);
  // the grains fall between frames: the match is of moving meshes, not of ones at rest
  const grains::SurfaceMesh first = grains::read_surface_mesh(run / "frames" / "frame_0001.ply");
  EXPECT_GT((ours.V - first.V).cwiseAbs().maxCoeff(), 1e-5);
}

TEST(RunFrames, ASoftRunRendersWithEitherCurvature) {
  RenderCommandSettings settings;
  settings.run = soft_run();
  settings.render.width = 24;
  settings.render.height = 16;
  settings.render.samples_per_pixel = 1;
  for (SoftCurvature curvature : {SoftCurvature::kRest, SoftCurvature::kDeformed}) {
    settings.soft_curvature = curvature;
    const fs::path out = fs::path(RICE_TEST_SCRATCH) / "run-frames-soft-render";
    fs::remove_all(out);
    render_command(settings, out);
    EXPECT_TRUE(fs::exists(out / "render.png"));
  }
}

TEST(RunFrames, AFrameThatDoesNotMatchTheGrainsIsRefused) {
  const fs::path run = soft_run();
  const RunVariants variants = read_run_variants(run);
  const NumericCsv grains_csv = read_numeric_csv(run / "grains.csv");
  NumericCsv frame = read_numeric_csv(run_frame_path(run, 3));
  frame.rows.pop_back();
  try {
    soft_run_grains(grains_csv, frame, variants);
    ADD_FAILURE() << "a frame one row short was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("frame_0003.csv ends before grain 2"), std::string::npos) << e.what();
  }
  RunVariants rigid = variants;
  rigid.simulation.clear();
  EXPECT_THROW(soft_run_grains(grains_csv, read_numeric_csv(run_frame_path(run, 3)), rigid), std::runtime_error);
}

}  // namespace
}  // namespace rice::experiments
