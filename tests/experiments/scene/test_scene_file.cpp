// Scene files (experiments/scene/scene_file.hpp): every shipped scene parses; an empty file gives
// the scene's defaults; each kind of mistake stops the read with a message naming the file,
// the line and the key; `--set` overrides; `rice run` on a short variant writes the run with a
// copy of its scene, and a bad scene writes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "experiments/scene/scene_file.hpp"
#include "experiments/scene/scene_run.hpp"

#ifndef RICE_SCENES_DIR
#error "RICE_SCENES_DIR must name experiments/scenes (set by tests/CMakeLists.txt)"
#endif

namespace rice::experiments {
namespace {

TEST(SceneFile, EveryShippedSceneParses) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(RICE_SCENES_DIR)) {
    if (entry.path().extension() != ".toml") continue;
    ++count;
    SCOPED_TRACE(entry.path().string());
    const Scene scene = read_scene_file(entry.path());
    EXPECT_EQ(scene.name, entry.path().stem().string());
    EXPECT_FALSE(scene.description.empty());
    EXPECT_NO_THROW(validate(scene));
  }
  EXPECT_GE(count, 2);
}

TEST(SceneFile, AnEmptyFileIsTheSceneWithItsDefaults) {
  const Scene scene = parse_scene("", "dir/empty.toml");
  EXPECT_EQ(scene.name, "empty");
  const Scene d;  // the defaults in code equal the key table's, which the reader used
  EXPECT_EQ(scene.grains.cultivar, d.grains.cultivar);
  EXPECT_EQ(scene.grains.count, d.grains.count);
  EXPECT_EQ(scene.grains.variants, d.grains.variants);
  EXPECT_EQ(scene.grains.seed, d.grains.seed);
  EXPECT_EQ(scene.grains.body, d.grains.body);
  EXPECT_EQ(scene.grains.young, d.grains.young);
  EXPECT_EQ(scene.grains.elasticity, d.grains.elasticity);
  EXPECT_EQ(scene.grains.poisson, d.grains.poisson);
  EXPECT_EQ(scene.grains.soak_minutes, d.grains.soak_minutes);
  EXPECT_EQ(scene.grains.soak_temperature, d.grains.soak_temperature);
  EXPECT_TRUE(std::isnan(scene.grains.stickiness));
  EXPECT_EQ(scene.solver.fps, d.solver.fps);
  EXPECT_EQ(scene.solver.frames, d.solver.frames);
  EXPECT_EQ(scene.solver.substeps, d.solver.substeps);
  EXPECT_EQ(scene.solver.iterations, d.solver.iterations);
  EXPECT_EQ(scene.solver.vertex_block_descent, d.solver.vertex_block_descent);
  EXPECT_EQ(scene.container.kind, d.container.kind);
  EXPECT_EQ(scene.container.grid_spacing, d.container.grid_spacing);
  EXPECT_EQ(scene.container.scale, d.container.scale);
  EXPECT_EQ(scene.emitter.kind, d.emitter.kind);
  EXPECT_EQ(scene.emitter.height, d.emitter.height);
  EXPECT_EQ(scene.emitter.radius, d.emitter.radius);
  EXPECT_EQ(scene.emitter.seconds, d.emitter.seconds);
  EXPECT_EQ(scene.effects.static_friction, d.effects.static_friction);
  EXPECT_EQ(scene.effects.dynamic_friction, d.effects.dynamic_friction);
  EXPECT_EQ(scene.effects.cohesion, d.effects.cohesion);
  EXPECT_EQ(scene.effects.damping, d.effects.damping);
  EXPECT_EQ(scene.effects.sleeping, d.effects.sleeping);
  EXPECT_EQ(scene.effects.render_meshes, d.effects.render_meshes);
  EXPECT_FALSE(scene.render);
  // [render] with no keys, and a fill's round time, take their defaults too.
  const SceneRender r = *parse_scene("[render]\n", "s.toml").render, dr;
  EXPECT_EQ(r.width, dr.width);
  EXPECT_EQ(r.height, dr.height);
  EXPECT_EQ(r.samples_per_pixel, dr.samples_per_pixel);
  EXPECT_EQ(r.sun_elevation_degrees, dr.sun_elevation_degrees);
  EXPECT_EQ(r.sun_azimuth_degrees, dr.sun_azimuth_degrees);
  EXPECT_EQ(r.sun_irradiance, dr.sun_irradiance);
  EXPECT_EQ(r.sky_radiance, dr.sky_radiance);
  EXPECT_EQ(r.ground, dr.ground);
  EXPECT_EQ(r.every_frame, dr.every_frame);
  EXPECT_EQ(r.video, dr.video);
  EXPECT_EQ(r.vertical_fov_degrees, dr.vertical_fov_degrees);
  EXPECT_FALSE(r.eye);
}

TEST(SceneFile, KeysSetTheSettings) {
  const Scene scene = parse_scene(R"([grains]
count = 12
body = "soft"
young_pa = 2e5
elasticity = "corotated"
min_vertices = 8
max_vertices = 12
[solver]
method = "vbd"
vbd_damping = "constraint"
frames = 7
[container]
kind = "plate"
[effects]
friction = false
cohesion = false
damping = false
)", "s.toml");
  EXPECT_EQ(scene.grains.count, 12);
  EXPECT_EQ(scene.grains.body, xpbd::BodyKind::kSoft);
  EXPECT_EQ(scene.grains.young, 2e5);
  EXPECT_EQ(scene.grains.elasticity, xpbd::TetMaterial::kCorotated);
  EXPECT_EQ(scene.grains.min_vertices, 8);
  EXPECT_EQ(scene.grains.max_vertices, 12);
  EXPECT_TRUE(scene.solver.vertex_block_descent);
  EXPECT_FALSE(scene.solver.vbd_strain_rate_damping);
  EXPECT_EQ(scene.solver.frames, 7);
  EXPECT_EQ(scene.container.kind, Container::kPlate);
  EXPECT_EQ(scene.effects.static_friction, 0.0);
  EXPECT_EQ(scene.effects.dynamic_friction, 0.0);
  EXPECT_FALSE(scene.effects.cohesion);
  EXPECT_FALSE(scene.effects.damping);
}

/// The message of reading `text` as "bad.toml" (empty when it is read).
std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse_scene(text, "bad.toml", overrides);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneFile, MistakesNameTheFileTheLineAndTheKey) {
  struct Case {
    const char* text;
    const char* message;  ///< the start of the expected message
  };
  const Case cases[] = {
      {"[grains]\ncount = 10\ncont = 3\n", "bad.toml:3: [grains] has no key 'cont'"},
      {"[grain]\ncount = 10\n", "bad.toml:1: 'grain' is not a section"},
      {"count = 10\n", "bad.toml:1: 'count' is not a section"},
      {"[grains]\ncount = \"many\"\n", "bad.toml:2: [grains] count = \"many\": expected an integer in [1, 100000]"},
      {"[grains]\n\ncount = 0\n", "bad.toml:3: [grains] count = 0: expected an integer in [1, 100000]"},
      {"[grains]\ncount = 2.5\n", "bad.toml:2: [grains] count = 2.5: expected an integer"},
      {"[grains]\npoisson = 0.5\n", "bad.toml:2: [grains] poisson = 0.5: expected a number in (-1, 0.5)"},
      {"[grains]\nelasticity = \"corotated\"\npoisson = 0\n", "bad.toml:3: [grains] poisson = 0: expected > 0 with elasticity = 'corotated'"},
      {"[grains]\nmin_vertices = 8\nmax_vertices = 6\n", "bad.toml:3: [grains] max_vertices = 6: expected at least min_vertices (8)"},
      {"[grains]\nmin_vertices = 80\n", "bad.toml:2: [grains] min_vertices = 80: expected at most max_vertices (60)"},
      {"[grains]\ncultivar = \"basmati\"\n", "bad.toml:2: [grains] cultivar = \"basmati\": expected one of 'japonica'"},
      {"[solver]\nfps = nan\n", "bad.toml:2: [solver] fps = nan: expected a number in (0, 1000]"},
      {"[solver]\nmethod = \"vbd\"\n", "bad.toml:2: [solver] method = \"vbd\": expected 'xpbd' for rigid grains"},
      {"[solver]\nvbd_damping = \"constraint\"\n", "bad.toml:2: [solver] vbd_damping = \"constraint\": expected given only with method = 'vbd'"},
      {"[effects]\nstatic_friction = 0.3\ndynamic_friction = 0.4\n",
       "bad.toml:3: [effects] dynamic_friction = 0.4: expected at most static_friction"},
      {"[effects]\nstatic_friction = 0.3\n", "bad.toml:2: [effects] static_friction = 0.3: expected at least dynamic_friction"},
      {"[effects]\ncohesion = 1\n", "bad.toml:2: [effects] cohesion = 1: expected true or false"},
      {"[emitter]\nkind = \"stream\"\n", "bad.toml:2: [emitter] kind = \"stream\": expected one of 'spout'"},
      {"[emitter]\nseconds = 0\n", "bad.toml:2: [emitter] seconds = 0: expected a number in (0, 10000] (all at once: kind = 'clump')"},
      {"[emitter]\nkind = \"clump\"\nseconds = 1\n", "bad.toml:3: [emitter] has no key 'seconds'"},
      {"[grains]\ncount = = 3\n", "bad.toml:2: "},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    const std::string message = error_of(c.text);
    EXPECT_TRUE(message.starts_with(c.message)) << message;
  }
}

TEST(SceneFile, CollidersHaveTheirShapesSizesAndKeyframes) {
  const Scene scene = parse_scene(R"([effects]
static_friction = 0.6
dynamic_friction = 0.5
[[colliders]]
shape = "plane"
position_m = [0.0, 0.0, 0.1]
axis = [1.0, 0.0, 0.0]
angle_deg = 180
[[colliders]]
shape = "box"
half_extents_m = [0.03, 0.02, 0.005]
static_friction = 0.2
keyframes = [ { time_s = 0.0, position_m = [0.0, 0.0, 0.08] },
              { time_s = 1.5, position_m = [0.0, 0.0, 0.01], axis = [0.0, 0.0, 1.0], angle_deg = 90, size = 0.9 } ]
[[colliders]]
shape = "capsule"
radius_m = 0.01
half_length_m = 0.03
)", "s.toml");
  ASSERT_EQ(scene.colliders.size(), 3u);
  const xpbd::Collider& lid = scene.colliders[0];
  EXPECT_EQ(lid.shape, xpbd::ColliderShape::kHalfSpace);
  EXPECT_NEAR((lid.motion[0].rotation * xpbd::Vec3::UnitZ() + xpbd::Vec3::UnitZ()).norm(), 0.0, 1e-12);  // facing down
  EXPECT_EQ(lid.static_friction, 0.6);  // the grains' by default
  const xpbd::Collider& hand = scene.colliders[1];
  EXPECT_EQ(hand.shape, xpbd::ColliderShape::kBox);
  EXPECT_EQ(hand.half_extents, xpbd::Vec3(0.03, 0.02, 0.005));
  EXPECT_EQ(hand.static_friction, 0.2);
  EXPECT_EQ(hand.dynamic_friction, 0.2);  // capped by its own static friction
  ASSERT_EQ(hand.motion.size(), 2u);
  EXPECT_EQ(hand.motion[1].time, 1.5);
  EXPECT_EQ(hand.motion[0].scale, 1.0);
  EXPECT_EQ(hand.motion[1].scale, 0.9);
  EXPECT_NEAR((hand.motion[1].rotation * xpbd::Vec3::UnitX() - xpbd::Vec3::UnitY()).norm(), 0.0, 1e-12);
  EXPECT_EQ(scene.colliders[2].half_length, 0.03);
  EXPECT_NO_THROW(validate(scene));

  const std::string box = "[[colliders]]\nshape = \"box\"\n";
  EXPECT_TRUE(error_of("[[colliders]]\nradius_m = 1\n").starts_with("bad.toml:1: [colliders.1] needs a shape"));
  EXPECT_TRUE(error_of("[[colliders]]\nshape = \"cone\"\n").starts_with("bad.toml:2: [colliders.1] shape = \"cone\""));
  EXPECT_TRUE(error_of("[[colliders]]\nshape = \"sphere\"\n").starts_with("bad.toml:1: [colliders.1] a sphere needs radius_m"));
  EXPECT_TRUE(error_of(box + "half_extents_m = [1, 2]\n").starts_with("bad.toml:3: [colliders.1] half_extents_m = [ 1, 2 ]: expected three numbers"));
  EXPECT_TRUE(error_of(box + "half_extents_m = [1, 2, 3]\nradius_m = 1\n").starts_with("bad.toml:4: [colliders.1] has no key 'radius_m'"));
  EXPECT_TRUE(error_of(box + "half_extents_m = [1, 2, 3]\nkeyframes = [ { time_s = 1.0 }, { time_s = 0.5 } ]\n")
                  .starts_with("bad.toml:4: [colliders.1.keyframes.2] time_s = 0.5: expected a time in s after the previous"));
  EXPECT_TRUE(error_of(box + "half_extents_m = [1, 2, 3]\nkeyframes = [ { size = 0 } ]\n")
                  .starts_with("bad.toml:4: [colliders.1.keyframes.1] size = 0: expected a number in (0, 10]"))
      << error_of(box + "half_extents_m = [1, 2, 3]\nkeyframes = [ { size = 0 } ]\n");
  EXPECT_TRUE(error_of(box + "half_extents_m = [1, 2, 3]\nkeyframes = 3\n").starts_with("bad.toml:4: [colliders.1] keyframes = 3: expected a list"));
  EXPECT_TRUE(error_of("colliders = 3\n").starts_with("bad.toml:1: 'colliders' must be a list of [[colliders]] tables"));
}

TEST(SceneFile, MeshCollidersAndTheFillReadTheirFilesFromTheScenesFolder) {
  // Paths are from the scene file's folder; the file is read, checked closed and scaled.
  const std::string scene_path = std::string(RICE_SCENES_DIR) + "/test.toml";
  const Scene scene = parse_scene(R"([emitter]
kind = "fill"
mould = 2
round_s = 0.25
[[colliders]]
shape = "box"
half_extents_m = [0.01, 0.01, 0.01]
[[colliders]]
shape = "mesh"
file = "meshes/shari_mould.obj"
scale = 2
hollow = true
grid_spacing_m = 5e-4
removed_at_s = 4.5
)", scene_path);
  ASSERT_EQ(scene.mesh_colliders.size(), 1u);
  ASSERT_EQ(scene.colliders.size(), 1u);
  const MeshCollider& mould = scene.mesh_colliders[0];
  EXPECT_TRUE(mould.hollow);
  EXPECT_EQ(mould.grid_spacing, 5e-4);
  EXPECT_EQ(mould.collider.removal_time, 4.5);
  EXPECT_NEAR(mould.mesh.V.col(2).maxCoeff(), 2 * 0.04, 1e-9);  // the shari mould is 4 cm tall
  EXPECT_EQ(scene.emitter.kind, EmitterKind::kFill);
  EXPECT_EQ(scene.emitter.mould, 0);
  EXPECT_EQ(scene.emitter.round_seconds, 0.25);
  EXPECT_TRUE(std::isinf(scene.colliders[0].removal_time));
  EXPECT_NO_THROW(validate(scene));

  const auto error_at = [&](const std::string& text) {
    try {
      parse_scene(text, scene_path);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string mesh = "[[colliders]]\nshape = \"mesh\"\n";
  EXPECT_NE(error_at(mesh).find("[colliders.1] needs file"), std::string::npos) << error_at(mesh);
  EXPECT_NE(error_at(mesh + "file = \"meshes/none.obj\"\n").find(":3: [colliders.1] file = \"meshes/none.obj\": expected a mesh file that exists"),
            std::string::npos);
  // An open mesh (a tetrahedron without one face) is refused naming its defect.
  const std::filesystem::path open = std::filesystem::path(RICE_TEST_SCRATCH) / "open_mesh.obj";
  std::ofstream(open) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n";
  EXPECT_NE(error_at(mesh + "file = \"" + open.string() + "\"\n").find("expected a closed triangle mesh"), std::string::npos);
  EXPECT_NE(error_at("[[colliders]]\nshape = \"box\"\nhalf_extents_m = [1, 1, 1]\nfile = \"x.obj\"\n").find("has no key 'file'"),
            std::string::npos);
  EXPECT_NE(error_at("[[colliders]]\nshape = \"plane\"\nremoved_at_s = 0\n").find("removed_at_s = 0: expected a number in (0, 10000]"),
            std::string::npos);
  EXPECT_NE(error_at("[emitter]\nkind = \"fill\"\n").find("[emitter] kind = 'fill' needs mould"), std::string::npos);
  EXPECT_NE(error_at("[emitter]\nkind = \"fill\"\nmould = 1\n[[colliders]]\nshape = \"plane\"\n")
                .find("[emitter] mould = 1: expected the number of a [[colliders]] with shape = 'mesh' and hollow = true"),
            std::string::npos);
  EXPECT_NE(error_at("[emitter]\nkind = \"fill\"\nmould = 1\nheight_m = 0.1\n" + mesh + "file = \"meshes/shari_mould.obj\"\nhollow = true\n")
                .find("[emitter] has no key 'height_m'"),
            std::string::npos);
}

TEST(SceneFile, RenderSectionSetsTheImageAndTheCamera) {
  const Scene scene = parse_scene(R"([render]
width = 320
height = 200
samples_per_pixel = 8
eye_m = [0.0, -0.2, 0.1]
look_at_m = [0.0, 0.0, 0.02]
fov_deg = 40
)", "s.toml");
  ASSERT_TRUE(scene.render);
  EXPECT_EQ(scene.render->width, 320);
  EXPECT_EQ(scene.render->samples_per_pixel, 8);
  EXPECT_EQ(*scene.render->eye, xpbd::Vec3(0.0, -0.2, 0.1));
  EXPECT_EQ(scene.render->vertical_fov_degrees, 40.0);
  EXPECT_FALSE(parse_scene("", "s.toml").render);  // no section, no render
  EXPECT_TRUE(error_of("[render]\neye_m = [0, 0, 1]\n").starts_with("bad.toml:1: [render] give both eye_m and look_at_m"));
  EXPECT_TRUE(parse_scene("[grains]\nbody = \"soft\"\n[render]\nwidth = 64\n", "s.toml").render);  // soft runs render
  EXPECT_TRUE(error_of("[render]\nwidth = 8\n").starts_with("bad.toml:2: [render] width = 8: expected an integer in [16, 16384]"));
}

TEST(SceneFile, OverridesReplaceOrAddKeysAndAreCheckedTheSameWay) {
  const Scene scene = parse_scene("[grains]\ncount = 800\n", "s.toml", {"grains.count=40", "solver.frames=5"});
  EXPECT_EQ(scene.grains.count, 40);
  EXPECT_EQ(scene.solver.frames, 5);
  EXPECT_TRUE(error_of("", {"grains.count=-1"}).starts_with("--set grains.count=-1:1: [grains] count = -1: expected"));
  EXPECT_TRUE(error_of("", {"grains.colour=2"}).starts_with("--set grains.colour=2:1: [grains] has no key 'colour'"));
  EXPECT_TRUE(error_of("", {"count=40"}).starts_with("--set count=40: expected section.key=value"));
  EXPECT_TRUE(error_of("", {"grain.count=40"}).starts_with("--set grain.count=40: there is no section 'grain'"));
}

TEST(SceneFile, OverridesReachACollidersKeysByItsNumber) {
  const std::string two_boxes = "[[colliders]]\nshape = \"box\"\nhalf_extents_m = [0.01, 0.01, 0.01]\n"
                                "[[colliders]]\nshape = \"box\"\nhalf_extents_m = [0.02, 0.02, 0.02]\n";
  const Scene scene = parse_scene(two_boxes, "s.toml", {"colliders.2.removed_at_s=3"});
  ASSERT_EQ(scene.colliders.size(), 2u);
  EXPECT_EQ(scene.colliders[0].removal_time, INFINITY);
  EXPECT_EQ(scene.colliders[1].removal_time, 3.0);
  EXPECT_TRUE(error_of(two_boxes, {"colliders.3.removed_at_s=3"})
                  .starts_with("--set colliders.3.removed_at_s=3: expected colliders.N.key=value with N in [1, 2]"));
  EXPECT_TRUE(error_of(two_boxes, {"colliders.x.removed_at_s=3"}).find("with N in [1, 2]") != std::string::npos);
  EXPECT_TRUE(error_of(two_boxes, {"colliders.1.colour=3"}).find("has no key 'colour'") != std::string::npos);
}

TEST(SceneFile, AColliderWithAForceLimitYieldsAlongItsAxis) {
  const std::string lid = "[[colliders]]\nshape = \"box\"\nhalf_extents_m = [0.01, 0.01, 0.01]\n";
  const xpbd::Collider kinematic = parse_scene(lid, "s.toml").colliders.at(0);
  EXPECT_FALSE(xpbd::yields(kinematic));
  const xpbd::Collider hand =
      parse_scene(lid + "force_limit_n = 2.5\nyield_axis = [0, 3, 4]\n", "s.toml").colliders.at(0);
  EXPECT_EQ(hand.force_limit, 2.5);
  EXPECT_TRUE(hand.yield_axis.isApprox(xpbd::Vec3(0.0, 0.6, 0.8), 1e-15));
  EXPECT_EQ(hand.yield_speed, 0.01);
  EXPECT_TRUE(error_of(lid + "force_limit_n = 1\nyield_axis = [0, 0, 0]\n")
                  .find("[colliders.1] yield_axis = [ 0, 0, 0 ]: expected a direction") != std::string::npos)
      << error_of(lid + "force_limit_n = 1\nyield_axis = [0, 0, 0]\n");
  EXPECT_TRUE(error_of(lid + "force_limit_n = 0\n").find("force_limit_n = 0: expected a number in (0, 1e6]") !=
              std::string::npos)
      << error_of(lid + "force_limit_n = 0\n");
}

TEST(SceneFile, RunWritesTheRunWithItsSceneAndABadSceneWritesNothing) {
  const std::filesystem::path out = std::filesystem::path(RICE_TEST_SCRATCH) / "scene-run";
  std::filesystem::remove_all(out);
  const std::filesystem::path chawan = std::filesystem::path(RICE_SCENES_DIR) / "chawan.toml";
  EXPECT_THROW(run_scene_command(chawan, {"grains.count=0"}, out), SceneError);
  EXPECT_FALSE(std::filesystem::exists(out));
  run_scene_command(chawan, {"grains.count=20", "grains.variants=2", "solver.frames=3", "render.width=32",
                             "render.height=24", "render.samples_per_pixel=1", "render.video=true"},
                    out);
  for (const char* file : {"scene.toml", "stats.csv", "run_info.txt", "grains.csv", "render/render.png",
                           "render_frames/frame_0001.png", "render_frames/frame_0002.png", "render_frames/render.mp4"})
    EXPECT_TRUE(std::filesystem::exists(out / file)) << file;
  // Every frame through the last one's camera: the last of them is the last frame's image.
  const auto bytes = [](const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes(out / "render_frames" / "frame_0003.png"), bytes(out / "render" / "render.png"));
  // The copy reads back as the scene it ran.
  const Scene copy = read_scene_file(out / "scene.toml");
  EXPECT_EQ(copy.grains.count, 800);  // the file's own value; the overrides are listed below it
}

TEST(SceneFile, GrainsThatMissTheBowlStayOutOfItsMeasures) {
  // A bowl 1.2 cm across under a spout 4 cm wide: most grains miss it and fall on, metres
  // down by the end; the bowl's section and packing cover those in it (the section of all of
  // them once asked for a picture metres wide and stopped the run).
  const std::filesystem::path out = std::filesystem::path(RICE_TEST_SCRATCH) / "scene-overflow";
  std::filesystem::remove_all(out);
  const SceneResult result =
      run_scene_command(std::filesystem::path(RICE_SCENES_DIR) / "chawan.toml",
                        {"grains.count=30", "grains.variants=2", "solver.frames=20", "container.scale=0.1",
                         "render.width=16", "render.height=16", "render.samples_per_pixel=1"},
                        out);
  EXPECT_LT(result.in_container, 30);
  EXPECT_GE(result.in_container, 0);
  EXPECT_TRUE(std::filesystem::exists(out / "render" / "render.png"));
}

TEST(SceneFile, TheMouldScenesRunShortAndEveryGrainFindsRoom) {
  // Short variants of the shari and the bunny: the fill drops every grain into the mould within
  // a few rounds; grains start inside it (the highest centre below the mould's top).
  for (const auto& [name, mould_top] : {std::pair("shari", 0.04), std::pair("bunny", 0.0497 + 0.05)}) {
    SCOPED_TRACE(name);
    const std::filesystem::path out = std::filesystem::path(RICE_TEST_SCRATCH) / (std::string("scene-") + name);
    std::filesystem::remove_all(out);
    const SceneResult result = run_scene_command(
        std::filesystem::path(RICE_SCENES_DIR) / (std::string(name) + ".toml"),
        {"grains.count=40", "grains.variants=2", "solver.frames=6", "render.width=32", "render.height=24",
         "render.samples_per_pixel=1"},
        out);
    EXPECT_GT(result.top, 0.0);
    EXPECT_LT(result.top, mould_top);
    std::ifstream info(out / "run_info.txt");
    const std::string text((std::istreambuf_iterator<char>(info)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("grains_placed: 40\n"), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace rice::experiments
