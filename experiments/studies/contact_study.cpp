// The Hertz contact study; see contact_study.hpp.
#include "experiments/studies/contact_study.hpp"

#include <algorithm>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "experiments/io/gnuplot.hpp"
#include "experiments/studies/grain_contact.hpp"
#include "experiments/io/interrupt.hpp"
#include "experiments/io/item_loop.hpp"
#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/progress.hpp"
#include "experiments/io/run_info.hpp"
#include "fem_reference/implicit_solver.hpp"
#include "grains/grain_generator.hpp"
#include "grains/simulation_mesh.hpp"
#include "xpbd/energy.hpp"
#include "xpbd/solver.hpp"

namespace rice::experiments {
namespace {

using Clock = std::chrono::steady_clock;
using xpbd::Vec3;

/// Triangles between two rings of vertex indices (same angular direction), or a fan when one
/// ring is a single vertex; every triangle runs forward along `a` and backward along `b`, so
/// consecutive strips share edges in opposite directions (a consistently oriented surface).
void stitch(const std::vector<int>& a, const std::vector<int>& b, std::vector<Eigen::Vector3i>& triangles) {
  const int na = static_cast<int>(a.size()), nb = static_cast<int>(b.size());
  int i = 0, j = 0;
  while ((na > 1 && i < na) || (nb > 1 && j < nb)) {
    const bool advance_a = nb == 1 || (na > 1 && i < na && (j >= nb || (i + 1) * nb <= (j + 1) * na));
    if (advance_a) {
      triangles.emplace_back(a[i % na], a[(i + 1) % na], b[j % nb]);
      ++i;
    } else {
      triangles.emplace_back(a[i % na], b[(j + 1) % nb], b[j % nb]);
      ++j;
    }
  }
}

/// The closed surface of the lower half of the sphere of radius R centred at (0, 0, R): `rings`
/// rings of 6k vertices from the pole to the equator, then the flat face at z = R back to its
/// centre in `face_rings` rings. Outward oriented.
grains::SurfaceMesh half_sphere_surface(double R, int rings, int face_rings) {
  std::vector<Vec3> points{Vec3::Zero()};
  std::vector<std::vector<int>> sequence{{0}};
  const auto add_ring = [&](int count, const auto& place) {
    std::vector<int> ring;
    for (int j = 0; j < count; ++j) {
      ring.push_back(static_cast<int>(points.size()));
      points.push_back(place(2.0 * std::numbers::pi * j / count));
    }
    sequence.push_back(ring);
  };
  for (int k = 1; k <= rings; ++k) {
    const double alpha = 0.5 * std::numbers::pi * k / rings;  // polar angle from the pole
    add_ring(6 * k, [&](double phi) {
      return Vec3(R * std::sin(alpha) * std::cos(phi), R * std::sin(alpha) * std::sin(phi), R - R * std::cos(alpha));
    });
  }
  for (int k = face_rings - 1; k >= 1; --k)
    add_ring(6 * k, [&](double phi) {
      return Vec3(R * k / face_rings * std::cos(phi), R * k / face_rings * std::sin(phi), R);
    });
  sequence.push_back({static_cast<int>(points.size())});
  points.emplace_back(0.0, 0.0, R);
  std::vector<Eigen::Vector3i> triangles;
  for (size_t r = 0; r + 1 < sequence.size(); ++r) stitch(sequence[r], sequence[r + 1], triangles);
  grains::SurfaceMesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(points.size()), 3);
  for (size_t i = 0; i < points.size(); ++i) mesh.V.row(static_cast<Eigen::Index>(i)) = points[i].transpose();
  mesh.F.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  double volume = 0.0;
  for (size_t t = 0; t < triangles.size(); ++t) {
    mesh.F.row(static_cast<Eigen::Index>(t)) = triangles[t].transpose();
    volume += points[triangles[t][0]].dot(points[triangles[t][1]].cross(points[triangles[t][2]])) / 6.0;
  }
  if (volume < 0.0) mesh.F.col(1).swap(mesh.F.col(2));
  return mesh;
}

/// The half sphere's tet mesh graded towards the pole, where it touches the ground: edges of
/// `contact_edge` within `fine_radius` of it, growing by `grading` per unit distance beyond,
/// at most R/4. (Mesh_3 bounds circumradii: a regular tet's is √6/4 of its edge.) The surface
/// it is cut from has rings a third of that edge apart near the pole: its facets' sag from
/// the sphere, s²/8R, stays under 1e-3 of the smallest depth.
grains::VolumeMesh half_sphere_mesh(double R, double contact_edge, double fine_radius, double grading) {
  const int rings = std::max(24, static_cast<int>(std::ceil(0.5 * std::numbers::pi * R / (contact_edge / 3.0))));
  const auto circumradius = [=](const Vec3& p) {
    const double edge = contact_edge + grading * std::max(0.0, p.norm() - fine_radius);
    return std::sqrt(6.0) / 4.0 * std::min(0.25 * R, edge);
  };
  return grains::make_graded_mesh(half_sphere_surface(R, rings, 24), circumradius, 0.005 * R, {}, 7);
}

/// The half sphere as a model: held flat face, ground at z = 0, no gravity; its pole `lift`
/// above the ground.
struct HalfSphere {
  xpbd::Model model;
  std::vector<int> face;  ///< held particles
  Eigen::VectorXd face_z;  ///< their heights before loading
  int tets = 0;
};

HalfSphere make_half_sphere(const ContactStudySettings& s, const grains::VolumeMesh& mesh, double lift) {
  HalfSphere body;
  const xpbd::TetMesh tets{mesh.V, mesh.T};
  body.model.particles = xpbd::make_particles(tets, s.density);
  xpbd::add_neo_hookean_tets(body.model, tets, xpbd::lame_from_young_poisson(s.young, s.poisson));
  body.model.gravity.setZero();
  body.model.ground = xpbd::GroundPlane{};
  body.model.particles.x.col(2).array() += lift - body.model.particles.x.col(2).minCoeff();
  const double top = body.model.particles.x.col(2).maxCoeff();
  for (int i = 0; i < body.model.particles.size(); ++i)
    if (body.model.particles.x(i, 2) > top - 1e-9 * s.radius) body.face.push_back(i);
  xpbd::pin_particles(body.model, body.face);
  body.face_z.resize(static_cast<Eigen::Index>(body.face.size()));
  for (size_t k = 0; k < body.face.size(); ++k) body.face_z[k] = body.model.particles.x(body.face[k], 2);
  body.tets = static_cast<int>(mesh.T.rows());
  return body;
}

/// Lowers the held face to `by` below its start and moves the other particles down with it,
/// none below `floor`: a start near the loaded shape (a flattened cap) rather than a face
/// pushed into an undeformed body, which a barrier's line search, never crossing the
/// ground, would walk down in hundreds of Newton steps.
void lower_face(HalfSphere& body, double by, double floor) {
  auto& x = body.model.particles.x;
  const double move = (body.face_z[0] - by) - x(body.face[0], 2);
  for (int i = 0; i < x.rows(); ++i) x(i, 2) = std::max(floor, x(i, 2) + move);
  for (size_t k = 0; k < body.face.size(); ++k) x(body.face[k], 2) = body.face_z[k] - by;
}

/// −Σ ∂U/∂z over the held face: the force with which the body pushes the face up.
double face_force(const HalfSphere& body) {
  const xpbd::Positions gradient = xpbd::elastic_energy_gradient(body.model);
  double force = 0.0;
  for (const int i : body.face) force -= gradient(i, 2);
  return force;
}

/// The contact radius a from the ground's forces f_i on the particles that touch it (those
/// within `touching` of it; f_i = ∂U/∂z_i, what holds such a particle at rest): Hertz's
/// pressure p ∝ √(1 − r²/a²) has the second moment ∫p r² dA / ∫p dA = (2/5) a², so
/// a = √(5/2 Σ f_i r_i² / Σ f_i), r_i measured from the forces' centre. Unlike the approach d,
/// a is set near the contact, whatever holds the body far from it.
double contact_radius(const HalfSphere& body, double touching) {
  const xpbd::Positions gradient = xpbd::elastic_energy_gradient(body.model);
  const auto& x = body.model.particles.x;
  std::vector<int> touch;
  for (int i = 0; i < x.rows(); ++i)
    if (x(i, 2) < touching && gradient(i, 2) > 0.0) touch.push_back(i);
  double total = 0.0;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const int i : touch) {
    total += gradient(i, 2);
    centre += gradient(i, 2) * x.row(i).head<2>().transpose();
  }
  if (!(total > 0.0)) return 0.0;
  centre /= total;
  double moment = 0.0;
  for (const int i : touch) moment += gradient(i, 2) * (x.row(i).head<2>().transpose() - centre).squaredNorm();
  return std::sqrt(2.5 * moment / total);
}

double effective_modulus(const ContactStudySettings& s) { return s.young / (1.0 - s.poisson * s.poisson); }

double hertz_force(const ContactStudySettings& s, double d) {
  return 4.0 / 3.0 * effective_modulus(s) * std::sqrt(s.radius) * std::pow(d, 1.5);
}

HertzRow row(const ContactStudySettings& s, const char* solver, const HalfSphere& body, double d, double force,
             double seconds) {
  HertzRow r;
  r.solver = solver;
  r.vertices = body.model.particles.size();
  r.tets = body.tets;
  r.depth = d;
  r.force = force;
  r.hertz = hertz_force(s, d);
  r.error = (force - r.hertz) / r.hertz;
  r.contact_radius = contact_radius(body, 0.01 * d);
  r.hertz_at_radius = 4.0 / 3.0 * effective_modulus(s) * std::pow(r.contact_radius, 3) / s.radius;
  r.radius_error = (force - r.hertz_at_radius) / r.hertz_at_radius;
  r.seconds = seconds;
  return r;
}

std::vector<HertzRow> reference_rows(const ContactStudySettings& s, const grains::VolumeMesh& mesh) {
  // The pole starts d̂/2 above the ground (the barrier is infinite on it); the face is lowered
  // by that much more than d, so that d is counted from first touch.
  const double gap = 0.5 * s.barrier_distance;
  HalfSphere body = make_half_sphere(s, mesh, gap);
  fem::ImplicitSolver solver(body.model, {.time_step = 1e-3, .newton = {.tolerance = 1e-9, .max_iterations = 300}},
                             {.activation_distance = s.barrier_distance, .stiffness = s.barrier_stiffness});
  std::vector<HertzRow> rows;
  for (const double depth : s.depths) {
    stop_point();
    const double d = depth * s.radius;
    lower_face(body, d + gap, gap);
    const auto start = Clock::now();
    const fem::NewtonReport report = solver.solve_static();
    rows.push_back(row(s, "reference", body, d, report.converged ? face_force(body) : std::nan(""),
                       seconds_since(start)));
  }
  return rows;
}

std::vector<HertzRow> vbd_rows(const ContactStudySettings& s, const grains::VolumeMesh& mesh) {
  HalfSphere body = make_half_sphere(s, mesh, 0.0);
  xpbd::Solver solver(body.model, {.time_step = 1.0 / 60.0, .iterations = s.vbd_iterations,
                                   .method = xpbd::Method::kVbd, .execution = xpbd::Execution::kSerial});
  std::vector<HertzRow> rows;
  for (const double depth : s.depths) {
    stop_point();
    const double d = depth * s.radius;
    lower_face(body, d, 0.0);
    const auto start = Clock::now();
    for (int step = 0; step < s.vbd_steps; ++step) solver.step();
    HertzRow r = row(s, "vbd", body, d, face_force(body), seconds_since(start));
    r.fastest = body.model.particles.v.rowwise().norm().maxCoeff();
    rows.push_back(r);
  }
  return rows;
}

}  // namespace

ContactStudySettings ContactStudySettings::quick() {
  ContactStudySettings s;
  s.depths = {0.05, 0.1};
  s.contact_edges = {0.16, 0.08};  // both meshes refined to the deepest depth's contact
  s.vbd_steps = 15;
  s.xpbd_substeps = {80, 320};
  s.xpbd_iterations = {5};
  s.vbd_substeps = {1, 10};
  s.vbd_grain_iterations = {20};
  return s;
}

void validate(const ContactStudySettings& s) {
  if (!(s.radius > 0.0) || !(s.young > 0.0) || !(s.poisson > -1.0 && s.poisson < 0.5) || !(s.density > 0.0))
    throw std::invalid_argument("contact study: need radius, young, density > 0 and -1 < poisson < 0.5");
  if (s.depths.empty() || !std::is_sorted(s.depths.begin(), s.depths.end()) || !(s.depths.front() > 0.0) ||
      !(s.depths.back() < 0.5))
    throw std::invalid_argument("contact study: depths must be increasing fractions of the radius in (0, 0.5)");
  if (s.contact_edges.empty())
    throw std::invalid_argument("contact study: give at least one contact edge");
  for (const double e : s.contact_edges)
    if (!(e >= 0.005 && e <= 0.25)) throw std::invalid_argument("contact study: contact edges must be in [0.005, 0.25] R");
  if (!(s.grading > 0.0 && s.grading <= 2.0)) throw std::invalid_argument("contact study: grading must be in (0, 2]");
  if (!(s.barrier_distance > 0.0) || !(s.barrier_stiffness > 0.0) ||
      !(s.barrier_distance < 0.5 * s.depths.front() * s.radius))
    throw std::invalid_argument("contact study: the barrier's d-hat must be positive and under half the smallest depth");
  if (!(s.load >= 0.0 && s.load <= 1000.0) || !(s.spring_stiffness > 0.0))
    throw std::invalid_argument("contact study: the load must be in [0, 1000] weights and the springs' stiffness > 0");
  if (s.vbd_steps < 1 || s.vbd_iterations < 1)
    throw std::invalid_argument("contact study: vbd steps and iterations must be >= 1");
  for (const auto* list : {&s.xpbd_substeps, &s.xpbd_iterations, &s.vbd_substeps, &s.vbd_grain_iterations})
    for (const int n : *list)
      if (n < 1 || n > 10000) throw std::invalid_argument("contact study: substep and iteration counts must be in [1, 10000]");
}

std::vector<HertzRow> run_hertz(const ContactStudySettings& s) {
  validate(s);
  std::vector<grains::VolumeMesh> meshes(s.contact_edges.size());
  for_each_item("contact: half-sphere meshes", static_cast<int>(meshes.size()),
                [&](int r) { meshes[r] = half_sphere_mesh(s.radius, s.contact_edges[r] * s.radius,
                                                         1.2 * s.radius * std::sqrt(s.depths.back()), s.grading); });
  std::vector<std::vector<HertzRow>> parts(2 * meshes.size());
  for_each_item("contact: Hertz solves", static_cast<int>(parts.size()), [&](int job) {
    const grains::VolumeMesh& mesh = meshes[job / 2];
    if (job % 2 == 0)
      parts[job] = reference_rows(s, mesh);
    else if (job / 2 < s.vbd_resolutions)
      parts[job] = vbd_rows(s, mesh);
  });
  std::vector<HertzRow> rows;
  for (size_t job = 0; job < parts.size(); ++job)
    for (HertzRow r : parts[job]) {
      r.contact_edge = s.contact_edges[job / 2];
      rows.push_back(r);
    }
  return rows;
}

namespace {

/// Runs the Hertz part and writes contact_hertz.csv and its plot.
void hertz_outputs(const ContactStudySettings& s, const std::filesystem::path& folder) {
  const std::vector<HertzRow> rows = run_hertz(s);
  CsvTable table({"solver", "contact_edge_rel", "vertices", "tets", "depth_rel", "depth_m", "force_n", "hertz_n",
                  "rel_error", "contact_radius_m", "hertz_at_radius_n", "radius_rel_error", "seconds",
                  "fastest_m_per_s"});
  std::printf("\n%-9s %6s %8s %7s %12s %12s %9s %10s %9s %8s\n", "solver", "edge/R", "vertices", "d/R", "F [N]",
              "Hertz(d)", "error(d)", "a [mm]", "error(a)", "wall [s]");
  for (const HertzRow& r : rows) {
    table.add_row({r.solver, cell(r.contact_edge), cell(r.vertices), cell(r.tets), cell(r.depth / s.radius),
                   cell(r.depth), cell(r.force), cell(r.hertz), cell(r.error), cell(r.contact_radius),
                   cell(r.hertz_at_radius), cell(r.radius_error), cell(r.seconds), cell(r.fastest)});
    std::printf("%-9s %6.3f %8d %7.3f %12.4e %12.4e %8.1f%% %10.4f %8.1f%% %8.2f\n", r.solver.c_str(), r.contact_edge,
                r.vertices, r.depth / s.radius, r.force, r.hertz, 100.0 * r.error, 1e3 * r.contact_radius,
                100.0 * r.radius_error, r.seconds);
  }
  write_file_atomically(folder / "contact_hertz.csv", table.text());
  // The finding: the reference's largest error against Hertz at the measured contact radius on
  // the coarsest and the finest mesh, and how far the two solvers are apart.
  const auto worst = [&](double edge) {
    double e = 0.0;
    for (const HertzRow& r : rows)
      if (r.solver == "reference" && r.contact_edge == edge) e = std::max(e, std::abs(r.radius_error));
    return fixed(100.0 * e, 1) + "%";
  };
  double apart = 0.0;
  for (const HertzRow& a : rows)
    for (const HertzRow& b : rows)
      if (a.solver == "reference" && b.solver == "vbd" && a.contact_edge == b.contact_edge && a.depth == b.depth)
        apart = std::max(apart, std::abs(b.force - a.force) / a.force);
  const std::string title = "Reference force against Hertz at its contact radius: within " +
                            worst(s.contact_edges.front()) + " (edge " + fixed(s.contact_edges.front(), 3) +
                            " R) to " + worst(s.contact_edges.back()) + " (edge " + fixed(s.contact_edges.back(), 3) +
                            " R); VBD within " + fixed(100.0 * apart, 1) + "% of it";
  std::printf("\n%s\n", title.c_str());
  render_plot(folder, "contact_hertz", csv_plot_header("contact_hertz", 1400, 600) +
                                           "set multiplot layout 1,2 title '" + title + "'\n" + kLogLogAxes + R"(set xlabel 'depth d [m]'
set ylabel 'force on the held face [N]'
set key top left
E = )" + cell(effective_modulus(s)) + R"(
R = )" + cell(s.radius) + R"(
hertz(d) = 4.0/3.0 * E * sqrt(R) * d**1.5
plot 'contact_hertz.csv' using (strcol(1) eq 'reference' ? $6 : 1/0):7:2 with points pt 7 ps 1.3 palette title 'reference (colour: edge / R)', \
     '' using (strcol(1) eq 'vbd' ? $6 : 1/0):7:2 with points pt 6 ps 2 palette title 'vertex block descent', \
     '' using 6:(hertz($6)) with lines lw 2 lc rgb 'black' title 'Hertz'
set xlabel 'mesh edge where the sphere touches / R'
set ylabel 'force error against Hertz'
set xrange [*:*] reverse
set key top right
plot 'contact_hertz.csv' using (strcol(1) eq 'reference' ? $2 : 1/0):(abs($12)):(sprintf('%.0f%%', 100*$5)) with labels point pt 7 offset 2,0 title 'reference, at its contact radius a (labels: d/R)', \
     '' using (strcol(1) eq 'vbd' ? $2 : 1/0):(abs($12)) with points pt 6 ps 2 title 'vertex block descent, at a', \
     '' using (strcol(1) eq 'reference' ? $2 : 1/0):(abs($9)) with points pt 4 ps 1.2 lc rgb 'gray40' title 'reference, at the approach d (held-face bias)'
unset multiplot
)");
}

/// Writes a grain scene's rows as `name`.csv and its plot: shape and contact-force errors
/// against wall time; the title names the cheapest stable run of each method within 1% of
/// the reference's rest shape.
void grain_outputs(const std::vector<GrainContactRow>& rows, const std::filesystem::path& folder,
                   const std::string& name, const std::string& scene) {
  CsvTable table({"method", "substeps", "iterations", "h_s", "stable", "shape_error_rel", "force_error_rel",
                  "wall_s_per_sim_s"});
  std::printf("\n%s against the reference rest state\n%-5s %5s %3s %7s %12s %12s %10s\n", scene.c_str(), "", "N",
              "K", "stable", "shape/len", "force", "wall [s/s]");
  for (const GrainContactRow& r : rows) {
    table.add_row({r.method, cell(r.substeps), cell(r.iterations), cell(1.0 / (60.0 * r.substeps)),
                   cell(r.stable ? 1 : 0), cell(r.shape_error), cell(r.force_error), cell(r.wall)});
    std::printf("%-5s %5d %3d %7s %12.3e %12.3e %10.4f\n", r.method.c_str(), r.substeps, r.iterations,
                r.stable ? "yes" : "NO", r.shape_error, r.force_error, r.wall);
  }
  write_file_atomically(folder / (name + ".csv"), table.text());
  const auto cheapest = [&](const char* method) {
    const GrainContactRow* best = nullptr;
    for (const GrainContactRow& r : rows)
      if (r.method == method && r.stable && r.shape_error < 1e-2 && (!best || r.wall < best->wall)) best = &r;
    if (!best) return std::string(method) + " never";
    return std::string(method) + " at N = " + std::to_string(best->substeps) + ", K = " + std::to_string(best->iterations) +
           " (" + fixed(best->wall, 3) + " s/s)";
  };
  const std::string title =
      scene + " within 1% of the reference rest shape: " + cheapest("xpbd") + ", " + cheapest("vbd");
  std::printf("%s\n", title.c_str());
  render_plot(folder, name, csv_plot_header(name, 1400, 600) + "set multiplot layout 1,2 title '" + title + "'\n" +
                                kLogLogAxes + R"(set xlabel 'wall time per simulated second [s]'
set cblabel 'log2 substeps per frame'
set key bottom left
do for [col in '6 7'] {
  set ylabel (col eq '6' ? 'RMS distance to the reference rest shape / grain length' : '|f − f_{ref}| / |f_{ref}| (contact forces)')
  plot ')" + name + R"(.csv' using (strcol(1) eq 'xpbd' && $5 == 1 ? $8 : 1/0):(column(col+0)):(log($2)/log(2)) with points pt 7 ps 1.4 palette title 'XPBD (stable runs)', \
       '' using (strcol(1) eq 'vbd' && $5 == 1 ? $8 : 1/0):(column(col+0)):(log($2)/log(2)) with points pt 5 ps 1.4 palette title 'vertex block descent'
}
unset multiplot
)");
}

}  // namespace

void contact_study_command(const ContactStudySettings& s, const std::filesystem::path& folder) {
  validate(s);
  make_output_folder(folder);
  const auto start = Clock::now();
  hertz_outputs(s, folder);
  stop_point();
  grain_outputs(run_grain_contact(s), folder, "contact_grain", "Grain on the ground");
  stop_point();
  grain_outputs(run_grain_pair(s), folder, "contact_pair", "Two grains pressed");
  stop_point();
  write_file_atomically(folder / "run_info.txt",
                        run_info({{"study", "contact"},
                                  {"radius_m", cell(s.radius)},
                                  {"young_pa", cell(s.young)},
                                  {"poisson", cell(s.poisson)},
                                  {"barrier_distance_m", cell(s.barrier_distance)},
                                  {"barrier_stiffness_n_per_m", cell(s.barrier_stiffness)},
                                  {"vbd_steps", cell(s.vbd_steps)},
                                  {"vbd_iterations", cell(s.vbd_iterations)},
                                  {"pair_load_weights", cell(s.load)},
                                  {"spring_stiffness_n_per_m", cell(s.spring_stiffness)},
                                  {"wall_s", cell(seconds_since(start))}}));
  std::printf("wall time %.1f s\n", seconds_since(start));
}

}  // namespace rice::experiments
