// Ray throughput of the renderer's scene (shading/render_scene.hpp, Embree 3) on one core:
// 1000 japonica grains instanced from 8 generated variants (rotations uniform, swell in the
// cultivar's range) scattered over a 6 cm square in a 1 cm thick layer, as in a bowl, with
// the ground under them.
//   Primary  camera rays through a 512 × 512 image of the layer from 45° above: intersect
//            and turn the hit into a shading point (normal, curvature).
//   Shadow   occlusion rays from those hit points towards a sun 50° above the horizon.
// items_per_second is rays per second on one core (the benchmark's thread).
//
// Run: cmake --build build --target bench_render -j2 && build/benchmarks/bench_render
// Measured: see the README (Rendering, speed).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "experiments/render/scene_pieces.hpp"
#include "shading/renderer.hpp"
#include "grains/cultivar.hpp"
#include "grains/grain_generator.hpp"
#include "grains/random_stream.hpp"
#include "shading/camera.hpp"
#include "shading/render_scene.hpp"

namespace {

using namespace rice;

struct Layer {
  shading::RenderScene scene;
  std::vector<shading::Ray> primary, shadow;
};

Layer& layer() {
  static Layer* built = [] {
    auto* l = new Layer;
    grains::GrainRecipe recipe;
    recipe.cultivar = grains::cultivar_by_name("japonica");
    std::vector<int> prototypes;
    for (int k = 0; k < 8; ++k) {
      const grains::Grain grain = grains::make_grain(recipe, 100 + k, 1.0);
      prototypes.push_back(experiments::add_grain_prototype(l->scene, grain.render.V, grain.render.F));
    }
    grains::RandomStream random(7);
    const auto instances = grains::make_instances(1000, 8, recipe.cultivar, random);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const auto& inst : instances) {
      const Eigen::Vector3d at(0.06 * (unit(rng) - 0.5), 0.06 * (unit(rng) - 0.5), 0.002 + 0.008 * unit(rng));
      l->scene.add_instance(prototypes[inst.variant],
                            Eigen::Translation3d(at) * inst.rotation * Eigen::Scaling(inst.swell), 0);
    }
    experiments::add_ground(l->scene, -0.1, -0.1, 0.1, 0.1, 0.0, 1);
    l->scene.commit();

    shading::Camera camera;
    camera.position = {0.0, -0.07, 0.07};
    camera.target = {0.0, 0.0, 0.005};
    camera.vertical_fov_degrees = 50.0;
    const Eigen::Vector3f sun = Eigen::Vector3f(0.4f, -0.5f, 0.77f).normalized();
    for (int y = 0; y < 512; ++y)
      for (int x = 0; x < 512; ++x) {
        const shading::CameraRay r = camera.ray((x + 0.5) / 512, (y + 0.5) / 512, 0, 0, 1.0);
        l->primary.push_back({r.origin, r.direction});
        if (const auto hit = l->scene.intersect(l->primary.back()))
          l->shadow.push_back({hit->position + l->scene.ray_offset() * hit->geometric_normal, sun});
      }
    return l;
  }();
  return *built;
}

void Primary(benchmark::State& state) {
  Layer& l = layer();
  std::size_t i = 0, hits = 0;
  for (auto _ : state) {
    const auto hit = l.scene.intersect(l.primary[i]);
    hits += hit.has_value();
    benchmark::DoNotOptimize(hit);
    if (++i == l.primary.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["hit_fraction"] = static_cast<double>(hits) / static_cast<double>(state.iterations());
}
BENCHMARK(Primary);

void Shadow(benchmark::State& state) {
  Layer& l = layer();
  std::size_t i = 0, blocked = 0;
  for (auto _ : state) {
    const bool occluded = l.scene.occluded(l.shadow[i]);
    blocked += occluded;
    benchmark::DoNotOptimize(occluded);
    if (++i == l.shadow.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["occluded_fraction"] = static_cast<double>(blocked) / static_cast<double>(state.iterations());
}
BENCHMARK(Shadow);

}  // namespace

BENCHMARK_MAIN();
