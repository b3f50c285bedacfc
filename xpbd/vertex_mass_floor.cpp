// Dykstra's alternating projections for the vertex mass floor (vertex_mass_floor.hpp). Written
// here: it is a dozen lines over a 4 x 4 solve, and none of the project's libraries offers a
// bound-constrained least-squares solver.
#include "xpbd/vertex_mass_floor.hpp"

#include <Eigen/Cholesky>

#include <stdexcept>
#include <string>

namespace rice::xpbd {
namespace {

/// The affine set {m : G m = g}, G = [1ᵀ; Xᵀ] (mass and first moment, X about the centroid so
/// that G Gᵀ is well conditioned), and its projection z − Gᵀ (G Gᵀ)⁻¹ (G z − g).
struct MassAndMoment {
  Eigen::Matrix<double, 4, Eigen::Dynamic> G;
  Eigen::Vector4d g;
  Eigen::LDLT<Eigen::Matrix4d> GGt;

  MassAndMoment(const Eigen::VectorXd& masses, const Positions& positions) : G(4, masses.size()) {
    const Eigen::RowVector3d centroid = positions.colwise().mean();
    G.row(0).setOnes();
    G.bottomRows(3) = (positions.rowwise() - centroid).transpose();
    g = G * masses;
    GGt.compute(G * G.transpose());
  }
  Eigen::VectorXd project(const Eigen::VectorXd& z) const { return z - G.transpose() * GGt.solve(G * z - g); }
};

constexpr int kMostIterations = 10000;  // a grain's 20-60 masses meet in under 100 (japonica, f = 0.5)

}  // namespace

Eigen::VectorXd floored_masses(const Eigen::VectorXd& masses, const Positions& positions, double f) {
  if (!(f >= 0.0 && f < 1.0))
    throw std::invalid_argument("vertex mass floor " + std::to_string(f) + ": expected in [0, 1)");
  if (!(masses.size() > 0 && masses.minCoeff() > 0.0 && masses.allFinite()))
    throw std::invalid_argument("vertex mass floor: every mass must be positive and finite (no pinned particle)");
  const double floor = f * masses.mean();
  if (masses.minCoeff() >= floor) return masses;
  const MassAndMoment affine(masses, positions);
  // Dykstra: y = P_box(x + p), p ← x + p − y; x = P_affine(y + q), q ← y + q − x.
  Eigen::VectorXd x = masses, p = Eigen::VectorXd::Zero(x.size()), q = p;
  for (int k = 0; k < kMostIterations; ++k) {
    const Eigen::VectorXd y = (x + p).cwiseMax(floor);
    p += x - y;
    x = affine.project(y + q);
    q += y - x;
    if (x.minCoeff() >= floor * (1.0 - 1e-9)) return x;
  }
  throw std::runtime_error("vertex mass floor " + std::to_string(f) + ": no masses above it keep the body's mass and "
                           "centre of mass (" + std::to_string(kMostIterations) + " projections)");
}

void floor_vertex_masses(Model& model, int body, double f) {
  const Body& b = model.bodies.at(static_cast<size_t>(body));
  if (b.kind != BodyKind::kSoft)
    throw std::invalid_argument("vertex mass floor: body " + std::to_string(body) + " is not soft");
  auto w = model.particles.w.segment(b.first_particle, b.particle_count);
  const Eigen::VectorXd masses = w.cwiseInverse();
  const Eigen::VectorXd floored =
      floored_masses(masses, model.particles.x.middleRows(b.first_particle, b.particle_count), f);
  if (floored != masses) w = floored.cwiseInverse();  // masses left as they were keep their inverses' bits
}

}  // namespace rice::xpbd
