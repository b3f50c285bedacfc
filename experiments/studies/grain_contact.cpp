// The grain scenes of the contact study; see grain_contact.hpp.
#include "experiments/studies/grain_contact.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "experiments/io/item_loop.hpp"
#include "experiments/io/progress.hpp"
#include "fem_reference/implicit_solver.hpp"
#include "grains/collision_spheres.hpp"
#include "grains/grain_generator.hpp"
#include "xpbd/contact_solver.hpp"
#include "xpbd/energy.hpp"
#include "xpbd/solver.hpp"

namespace rice::experiments {
namespace {

using Clock = std::chrono::steady_clock;
using xpbd::Mat3;
using xpbd::Vec3;

/// A grain's tet mesh and density: a procedural japonica grain, or a box of a grain's size.
struct GrainBody {
  xpbd::TetMesh mesh;
  double density = 0.0;
};

GrainBody grain_body(const ContactStudySettings& s) {
  if (s.box_grain) return {xpbd::make_box_tet_mesh(Vec3(7e-3, 3e-3, 2e-3), 4, 2, 1), s.density};
  grains::GrainRecipe recipe;
  recipe.cultivar = grains::cultivar_by_name("japonica");
  const grains::Grain grain = grains::make_grain(recipe, s.grain_seed);
  return {xpbd::TetMesh{grain.simulation.V, grain.simulation.T}, grain.simulation_density};
}

double grain_length(const GrainBody& body) {
  return (body.mesh.V.colwise().maxCoeff() - body.mesh.V.colwise().minCoeff()).maxCoeff();
}

/// The rotation that lays points flat: its rows are their principal axes from the largest
/// spread to the least (right-handed), so the longest axis goes to x and the thinnest to z.
Mat3 flat_rotation(const xpbd::Positions& points) {
  const xpbd::Positions centred = points.rowwise() - points.colwise().mean();
  const Eigen::SelfAdjointEigenSolver<Mat3> axes(centred.transpose() * centred);
  Mat3 flat = axes.eigenvectors().rowwise().reverse().transpose();
  if (flat.determinant() < 0.0) flat.row(2) *= -1.0;
  return flat;
}

/// The reference for static solves of `model`, with the study's barrier.
fem::ImplicitSolver reference_solver(xpbd::Model& model, const ContactStudySettings& s) {
  return fem::ImplicitSolver(model, {.time_step = 1e-3, .newton = {.tolerance = 1e-10, .max_iterations = 300}},
                             {.activation_distance = s.barrier_distance, .stiffness = s.barrier_stiffness});
}

/// The reference's static solve of `model` in place.
void solve_reference(xpbd::Model& model, const ContactStudySettings& s) {
  if (!reference_solver(model, s).solve_static().converged)
    throw std::runtime_error("contact study: the reference's static solve did not converge");
}

/// f_i = ∂U/∂x_i − m_i g − f_ext,i − (spring force on i): what contacts hold each particle
/// with at rest (zero away from them).
xpbd::Positions contact_forces(const xpbd::Model& model) {
  xpbd::Positions f = xpbd::elastic_energy_gradient(model);
  for (int i = 0; i < model.particles.size(); ++i)
    if (model.particles.w[i] > 0.0) f.row(i) -= model.gravity.transpose() / model.particles.w[i];
  if (model.external_forces.rows() != 0) f -= model.external_forces;
  for (const xpbd::Attachment& a : model.attachments)
    f.row(a.particle) -= (a.target - model.particles.x.row(a.particle).transpose()).transpose() / a.compliance;
  return f;
}

bool any_inverted(const xpbd::Model& model) {
  const auto& x = model.particles.x;
  for (const xpbd::NeoHookeanTet& t : model.neo_hookean) {
    Mat3 Ds;
    for (int k = 0; k < 3; ++k) Ds.col(k) = (x.row(t.particles[k + 1]) - x.row(t.particles[0])).transpose();
    if (!(Ds.determinant() * t.Dm_inv.determinant() > 0.0)) return true;
  }
  return false;
}

struct Run {
  xpbd::Method method;
  int substeps, iterations;
};

std::vector<Run> runs(const ContactStudySettings& s) {
  std::vector<Run> list;
  for (const int n : s.xpbd_substeps)
    for (const int k : s.xpbd_iterations) list.push_back({xpbd::Method::kXpbd, n, k});
  for (const int n : s.vbd_substeps)
    for (const int k : s.vbd_grain_iterations) list.push_back({xpbd::Method::kVbd, n, k});
  return list;
}

/// Every run of the settings' grids for one second of 1/60 s frames from `start`; each row
/// gets its method, counts, stability and wall time here, its errors from
/// `measure(model, solver, row)` when the run stayed finite (NaN otherwise).
template <class Measure>
std::vector<GrainContactRow> run_grid(const ContactStudySettings& s, const std::string& label, const xpbd::Model& start,
                                      const Measure& measure) {
  const std::vector<Run> list = runs(s);
  std::vector<GrainContactRow> rows(list.size());
  for_each_item(label, static_cast<int>(list.size()), [&](int j) {
    GrainContactRow& r = rows[j];
    r.method = xpbd::method_name(list[j].method);
    r.substeps = list[j].substeps;
    r.iterations = list[j].iterations;
    xpbd::Model model = start;
    xpbd::Solver solver(model, {.time_step = 1.0 / 60.0, .substeps = r.substeps, .iterations = r.iterations,
                                .method = list[j].method, .execution = xpbd::Execution::kSerial});
    const auto begin = Clock::now();
    bool finite = true;
    try {
      for (int frame = 0; frame < 60; ++frame) solver.step();
    } catch (const xpbd::SimulationError&) {
      finite = false;
    }
    r.wall = seconds_since(begin);
    r.stable = finite && !any_inverted(model) && xpbd::max_speed(model.particles) < 1e-2;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    r.shape_error = r.force_error = nan;
    if (finite) measure(model, solver, r);
  });
  return rows;
}

// ---- One grain on the ground -------------------------------------------------------------

/// The body with its tets at positions x, a frictionless ground, gravity.
xpbd::Model ground_model(const ContactStudySettings& s, const GrainBody& body, const xpbd::Positions& x) {
  xpbd::Model model;
  model.particles = xpbd::make_particles(body.mesh, body.density);
  xpbd::add_neo_hookean_tets(model, body.mesh, xpbd::lame_from_young_poisson(s.young, s.poisson));
  model.particles.x = x;
  model.ground = xpbd::GroundPlane{};
  return model;
}

/// The undeformed body turned into a pose where it rests stably, its lowest point `lift` above
/// the ground: laid flat, then let the reference's static solve (a minimum of the potential,
/// so a stable pose, not a rocking one) settle it; the rotation from rest to that state is
/// fitted by Umeyama's method.
xpbd::Positions resting_pose(const ContactStudySettings& s, const GrainBody& body, double lift) {
  const xpbd::Positions centred = body.mesh.V.rowwise() - body.mesh.V.colwise().mean();
  xpbd::Positions laid = centred * flat_rotation(body.mesh.V).transpose();
  laid.col(2).array() += lift - laid.col(2).minCoeff();
  xpbd::Model model = ground_model(s, body, laid);
  solve_reference(model, s);
  const Eigen::Matrix4d fit =
      Eigen::umeyama(Eigen::Matrix3Xd(centred.transpose()), Eigen::Matrix3Xd(model.particles.x.transpose()), false);
  xpbd::Positions pose = centred * Mat3(fit.topLeftCorner<3, 3>()).transpose();
  pose.col(2).array() += lift - pose.col(2).minCoeff();
  return pose;
}

/// RMS distance between two shapes on the ground after removing what a frictionless ground
/// leaves free: a horizontal shift and a turn about the vertical (fitted in the plane).
double shape_distance_on_ground(const xpbd::Positions& a, const xpbd::Positions& b) {
  Eigen::RowVector3d ca = a.colwise().mean(), cb = b.colwise().mean();
  ca[2] = cb[2] = 0.0;
  const xpbd::Positions p = a.rowwise() - ca, q = b.rowwise() - cb;
  const double turn = std::atan2((p.col(0).array() * q.col(1).array() - p.col(1).array() * q.col(0).array()).sum(),
                                 (p.col(0).array() * q.col(0).array() + p.col(1).array() * q.col(1).array()).sum());
  const Mat3 R = Eigen::AngleAxisd(turn, Vec3::UnitZ()).toRotationMatrix();
  return std::sqrt((p * R.transpose() - q).rowwise().squaredNorm().mean());
}

// ---- Two grains pressed together ---------------------------------------------------------

/// How far to raise spheres `upper` so that each clears each of `lower` by `gap`, the upper
/// above: for a pair at horizontal distance ρ < R = r_a + r_b + gap the centres must be
/// √(R² − ρ²) apart vertically.
double lift_to_clear(const xpbd::SphereSet& upper, const xpbd::SphereSet& lower, double gap) {
  double lift = -std::numeric_limits<double>::infinity();
  for (Eigen::Index a = 0; a < upper.centres.rows(); ++a)
    for (Eigen::Index b = 0; b < lower.centres.rows(); ++b) {
      const double R = upper.radii[a] + lower.radii[b] + gap;
      const double rho2 = (upper.centres.row(a).head<2>() - lower.centres.row(b).head<2>()).squaredNorm();
      if (rho2 < R * R)
        lift = std::max(lift, lower.centres(b, 2) - upper.centres(a, 2) + std::sqrt(R * R - rho2));
    }
  return lift;
}

/// The pair scene (grain_contact.hpp) at its start: both boxes undeformed, the lower's bottom
/// face held, the upper shifted by half the sphere spacing along the length (its spheres in
/// the dips between the lower's) and lifted until each sphere gap is at least d̂/2; the load
/// on the upper box's particles, the springs at its bottom corners.
constexpr double kPairLength = 7e-3;  ///< the pair's boxes [m]

xpbd::Model pair_model(const ContactStudySettings& s) {
  constexpr double length = kPairLength, width = 3e-3, thickness = 2e-3, r = 0.5 * thickness;
  constexpr int rows = 2, per_row = 5;
  const double dx = (length - 2 * r) / (per_row - 1), dy = (width - 2 * r) / (rows - 1);
  xpbd::Model model;
  xpbd::SphereSet lower;
  for (int g = 0; g < 2; ++g) {
    const Vec3 shift = g == 0 ? Vec3::Zero() : Vec3(0.5 * dx, 0.0, 0.0);
    xpbd::TetMesh mesh = xpbd::make_box_tet_mesh(Vec3(length, width, thickness), 8, 4, 2);
    mesh.V.rowwise() += shift.transpose();
    xpbd::SphereSet spheres{xpbd::Positions(rows * per_row, 3), Eigen::VectorXd::Constant(rows * per_row, r)};
    for (int k = 0; k < per_row; ++k)
      for (int row = 0; row < rows; ++row)
        spheres.centres.row(per_row * row + k) = (shift + Vec3(r + k * dx, r + row * dy, r)).transpose();
    const double lift = g == 0 ? 0.0 : lift_to_clear(spheres, lower, 0.5 * s.barrier_distance);
    mesh.V.col(2).array() += lift;
    spheres.centres.col(2).array() += lift;
    xpbd::add_soft_body(model, mesh, s.density, xpbd::lame_from_young_poisson(s.young, s.poisson), 0.0, spheres);
    if (g == 0) lower = spheres;
  }
  std::vector<int> bottom;
  for (int i = 0; i < model.bodies[0].particle_count; ++i)
    if (model.particles.x(i, 2) == 0.0) bottom.push_back(i);
  xpbd::pin_particles(model, bottom);
  const xpbd::Body& upper = model.bodies[1];
  model.external_forces = xpbd::Positions::Zero(model.particles.size(), 3);
  for (int i = upper.first_particle; i < upper.first_particle + upper.particle_count; ++i)
    model.external_forces.row(i) = s.load * model.gravity.transpose() / model.particles.w[i];
  // The springs, at the upper box's four bottom corners, towards where they start.
  const xpbd::Positions box = model.particles.x.middleRows(upper.first_particle, upper.particle_count);
  for (int i = 0; i < upper.particle_count; ++i) {
    const Vec3 p = box.row(i).transpose();
    const bool corner = p.z() == box.col(2).minCoeff() &&
                        (p.x() == box.col(0).minCoeff() || p.x() == box.col(0).maxCoeff()) &&
                        (p.y() == box.col(1).minCoeff() || p.y() == box.col(1).maxCoeff());
    if (corner) model.attachments.push_back({upper.first_particle + i, p, 1.0 / s.spring_stiffness});
  }
  return model;
}

/// The reference's rest state of the pair: static solves from the start, each with the
/// spheres' radii of the last one's shape, until the shape moves less than 1e-6 of `length`
/// (radii only shrink under load, r₀ min(1, σ_min), so the start stays clear of every barrier).
xpbd::Model pair_reference(const ContactStudySettings& s, const xpbd::Model& start, double length) {
  xpbd::Model reference = start;
  fem::ImplicitSolver solver = reference_solver(reference, s);
  xpbd::Positions shape = start.particles.x;
  for (int pass = 0; pass < 50; ++pass) {
    reference.particles.x = start.particles.x;
    if (!solver.solve_static(&shape).converged)
      throw std::runtime_error("contact study: the reference's static solve of the grain pair did not converge");
    const double moved = (reference.particles.x - shape).rowwise().norm().maxCoeff();
    shape = reference.particles.x;
    if (moved < 1e-6 * length) return reference;
  }
  throw std::runtime_error("contact study: the grain pair's radii and shape did not settle in 50 static solves");
}

}  // namespace

std::vector<GrainContactRow> run_grain_contact(const ContactStudySettings& s) {
  validate(s);
  const GrainBody body = grain_body(s);
  const xpbd::Positions pose = resting_pose(s, body, 0.5 * s.barrier_distance);
  const double length = grain_length(body);
  xpbd::Model reference = ground_model(s, body, pose);
  solve_reference(reference, s);
  const xpbd::Positions reference_forces = contact_forces(reference);
  return run_grid(s, "contact: grain on the ground", ground_model(s, body, pose),
                  [&](const xpbd::Model& model, const xpbd::Solver&, GrainContactRow& r) {
                    r.shape_error = shape_distance_on_ground(model.particles.x, reference.particles.x) / length;
                    r.force_error = (contact_forces(model) - reference_forces).norm() / reference_forces.norm();
                  });
}

std::vector<GrainContactRow> run_grain_pair(const ContactStudySettings& s) {
  validate(s);
  const double length = kPairLength;
  const xpbd::Model start = pair_model(s);
  const xpbd::Model reference = pair_reference(s, start, length);
  const xpbd::Positions reference_forces = contact_forces(reference);
  return run_grid(s, "contact: two grains pressed", start,
                  [&](const xpbd::Model& model, const xpbd::Solver&, GrainContactRow& r) {
                    const auto n = static_cast<double>(model.particles.size());
                    r.shape_error = (model.particles.x - reference.particles.x).norm() / std::sqrt(n) / length;
                    r.force_error = (contact_forces(model) - reference_forces).norm() / reference_forces.norm();
                  });
}

}  // namespace rice::experiments
