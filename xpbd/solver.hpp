// The XPBD time stepper (Macklin, Müller & Chentanez 2016) with substepping (Macklin et al.
// 2019, "Small Steps in Physics Simulation"): each step of length Δt is split into N substeps
// of h = Δt/N; each substep predicts x̃ = x + h v + h² M⁻¹ f_ext, resets λ, runs K Gauss–Seidel
// iterations over all constraints, and sets v = (x − xⁿ)/h. Constraint kernels are stateless
// (distance_constraint.hpp, tet_volume_constraint.hpp, neo_hookean_constraints.hpp); this
// class owns the bookkeeping: multipliers, colouring, diagnostics.
//
// Strain-rate damping (strain_rate_damping.hpp) is part of the step's potential under
// Method::kVbd, and the other methods refuse a model that has it. (Applied after XPBD's
// constraint iterations by one damping sweep, operator splitting, it made a bent bar gain
// energy until it blew up at τ = 10 h: the sweep strains the elements and nothing corrects it
// within the substep. Written as a compliant per-tet constraint on the strain increment it
// would fit XPBD; not done.)
//
// The solver keeps a reference to the model and colours its constraints once, at
// construction: build a new solver after adding or removing constraints.
#pragma once

#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "xpbd/damped_update.hpp"
#include "xpbd/graph_coloring.hpp"
#include "xpbd/model.hpp"

namespace rice::xpbd {

enum class Method {
  kXpbd,  ///< compliant constraints, λ accumulated over a substep (XPBD eq. 18, 26)
  kPbd,   ///< classic PBD: stiffness k ∈ [0, 1] per projection, no λ; kept to show what XPBD fixes
  /// Vertex block descent on the Neo-Hookean tets' backward-Euler potential
  /// (vertex_block_descent.hpp): K sweeps of per-particle Newton steps, stable at substeps far
  /// past the tets' wave-crossing time. The ground, compliant attachments, and contacts of
  /// soft bodies' spheres (with each other and with colliders) with their friction and
  /// compliant bonds are terms of each particle's step; hard attachments and bonds (α = 0)
  /// and contacts with rigid bodies stay projections after each sweep; springs and tet
  /// volumes are not supported.
  kVbd,
};

/// "xpbd", "pbd" or "vbd": the method's name in the studies' tables.
constexpr const char* method_name(Method m) {
  return m == Method::kVbd ? "vbd" : m == Method::kPbd ? "pbd" : "xpbd";
}

enum class Execution {
  kSerial,    ///< plain Gauss–Seidel in constraint index order
  /// Gauss–Seidel on TBB's threads: where every tet belongs to one soft body (grains), body by
  /// body in parallel, each body's tets in index order, so the result is the serial one; else
  /// colour by colour, each colour in parallel.
  kParallel,
};

struct SolverSettings {
  double time_step = 1.0 / 60.0;  ///< Δt of one step() [s]
  int substeps = 1;               ///< N
  int iterations = 10;            ///< K per substep
  Method method = Method::kXpbd;
  Execution execution = Execution::kParallel;
  double pbd_stiffness = 1.0;     ///< k ∈ [0, 1], used by Method::kPbd only
  /// Primal-residual correction for the Neo-Hookean pair (our variant of Chen et al. 2024,
  /// "Primal residual reduction with XPBD and hyperelasticity"): each tet remembers the
  /// impulse ∇C(x)ᵀλ it last applied, and before its next projection re-applies λ along the
  /// current gradients, x += M⁻¹(∇C(x)ᵀλ − that impulse). Then M(x − x̃) always equals the sum
  /// of the stored impulses, and the primal residual g = M(x − x̃) − ∇C(x)ᵀλ vanishes at a
  /// fixed point, so a converged solve is backward Euler. Costs one more gradient per visit.
  /// Springs and volumes keep the plain update. Stable only at smaller substeps than plain
  /// XPBD (measured by `rice study convergence`).
  bool primal_correction = false;
  bool diagnostics = false;       ///< compute StepDiagnostics after every step (costs one pass)
};

/// Figures of the state at the end of a step.
struct StepDiagnostics {
  long step = 0;                      ///< index of the step these figures describe
  /// ‖C + α̃λ + γ∇C(x − xⁿ)‖₂ over the equality constraints (XPBD eq. 9 with damping): what
  /// the iterations drive to zero.
  double constraint_residual = 0.0;
  /// ‖M(x − x̃) − ∇C(x)ᵀλ‖₂ over free particles (XPBD eq. 8): XPBD assumes it stays zero; it
  /// does not for non-linear constraints (the gap to backward Euler; ground contacts, which
  /// carry no λ, also show here).
  double primal_residual = 0.0;
  double kinetic_energy = 0.0;
  double gravitational_energy = 0.0;
  double elastic_energy = 0.0;
  double max_speed = 0.0;
  double total_energy() const { return kinetic_energy + gravitational_energy + elastic_energy; }
};

/// A non-finite number met during a step; the message names the step and the constraint.
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ContactSolver;
class VertexBlockDescent;
class StateWriter;
class StateReader;

/// Wall time spent in each part of step() since the solver was built [s]; the rest of
/// `total` is prediction, constraint and contact solves, and velocity updates.
struct SolverTimings {
  double broad_phase = 0.0;   ///< candidate pairs (contact_solver.hpp)
  double narrow_phase = 0.0;  ///< contacts from candidates, each substep
  double sleeping = 0.0;      ///< sleep bookkeeping
  double total = 0.0;
  long substeps = 0;  ///< substeps solved (those of a step where all sleeps are skipped)
  double solve() const { return total - broad_phase - narrow_phase - sleeping; }
};

class Solver {
 public:
  /// Throws std::invalid_argument for settings out of range or a method the model cannot use.
  Solver(Model& model, const SolverSettings& settings);
  ~Solver();

  /// Advances the model by settings().time_step. Throws SimulationError on NaN or infinity.
  void step();

  const SolverSettings& settings() const { return settings_; }
  long steps_taken() const { return step_; }
  /// Simulated time at the start of the next step [s].
  double time() const { return step_ * settings_.time_step; }
  /// The contact solver, or null when the model has no bodies and no colliders.
  const ContactSolver* contacts() const { return contacts_.get(); }
  const SolverTimings& timings() const { return timings_; }
  /// Figures of the last step; computed only when settings().diagnostics is on.
  const StepDiagnostics& diagnostics() const { return diagnostics_; }

  /// The model's state (positions, velocities, rigid poses, sleep) and the solver's between
  /// steps (the step count, warm starts, the contacts'), for checkpoints (state_archive.hpp).
  /// load_state throws std::runtime_error when the bytes do not fit this model.
  void save_state(StateWriter& out) const;
  void load_state(StateReader& in);

 private:
  /// `end_of_interval`: the last substep before the next broad phase.
  void substep(double h, bool end_of_interval);
  /// xⁿ = x and zero multipliers for the awake particles and tets (the sleeping ones keep
  /// what mark_sleeping set); the multipliers of springs, volumes and attachments all zero.
  void start_substep_state();
  void predict(double h);
  /// Method::kVbd: keeps the prediction as y and starts from the adaptive initial guess of
  /// Chen et al. 2024: gravity's share of h² g that the particle's last acceleration
  /// showed, so a resting body is not pushed into what holds it.
  void start_vertex_block_descent(double h);
  /// Per particle and per rigid body: 1 when its body sleeps (sleeping.hpp); empty when
  /// sleeping is off. Also the awake runs, and every particle's xⁿ and multipliers as a
  /// substep's start leaves them, so that substeps touch the awake runs only.
  void mark_sleeping();
  /// Runs [first, last) of the indices 0..count−1 whose `asleep` mark is 0 (all of them for
  /// no marks).
  static std::vector<std::pair<int, int>> awake_runs(const std::vector<char>& asleep, int count);
  /// The awake runs of particles (awake_particles_) and of the body blocks' tets, and the
  /// awake blocks.
  void find_awake_runs();
  void iterate(double h);
  void project_distance(int c, double h);
  void project_volume(int c, double h);
  void project_neo_hookean(int c);
  void project_attachments(double h);
  void project_ground();
  /// Σ_c ∇C_c(x)ᵀλ_c per particle (#P by 3), the constraint forces times h².
  Positions constraint_impulses() const;
  void check_positions() const;
  template <class Project>
  void for_each_constraint(const Coloring& coloring, Project&& project);
  /// The Neo-Hookean tets' sweep: by body blocks where the model has them, else by colour.
  void project_neo_hookean_tets(double h);
  struct TetBlock;
  /// Each soft body's tets as one block, or nothing when some tet is not in one body's
  /// contiguous range (a tet of free particles, two bodies' tets interleaved).
  static std::vector<TetBlock> body_tet_blocks(const Model& model);
  [[noreturn]] void fail(const char* constraint_type, int index) const;
  template <class Self, class Archive>
  static void transfer_state(Self& self, Archive& archive);
  StepDiagnostics measure(double h) const;

  Model& model_;
  SolverSettings settings_;
  Positions x_previous_;   ///< xⁿ, positions at the start of the substep
  Positions x_predicted_;  ///< x̃ of the substep, kept only for diagnostics
  std::vector<double> lambda_distance_, lambda_volume_;
  std::vector<Vec2> lambda_neo_hookean_;  ///< (λ_D, λ_H) per tet
  /// (α̃, γ) of each tet's two constraints at the substep h_scaled_, computed when h or the
  /// tet count changes (a tet's material is fixed for the solver's life): six of a projection's
  /// ten divisions, the same numbers as it computed itself.
  std::vector<std::array<ScaledCompliance, 2>> scaled_neo_hookean_;
  double h_scaled_ = 0.0;
  /// ∇C_Dᵀλ_D + ∇C_Hᵀλ_H per tet as last applied (one column per vertex); primal correction only
  std::vector<Eigen::Matrix<double, 3, 4>> impulse_neo_hookean_;
  /// Polar rotation of each corotated tet's F, warm-started across substeps (refine_polar_rotation)
  std::vector<Eigen::Quaterniond> rotation_;
  std::vector<Vec3> lambda_attachment_;
  std::unique_ptr<ContactSolver> contacts_;
  std::unique_ptr<VertexBlockDescent> vbd_;  ///< Method::kVbd
  Positions y_;                              ///< Method::kVbd: the substep's inertial prediction
  Positions v_previous_;                     ///< Method::kVbd: velocities at the last substep's start
  std::vector<char> asleep_particle_, asleep_rigid_;
  /// The particles and the Neo-Hookean tets that may move this substep, as runs [first, last):
  /// the per-substep passes over particles and multipliers walk these, so that a sleeping body
  /// costs nothing a substep (the settled frames of a 1000-grain rice cooker, 55 grains awake,
  /// took 0.24 s with every particle copied and reset each substep, 0.18 s without).
  std::vector<std::pair<int, int>> awake_particles_, awake_tets_;
  bool all_asleep_ = false;  ///< every particle and rigid body that can move is asleep (mark_sleeping)
  SolverTimings timings_;
  Coloring coloring_distance_, coloring_volume_, coloring_neo_hookean_;
  /// A soft body's tets, [first, last) in model.neo_hookean, and its first particle.
  struct TetBlock {
    int first, last, first_particle;
  };
  std::vector<TetBlock> tet_blocks_;  ///< body_tet_blocks
  std::vector<int> awake_blocks_;     ///< the tet blocks of awake bodies (find_awake_runs)
  long step_ = 0;
  int substep_ = 0;
  StepDiagnostics diagnostics_;
};

}  // namespace rice::xpbd
