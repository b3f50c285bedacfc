// Google Benchmark kernels of the XPBD solver: one Neo-Hookean tet solve (both constraints,
// jointly) and a full substep on a mesh with >= 100k tets, on 1 and 2 threads.
// Reported counter `tets/s`: Neo-Hookean tet projections per second.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include "xpbd/solver.hpp"

namespace {

using namespace rice::xpbd;

Model block_model(int nx, int ny, int nz) {
  const TetMesh mesh = make_box_tet_mesh(Vec3(nx * 1e-3, ny * 1e-3, nz * 1e-3), nx, ny, nz);
  Model model;
  model.particles = make_particles(mesh, 1100.0);
  add_neo_hookean_tets(model, mesh, lame_from_young_poisson(1e5, 0.3), 1e-4);
  return model;
}

/// Single tet solve: one cube (6 tets), serial, one substep of one iteration per run.
void BM_NeoHookeanTetSolve(benchmark::State& state) {
  Model model = block_model(1, 1, 1);
  Solver solver(model, {.time_step = 1e-5, .substeps = 1, .iterations = 100, .execution = Execution::kSerial});
  for (auto _ : state) {
    solver.step();
    benchmark::DoNotOptimize(model.particles.x.data());
  }
  state.counters["tets/s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * 100 * model.neo_hookean.size(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_NeoHookeanTetSolve)->Unit(benchmark::kMicrosecond);

/// Full substep (predict, one Gauss–Seidel iteration over all colours, velocity update) on a
/// 40×40×11 block: 105,600 tets. Argument: thread count.
void BM_Substep100kTets(benchmark::State& state) {
  tbb::global_control threads(tbb::global_control::max_allowed_parallelism, state.range(0));
  Model model = block_model(40, 40, 11);
  Solver solver(model, {.time_step = 1e-5, .substeps = 1, .iterations = 1});
  for (auto _ : state) {
    solver.step();
    benchmark::DoNotOptimize(model.particles.x.data());
  }
  state.counters["tets"] = static_cast<double>(model.neo_hookean.size());
  state.counters["tets/s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * model.neo_hookean.size(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_Substep100kTets)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
