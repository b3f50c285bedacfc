// A scene run's frames read back for rendering (experiments/render/run_frames.hpp): a soft
// run's grains, carried through their embeddings, are the render meshes the run itself wrote
// (frames/frame_NNNN.ply), and its frames render; a grain within a fraction of a pixel's
// footprint of rigid is drawn as its variant at its best rigid fit; a frame whose rows do not
// match the grains' simulation meshes is refused, naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "experiments/render/render_command.hpp"
#include "experiments/render/rigid_fit.hpp"
#include "experiments/render/run_frames.hpp"
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

// Only the variants a run's grains use are shaded: two variants, every grain the second.
TEST(RunFrames, OnlyTheVariantsTheGrainsUseAreShaded) {
  const fs::path run = fs::path(RICE_TEST_SCRATCH) / "run-frames-used-variants";
  fs::remove_all(run);
  fs::create_directories(run / "variants");
  grains::SurfaceMesh tetrahedron;
  tetrahedron.V = (grains::Vertices(4, 3) << 0, 0, 0, 1e-3, 0, 0, 0, 1e-3, 0, 0, 0, 1e-3).finished();
  tetrahedron.F = (grains::Triangles(4, 3) << 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3).finished();
  for (const char* name : {"variant_0.ply", "variant_1.ply"}) {
    std::ofstream out(run / "variants" / name);
    grains::write_ply(out, tetrahedron);
  }
  std::ofstream(run / "grains.csv") << "grain,variant\n0,1\n1,1\n";
  const RunVariants variants = read_run_variants(run);
  ASSERT_EQ(variants.shading.size(), 2u);
  EXPECT_EQ(variants.shading[0].normals.rows(), 0);
  EXPECT_EQ(variants.shading[1].normals.rows(), 4);
  EXPECT_EQ(variants.shading[1].curvature.size(), 4);
}

TEST(RunFrames, ASoftRunsGrainsAreTheRenderMeshesTheRunWrote) {
  const fs::path run = soft_run();
  const RunVariants variants = read_run_variants(run);
  ASSERT_EQ(variants.simulation.size(), 2u);
  const NumericCsv grains_csv = read_numeric_csv(run / "grains.csv");
  const std::vector<SoftGrain> soft = soft_run_grains(grains_csv, read_numeric_csv(run_frame_path(run, 3)), variants);
  ASSERT_EQ(soft.size(), 3u);
  std::vector<grains::SurfaceMesh> meshes;
  for (const SoftGrain& grain : soft) meshes.push_back(deformed_render_mesh(grain, variants));
  const grains::SurfaceMesh ours = grains::merged(meshes);
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
    settings.soft = {.curvature = curvature, .instance_pixels = 0.0};
    const fs::path out = fs::path(RICE_TEST_SCRATCH) / "run-frames-soft-render";
    fs::remove_all(out);
    render_command(settings, out);
    EXPECT_TRUE(fs::exists(out / "render.png"));
  }
}

TEST(RunFrames, ASoftGrainCloseToRigidIsAnInstanceOfItsVariantAtItsFit) {
  // The clump's three grains, a little deformed where they touch: each one's variant placed at
  // its fit is its deformed render mesh to within a few times the fit's residual. With no
  // tolerance each grain is a mesh of its own; with one above every residual, none is, and
  // the scene holds just the variants.
  const fs::path run = soft_run();
  const RunVariants variants = read_run_variants(run);
  const fs::path frame = run_frame_path(run, 3);
  for (const SoftGrain& grain :
       soft_run_grains(read_numeric_csv(run / "grains.csv"), read_numeric_csv(frame), variants)) {
    const RigidFit fit = fit_rigid_motion(variants.simulation[grain.variant].V, grain.swell, grain.x);
    EXPECT_LT(fit.residual, 1e-4);  // (the clump's grains touch: up to 18 µm)
    const grains::Vertices placed = (fit.place * variants.meshes[grain.variant].V.transpose()).transpose();
    EXPECT_LT((placed - deformed_render_mesh(grain, variants).V).rowwise().norm().maxCoeff(), 3.0 * fit.residual + 1e-12);
  }
  // The tolerance is instance_pixels footprints at the grain's distance from the eye: from a
  // pixel a metre wide a metre away, every grain is an instance; from grain 0's own centre,
  // grain 0's tolerance is 0 and it alone is a mesh of its own.
  const RunFrame grains = read_run_frame(run, variants, frame);
  ASSERT_EQ(grains.soft.size(), 3u);
  const Eigen::Vector3d centre_0 = grains.soft[0].x.colwise().mean().transpose();
  const struct {
    double pixels;
    PixelFootprint footprint;
    std::set<size_t> own;  // the grains drawn as their own mesh
  } cases[] = {{0.0, {centre_0 + Eigen::Vector3d(0, 0, 1), 1.0}, {0, 1, 2}},
               {1.0, {centre_0 + Eigen::Vector3d(0, 0, 1), 1.0}, {}},
               {1.0, {centre_0, 1.0}, {0}}};
  for (const auto& c : cases) {
    shading::RenderScene scene;
    const int own = add_run_frame(scene, grains, variants, {.instance_pixels = c.pixels}, c.footprint);
    EXPECT_EQ(own, static_cast<int>(c.own.size())) << c.pixels;
    EXPECT_EQ(scene.instance_count(), 3);
    std::set<int> instanced_variants;
    for (size_t g = 0; g < 3; ++g)
      if (!c.own.contains(g)) instanced_variants.insert(grains.soft[g].variant);
    EXPECT_EQ(scene.prototype_count(), static_cast<int>(c.own.size() + instanced_variants.size()));
  }
}

TEST(RunFrames, ASoftFramesBoxesHoldItsGrainsRenderMeshesNearly) {
  // A soft grain's box is read before its render mesh is made, from every 16th vertex carried
  // by the embedding, as a rigid grain's: it misses the mesh by a few per cent of the grain's
  // size (2.4% here), a framing margin; the box of its simulation vertices, inscribed, missed
  // it by 10%.
  const fs::path run = soft_run();
  const RunVariants variants = read_run_variants(run);
  const RunFrame grains = read_run_frame(run, variants, run_frame_path(run, 3));
  ASSERT_EQ(grains.boxes.size(), grains.soft.size());
  for (size_t g = 0; g < grains.soft.size(); ++g) {
    const grains::Vertices V = deformed_render_mesh(grains.soft[g], variants).V;
    double outside = 0.0;
    for (Eigen::Index v = 0; v < V.rows(); ++v)
      outside = std::max(outside, grains.boxes[g].exteriorDistance(V.row(v).transpose()));
    EXPECT_LT(outside, 0.04 * grains.boxes[g].sizes().maxCoeff()) << g;
  }
}

TEST(PixelFootprint, IsTheFilmsHeightOverItsPixelsAtADistance) {
  // 90° vertically: the film at distance d is 2d high, so a pixel of 100 rows spans d / 50.
  shading::Camera camera;
  camera.position = {1, 2, 3};
  camera.vertical_fov_degrees = 90.0;
  const PixelFootprint footprint = pixel_footprint(camera, 100);
  EXPECT_NEAR(footprint.at({1, 2, 3}), 0.0, 1e-15);
  EXPECT_NEAR(footprint.at({1, 2 + 3.0, 3 + 4.0}), 5.0 / 50.0, 1e-12);
}

TEST(RigidFit, RecoversAKnownMotionAndMeasuresADisplacedVertex) {
  grains::Vertices rest(5, 3);
  rest << 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3, 1, 1, 1;
  const Eigen::Affine3d motion = Eigen::Translation3d(0.3, -0.2, 1.0) *
                                 Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) * Eigen::Scaling(1.2);
  grains::Vertices x = (motion * rest.transpose()).transpose();
  RigidFit fit = fit_rigid_motion(rest, 1.2, x);
  EXPECT_LT((fit.place.matrix() - motion.matrix()).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT(fit.residual, 1e-12);
  // One vertex pushed off by d: the fit spreads it over the others, its residual stays ≤ d.
  const double d = 1e-3;
  x(4, 2) += d;
  fit = fit_rigid_motion(rest, 1.2, x);
  EXPECT_GT(fit.residual, 0.5 * d);
  EXPECT_LE(fit.residual, d);
  EXPECT_THROW(fit_rigid_motion(rest, 1.2, x.topRows(4)), std::invalid_argument);
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
