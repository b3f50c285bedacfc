// `rice study contact` (issue 12, §3): contact checked against a known answer. Hertz: a soft
// sphere of radius R (5 mm, E = 100 kPa, ν = 0.3) pressed onto a rigid plane by d = 1–5% of R
// must push back with F = (4/3) E* √R d^{3/2}, E* = E / (1 − ν²), over a contact of radius
// a = √(R d), i.e. F = (4/3) E* a³ / R.
//
// The body is the lower half of the sphere: its flat face is the sphere's plane of symmetry
// when a whole sphere is squeezed between two plates, so holding that face and lowering it by d
// is the plates' approach d per contact. Its tet mesh is CGAL's, graded towards the pole
// (grains::make_graded_mesh): edges of a given length where it touches, coarser away. For each
// depth, in increasing order:
//
//   reference         a quasi-static Newton solve with the ground as the IPC barrier
//                     (fem_reference/barrier_contact_form.hpp);
//   vertex block      dynamics to rest (1/60 s steps, the ground a constraint of each particle's
//   descent           step, xpbd/vertex_block_descent.hpp), started from the previous depth.
//
// F is the reaction on the held face, −Σ ∂U/∂z over its particles, the same for both. Two
// errors against Hertz: at the approach d, and at the contact radius a measured from the
// ground's forces on the particles. The first keeps a bias that no mesh removes (Hertz's
// approach is that of points far from the contact; here the face is at R and held, not free
// to slide); the second depends only on the field near the contact and falls as the mesh
// there refines.
//
// The grain scenes (grain_contact.hpp): a grain on the ground and two grains pressed
// together, XPBD and vertex block descent over substeps N and iterations K against the
// reference's rest shape and contact forces: what contact accuracy costs in time.
//
// Writes contact_hertz.csv, contact_hertz.png (force against depth beside Hertz; error against
// the mesh's edge at the contact), contact_grain.csv/.png, contact_pair.csv/.png and
// run_info.txt.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rice::experiments {

struct ContactStudySettings {
  double radius = 5e-3;   ///< R [m]
  double young = 1e5;     ///< E [Pa]
  double poisson = 0.3;   ///< ν
  double density = 1100;  ///< [kg/m³] (dynamics only)
  std::vector<double> depths{0.01, 0.02, 0.05};  ///< d / R, increasing
  /// Edge lengths of the half sphere's mesh at the pole, where it touches, / R: coarse to
  /// fine; the mesh grows coarser away from the pole by `grading` per unit distance.
  std::vector<double> contact_edges{0.08, 0.04, 0.02};
  double grading = 0.5;
  /// Vertex block descent runs on the coarsest this many meshes only: its Gauss–Seidel sweeps
  /// reach the static state ever more slowly as the mesh refines.
  int vbd_resolutions = 2;
  double barrier_distance = 2e-7;   ///< d̂ of the reference's barrier [m] (bounds its gap)
  double barrier_stiffness = 1e4;   ///< κ [N/m]
  int vbd_steps = 30;               ///< steps of 1/60 s per depth
  int vbd_iterations = 30;          ///< sweeps per step
  unsigned grain_seed = 3;          ///< the grain on the ground
  /// A 7 × 3 × 2 mm box of a grain's size instead of the procedural grain, whose mesh depends
  /// on the compiler (CGAL's meshing); the tests use it.
  bool box_grain = false;
  std::vector<int> xpbd_substeps{40, 80, 160, 320, 640};  ///< per 1/60 s frame
  std::vector<int> xpbd_iterations{2, 5, 20};
  std::vector<int> vbd_substeps{1, 2, 5, 10, 20};
  std::vector<int> vbd_grain_iterations{5, 20, 50};
  /// Two grains pressed together: the load on the upper grain, in its weights.
  double load = 5.0;
  /// Stiffness of each of the four springs that hold a pressed grain sideways [N/m].
  double spring_stiffness = 2.0;

  /// Two coarse resolutions and two depths, for CI (seconds).
  static ContactStudySettings quick();
};

/// One row of contact_hertz.csv.
struct HertzRow {
  std::string solver;  ///< "reference" or "vbd"
  double contact_edge = 0.0;  ///< the mesh's edge where it touches / R
  int vertices = 0, tets = 0;
  double depth = 0.0;        ///< d [m]
  double force = 0.0;        ///< F on the held face [N]
  double hertz = 0.0;        ///< (4/3) E* √R d^{3/2} [N]
  double error = 0.0;        ///< (F − Hertz) / Hertz
  double contact_radius = 0.0;   ///< a from the contact forces' second moment [m]
  double hertz_at_radius = 0.0;  ///< (4/3) E* a³ / R [N]
  double radius_error = 0.0;     ///< (F − that) / that
  double seconds = 0.0;      ///< wall time of this depth's solve
  double fastest = 0.0;      ///< vbd: fastest particle at the end [m/s]; reference: 0
};

/// Throws std::invalid_argument naming the setting that is out of range.
void validate(const ContactStudySettings& settings);

std::vector<HertzRow> run_hertz(const ContactStudySettings& settings);

void contact_study_command(const ContactStudySettings& settings, const std::filesystem::path& folder);

}  // namespace rice::experiments
