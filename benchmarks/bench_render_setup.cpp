// What a render pays before its first ray, per command and per grain variant:
//   CdrfTable    the 513 × 513 f_r table every render builds (shading/cdrf.hpp)
//   GrainShading one japonica grain's smoothed normals, curvature and thickness
//                (experiments/render/scene_pieces.hpp), paid once per variant of a run
//   SmoothedNormals / SmoothedCurvature  its two ball-smoothing passes alone
// Both run on every core (TBB), as in a render.
//
// Run: cmake --build build --target bench_render_setup -j2 && build/benchmarks/bench_render_setup
#include <benchmark/benchmark.h>

#include "experiments/render/scene_pieces.hpp"
#include "grains/cultivar.hpp"
#include "grains/grain_generator.hpp"
#include "shading/cdrf.hpp"
#include "shading/curvature.hpp"
#include "shading/smooth_normals.hpp"

namespace {

using namespace rice;

const grains::SurfaceMesh& grain_mesh() {
  static const grains::SurfaceMesh mesh = [] {
    grains::GrainRecipe recipe;
    recipe.cultivar = grains::cultivar_by_name("japonica");
    return grains::make_grain(recipe, 100, 1.0).render;
  }();
  return mesh;
}

void BM_CdrfTable(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(shading::CdrfTable(513, 513));
}
BENCHMARK(BM_CdrfTable)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_GrainShading(benchmark::State& state) {
  const grains::SurfaceMesh& m = grain_mesh();
  for (auto _ : state) benchmark::DoNotOptimize(experiments::grain_shading(m.V, m.F));
  state.counters["vertices"] = static_cast<double>(m.V.rows());
}
BENCHMARK(BM_GrainShading)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SmoothedNormals(benchmark::State& state) {
  const grains::SurfaceMesh& m = grain_mesh();
  for (auto _ : state) benchmark::DoNotOptimize(shading::smoothed_vertex_normals(m.V, m.F, experiments::kShadingRadius));
}
BENCHMARK(BM_SmoothedNormals)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SmoothedCurvature(benchmark::State& state) {
  const grains::SurfaceMesh& m = grain_mesh();
  const Eigen::VectorXd H = shading::vertex_mean_curvature(m.V, m.F);
  for (auto _ : state)
    benchmark::DoNotOptimize(shading::smoothed_vertex_values(m.V, m.F, H, experiments::kCurvatureRadius));
}
BENCHMARK(BM_SmoothedCurvature)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
