// Rigid grains: XPBD rigid bodies (Müller, Macklin, Chentanez, Jeschke & Kim 2020; the
// product's xpbd/rigid_body.hpp through add_rigid_body and the Solver) against shape matching
// (Müller, Heidelberger, Teschner & Gross 2005, "Meshless deformations based on shape
// matching", MHTG05 below), the measurement behind choosing the former.
//
// Both run the contact tests' grain (tests/xpbd/grain_fixtures.hpp: a 7 × 3 × 2 mm box tet
// mesh of 30 vertices, ρ = 1100 kg/m³) on the plane z = 0 without friction, Δt = 1/300 s in
// 10 substeps. The rigid body touches the plane through its 10 collision spheres (the
// product's half-space collider); the shape-matching grain through its 30 vertices, each
// projected back to z = 0. Shape matching is the rejected alternative and is written below
// only for this measurement, with stiffness 1 (fully rigid) and `iterations` rounds of
// (ground contact, shape match) per substep. Measured:
//   Cost        CPU time per grain-substep, N grains resting apart, serial.
//   Rest        one grain on the plane: centre drift over 1000 steps after 50 settling
//               steps, deepest contact point below z = 0 over them.
//   Drop        one grain tilted 30° about its width, lowest contact point 1 cm up, 0.5 s:
//               deepest contact point, and the largest relative change of a vertex–vertex
//               distance (rigidity).
//
// Run: cmake --build build --target bench_rigid_vs_shape_matching -j1 &&
//      build/benchmarks/bench_rigid_vs_shape_matching
// Measured (Release, -O3, 2-core 2.6 GHz x86-64; costs varied by up to 10% between runs):
//   Cost [µs per grain-substep], 1000 grains (100 grains: within 10%)
//     iterations K                     1      2      4
//     rigid body (10 contact spheres)  2.96   3.35   3.65
//     shape matching (30 vertices)     1.00   1.94   3.73
//   Rest                       drift [m]   penetration [m]
//     rigid body, K = 1, 2, 4  0           0
//     shape matching, K = 1    5.9e-11     2.4e-6
//                     K = 2    1.2e-10     1.0e-6
//                     K = 4    2.4e-10     3.4e-7
//   Drop                       penetration [m]
//     rigid body, K = 1, 2, 4  0
//     shape matching, K = 1    3.8e-4   (19% of the grain's 2 mm thickness)
//                     K = 2    1.7e-4
//                     K = 4    5.3e-5
//   Distortion: at most 1.7e-15 in every run, either model.
//
// Findings: with stiffness 1, shape matching keeps the grain as rigid as the rigid body does
// (round-off) and rests without drift, sagging into the plane by a steady 0.3–2.4 µm. What
// separates them is impact: contact and shape matching are alternating projections, and one
// corner pushed out of the plane is pulled back in by the other 29 vertices, so the landing
// corner stays 0.38 mm inside the plane at K = 1 and 53 µm (2.6% of the thickness, over the
// contact tests' 1% bound) at K = 4, where shape matching already costs as much as the rigid
// body. The rigid body shows no penetration at the end of any step, at any K. Shape matching
// is cheaper only at K = 1 (3×), and then with the cheapest contact there is (a clamp against
// z = 0, no friction, no velocity pass) against the product's full contact path. So grains
// that move rigidly stay XPBD rigid bodies.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "tests/xpbd/grain_fixtures.hpp"
#include "xpbd/solver.hpp"

namespace {

using namespace rice::xpbd;
using namespace rice::xpbd::test_support;

constexpr double kTimeStep = 1.0 / 300.0;
constexpr int kSubsteps = 10;
const Vec3 kGravity(0.0, 0.0, -9.81);

// ---- The grain ---------------------------------------------------------------------------

struct GrainShape {
  TetMesh mesh;
  SphereSet spheres;  ///< the rigid body's contact geometry
};

GrainShape grain_shape(const Vec3& corner) { return {grain_mesh(corner), grain_spheres(corner)}; }

/// Turns the grain by `angle` [rad] about the y axis through the centre of its box.
void tilt(GrainShape& grain, double angle) {
  const Vec3 centre = grain.mesh.V.colwise().mean().transpose();
  const Mat3 R = Eigen::AngleAxisd(angle, Vec3::UnitY()).toRotationMatrix();
  for (Positions* points : {&grain.mesh.V, &grain.spheres.centres})
    for (int i = 0; i < points->rows(); ++i)
      points->row(i) = (centre + R * (points->row(i).transpose() - centre)).transpose();
}

void translate(GrainShape& grain, const Vec3& offset) {
  grain.mesh.V.rowwise() += offset.transpose();
  grain.spheres.centres.rowwise() += offset.transpose();
}

/// n grains lying flat on z = 0 in a grid, 3 mm apart along x and y.
std::vector<GrainShape> resting_grains(int n) {
  const int columns = static_cast<int>(std::ceil(std::sqrt(n)));
  std::vector<GrainShape> grains;
  for (int k = 0; k < n; ++k)
    grains.push_back(grain_shape(Vec3((k % columns) * 10e-3, (k / columns) * 6e-3, 0.0)));
  return grains;
}

/// Largest | |x_i − x_j| − |X_i − X_j| | / |X_i − X_j| over vertex pairs: 0 for a rigid motion.
double distortion(const Positions& x, const Positions& rest) {
  double largest = 0.0;
  for (int i = 0; i < x.rows(); ++i)
    for (int j = i + 1; j < x.rows(); ++j) {
      const double rest_length = (rest.row(i) - rest.row(j)).norm();
      largest = std::max(largest, std::abs((x.row(i) - x.row(j)).norm() - rest_length) / rest_length);
    }
  return largest;
}

// ---- The product: XPBD rigid bodies ------------------------------------------------------

/// Rigid grains in a Model stepped by the product's Solver, serial, as in the contact tests.
/// The observers look at the first grain.
class RigidGrains {
 public:
  RigidGrains(const std::vector<GrainShape>& grains, int iterations)
      : model_(make_model(grains)), solver_(model_, settings(iterations)) {
    const Positions& V = grains.front().mesh.V;
    for (int i = 0; i < V.rows(); ++i) local_vertices_.push_back(model_.rigid_bodies.front().to_local(V.row(i).transpose()));
  }
  RigidGrains(const RigidGrains&) = delete;  // solver_ refers to model_
  RigidGrains& operator=(const RigidGrains&) = delete;

  /// Lowest point of a grain's contact geometry, its sphere union.
  static double lowest_point(const GrainShape& grain) {
    return (grain.spheres.centres.col(2) - grain.spheres.radii).minCoeff();
  }

  void step() { solver_.step(); }
  int contact_points() const { return model_.bodies.front().sphere_count(); }
  Vec3 centre() const { return model_.rigid_bodies.front().x; }
  double lowest_contact_point() const {
    const Body& body = model_.bodies.front();
    double lowest = INFINITY;
    for (int s = 0; s < body.sphere_count(); ++s)
      lowest = std::min(lowest, sphere_centre(model_, body, s).z() - body.radii[s]);
    return lowest;
  }
  /// The mesh vertices carried by the body's pose.
  Positions vertices() const {
    Positions x(local_vertices_.size(), 3);
    for (int i = 0; i < x.rows(); ++i)
      x.row(i) = model_.rigid_bodies.front().world_point(local_vertices_[i]).transpose();
    return x;
  }

 private:
  static Model make_model(const std::vector<GrainShape>& grains) {
    Model model;
    model.gravity = kGravity;
    for (const GrainShape& grain : grains) add_rigid_body(model, grain.mesh, kGrainDensity, grain.spheres);
    model.colliders.push_back(half_space(Vec3::UnitZ(), 0.0, 0.0, 0.0));
    return model;
  }
  static SolverSettings settings(int iterations) {
    return {.time_step = kTimeStep, .substeps = kSubsteps, .iterations = iterations,
            .execution = Execution::kSerial};
  }

  Model model_;
  Solver solver_;
  std::vector<Vec3> local_vertices_;
};

// ---- The rejected alternative: shape matching (MHTG05) -----------------------------------
// Written only for this measurement; nothing in the product uses it. A grain is the vertices
// of its tet mesh with lumped masses, and every vertex is a contact point.

struct ShapeMatchingGrain {
  Positions x, v;
  Positions x_previous;  ///< xⁿ, positions at the start of the substep
  Positions rest;        ///< q_i = x⁰_i − x⁰_cm (MHTG05 eq. 6)
  Eigen::VectorXd m;     ///< lumped masses [kg]
};

/// x_cm = Σ m_i x_i / Σ m_i (MHTG05 eq. 6).
Vec3 centre_of_mass(const Positions& x, const Eigen::VectorXd& m) {
  return (m.transpose() * x).transpose() / m.sum();
}

ShapeMatchingGrain make_shape_matching_grain(const TetMesh& mesh) {
  ShapeMatchingGrain grain;
  grain.m = lumped_masses(mesh.V, mesh.T, kGrainDensity);
  grain.x = grain.x_previous = mesh.V;
  grain.v = Positions::Zero(mesh.V.rows(), 3);
  grain.rest = mesh.V.rowwise() - centre_of_mass(mesh.V, grain.m).transpose();
  return grain;
}

/// The rotational part R of the polar decomposition A = R S (MHTG05 §3.3), from the SVD
/// A = U Σ Vᵀ as R = U diag(1, 1, det(U Vᵀ)) Vᵀ: the nearest rotation also when A reflects.
Mat3 rotation_of(const Mat3& A) {
  const Eigen::JacobiSVD<Mat3> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 D = Mat3::Identity();
  D(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return svd.matrixU() * D * svd.matrixV().transpose();
}

/// Moves every particle onto its goal with stiffness 1: A_pq = Σ m_i p_i q_iᵀ with
/// p_i = x_i − x_cm (MHTG05 eq. 7), R its rotation, goals g_i = R q_i + x_cm (§3.3).
void match_shape(ShapeMatchingGrain& grain) {
  const Vec3 c = centre_of_mass(grain.x, grain.m);
  Mat3 A_pq = Mat3::Zero();
  for (int i = 0; i < grain.x.rows(); ++i)
    A_pq += grain.m[i] * (grain.x.row(i).transpose() - c) * grain.rest.row(i);
  const Mat3 R = rotation_of(A_pq);
  for (int i = 0; i < grain.x.rows(); ++i)
    grain.x.row(i) = (R * grain.rest.row(i).transpose() + c).transpose();
}

/// Ground contact: every particle below the plane z = 0 is projected onto it.
void project_ground(ShapeMatchingGrain& grain) { grain.x.col(2) = grain.x.col(2).cwiseMax(0.0); }

/// One PBD substep: x̃ = x + h v + h² g, `iterations` × (contact, shape match), v = (x − xⁿ)/h.
void substep(ShapeMatchingGrain& grain, double h, int iterations) {
  grain.x_previous = grain.x;
  grain.x += h * grain.v;
  grain.x.rowwise() += (h * h * kGravity).transpose();
  for (int k = 0; k < iterations; ++k) {
    project_ground(grain);
    match_shape(grain);
  }
  grain.v = (grain.x - grain.x_previous) / h;
}

/// Shape-matching grains, with the observers of RigidGrains.
class ShapeMatchingGrains {
 public:
  ShapeMatchingGrains(const std::vector<GrainShape>& grains, int iterations)
      : iterations_(iterations) {
    for (const GrainShape& grain : grains) grains_.push_back(make_shape_matching_grain(grain.mesh));
  }

  /// Lowest point of a grain's contact geometry, its vertices.
  static double lowest_point(const GrainShape& grain) { return grain.mesh.V.col(2).minCoeff(); }

  void step() {
    for (int s = 0; s < kSubsteps; ++s)
      for (ShapeMatchingGrain& grain : grains_) substep(grain, kTimeStep / kSubsteps, iterations_);
  }
  int contact_points() const { return static_cast<int>(grains_.front().x.rows()); }
  Vec3 centre() const { return centre_of_mass(grains_.front().x, grains_.front().m); }
  double lowest_contact_point() const { return grains_.front().x.col(2).minCoeff(); }
  const Positions& vertices() const { return grains_.front().x; }

 private:
  int iterations_;
  std::vector<ShapeMatchingGrain> grains_;
};

// ---- Measurements ------------------------------------------------------------------------

/// What a run of one grain showed.
struct Observation {
  double drift = 0.0;        ///< |centre at the end − centre after settling| [m]
  double penetration = 0.0;  ///< deepest contact point below z = 0, end of a step [m]
  double distortion = 0.0;   ///< largest distortion() of the vertices, end of a step
};

/// Takes `settle` steps, then `steps` more while observing the first grain after each.
template <class Grains>
Observation observe(Grains& grains, const Positions& rest_vertices, int settle, int steps) {
  for (int k = 0; k < settle; ++k) grains.step();
  const Vec3 start = grains.centre();
  Observation seen;
  for (int k = 0; k < steps; ++k) {
    grains.step();
    seen.penetration = std::max(seen.penetration, -grains.lowest_contact_point());
    seen.distortion = std::max(seen.distortion, distortion(grains.vertices(), rest_vertices));
  }
  seen.drift = (grains.centre() - start).norm();
  return seen;
}

/// Cost: N grains at rest (argument 0) with K iterations (argument 1); one benchmark
/// iteration is one step. Counter: CPU time per grain and substep.
template <class Grains>
void BM_Cost(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Grains grains(resting_grains(n), static_cast<int>(state.range(1)));
  for (int k = 0; k < 10; ++k) grains.step();  // contacts in place before timing
  for (auto _ : state) {
    grains.step();
    benchmark::ClobberMemory();
  }
  // Grain-substeps per second of CPU time, inverted: seconds per grain-substep.
  state.counters["per_grain_substep"] = benchmark::Counter(
      n * kSubsteps, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["contact_points/grain"] = grains.contact_points();
}

/// Rest: one grain lying flat on the plane, 50 settling steps then 1000; argument: iterations.
template <class Grains>
void BM_Rest(benchmark::State& state) {
  for (auto _ : state) {
    const GrainShape grain = grain_shape(Vec3::Zero());
    Grains grains({grain}, static_cast<int>(state.range(0)));
    const Observation seen = observe(grains, grain.mesh.V, 50, 1000);
    state.counters["drift_m"] = seen.drift;
    state.counters["penetration_m"] = seen.penetration;
    state.counters["distortion"] = seen.distortion;
  }
}

/// Drop: one grain tilted 30° about y, its lowest contact point 1 cm above the plane, 150
/// steps (0.5 s: it lands at 45 ms and tips onto its face); argument: iterations.
template <class Grains>
void BM_Drop(benchmark::State& state) {
  for (auto _ : state) {
    GrainShape grain = grain_shape(Vec3::Zero());
    tilt(grain, std::numbers::pi / 6.0);
    translate(grain, Vec3(0.0, 0.0, 1e-2 - Grains::lowest_point(grain)));
    Grains grains({grain}, static_cast<int>(state.range(0)));
    const Observation seen = observe(grains, grain.mesh.V, 0, 150);
    state.counters["penetration_m"] = seen.penetration;
    state.counters["distortion"] = seen.distortion;
  }
}

const std::vector<std::int64_t> kIterations{1, 2, 4};

BENCHMARK_TEMPLATE(BM_Cost, RigidGrains)->ArgsProduct({{100, 1000}, kIterations})->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Cost, ShapeMatchingGrains)->ArgsProduct({{100, 1000}, kIterations})->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Rest, RigidGrains)->ArgsProduct({kIterations})->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Rest, ShapeMatchingGrains)->ArgsProduct({kIterations})->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Drop, RigidGrains)->ArgsProduct({kIterations})->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Drop, ShapeMatchingGrains)->ArgsProduct({kIterations})->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
