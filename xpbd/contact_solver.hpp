// Contact between bodies (body.hpp) and against colliders (collider.hpp) as XPBD inequality
// constraints with Coulomb friction at position level.
//
// Every ContactSettings::broad_phase_interval, a broad phase (broad_phase.hpp) over body boxes
// padded by the distance each body can move until the next (motion_bound) gives body pairs,
// each with its candidate sphere pairs (or sphere–collider pairs). At the start of every
// substep a body pair whose spheres' boxes lie further apart than the two bodies move in the
// substep is skipped whole (may_touch); otherwise each candidate whose gap at the substep's
// start is smaller than the distance its two sides can move in the substep becomes a contact
// with a normal n fixed from the start positions (a speculative contact): the half-space
// constraint
//   C = n·(c_a − c_b) − (r_a + r_b) ≥ 0   (against a collider: C = n·(c_a − q) − r_a ≥ 0)
// cannot be crossed however fast the bodies move, so nothing tunnels. Each Gauss–Seidel
// sweep projects C with mass weighting (α = 0, MMCJK20 eq. 2–5) and then friction: the
// relative tangential displacement of the contact points over the substep, d_t, is cancelled
// by a tangential positional impulse (Macklin et al. 2014 eq. 24 written with accumulated
// multipliers), capped at μ_k λ_n while the two bodies slide. While they stick, friction
// instead pulls together two anchors, the material points of either side that touched when
// sticking began, so that what one Gauss–Seidel sweep leaves over does not add up into creep;
// they start to slide when the net friction impulse of their contacts over a broad-phase
// interval exceeds μ_s Σλ_n (end_substep). A sticking contact keeps its anchors through a
// substep off the surface; back on it, friction takes back the slip of that flight up to
// μ_k λ_n (else a sphere chattering at the substep rate slides without friction); what it
// could not take back has slid, and the anchors start again there.
// Normals are projected for all contacts before friction, so friction sees the sweep's normal
// impulses. After the velocity update, contacts that pushed lose their relative normal
// velocity (restitution 0). Cohesive bonds (cohesion_bonds.hpp) form at touching contacts of
// sticky bodies and are projected after the normals.
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "xpbd/broad_phase.hpp"
#include "xpbd/cohesion_bonds.hpp"
#include "xpbd/model.hpp"
#include "xpbd/particle_contacts.hpp"

namespace rice::xpbd {

struct ContactStatistics {
  int candidates = 0;           ///< sphere pairs and sphere–collider pairs from the broad phase
  int contacts = 0;             ///< speculative contacts of the last substep
  int states = 0;               ///< contact states carried into the next substep (anchors, sliding, sums)
  double max_penetration = 0.0;  ///< largest −C over them at the end of the last substep [m]
  int bonds = 0;                 ///< cohesive bonds holding
  int bonds_broken = 0;          ///< body pairs whose bonds broke, since the start
  /// Mean force each collider took from the grains over the last broad-phase interval, in the
  /// model's collider order: −Σ (λ_n n + friction impulse) / h over its contacts and the
  /// interval's substeps, divided by the interval's length [N]. At rest, the load on it (a
  /// plate's squeezing force, a mould's pressing force); a mean, since a soft grain rings.
  std::vector<Vec3> collider_forces;
};

class ContactSolver {
 public:
  /// Validates the colliders and the contact settings (std::invalid_argument). `parallel`:
  /// per-body work (sphere centres) runs on TBB's threads; the results do not depend on it.
  explicit ContactSolver(Model& model, bool parallel = false);

  /// Broad phase for the interval [time, time + span] of one or more substeps; call before
  /// their prediction.
  void find_candidates(double time, double span);
  /// Contacts for the substep [time, time + h]; call after prediction, with the positions at
  /// the substep's start.
  void begin_substep(double time, double h, const Positions& x_previous);
  /// One Gauss–Seidel sweep over the contacts: all normals, then all frictions.
  void project(const Positions& x_previous);
  /// After the velocity update: removes the relative normal velocity of every contact that
  /// pushed in this substep (restitution 0). Call after end_substep, with the positions it saw.
  void solve_velocities();
  /// Records which body pairs slide, for the next substep's friction coefficient, and the
  /// statistics; call after the last sweep of a substep, saying whether it ends the
  /// broad-phase interval (where sticking pairs are checked against the friction cone).
  void end_substep(bool end_of_interval);

  const ContactStatistics& statistics() const { return statistics_; }
  /// For each body, how many others it is bonded to (all zero without cohesion).
  std::vector<int> bonded_neighbours() const {
    const int bodies = static_cast<int>(model_.bodies.size());
    return bonds_ ? bonds_->bonded_neighbours(bodies) : std::vector<int>(bodies, 0);
  }
  /// Whether the last broad phase found no body pair that may touch.
  bool no_candidates() const { return body_pairs_.empty(); }

  /// Vertex block descent: contacts of soft bodies' spheres with each other and with colliders,
  /// their friction, and compliant bonds between soft bodies become terms of each particle's
  /// step (particle_contacts.hpp) from the next substep on, instead of projections; contacts
  /// and bonds with rigid bodies stay projections.
  void hold_in_particle_steps() { particle_steps_ = true; }
  const ParticleContacts& particle_contacts() const { return particle_contacts_; }
  /// After each sweep: takes the force each particle contact pushes with, max(0, λ − k C), and
  /// its friction force as its impulses (times h²) for velocities and statistics, and lags the
  /// friction bounds μ f_n for the next sweep. (The multiplier step is taken at the substep's
  /// end, in end_substep.)
  void update_particle_contacts();

  /// Its state between steps, for checkpoints (state_archive.hpp).
  void save_state(StateWriter& out) const;
  void load_state(StateReader& in);

 private:
  /// What a sphere pair's contact carries from substep to substep, while its body pair stays
  /// in the broad phase: sphere s_a of body a against sphere s_b of body b, or against the
  /// collider collider_index(b) when is_collider(b). Sorted by key, so the states of one body
  /// pair are contiguous.
  struct ContactState {
    std::array<int, 4> key;  ///< (a, b, s_a, s_b)
    bool sliding = false;
    bool anchored = false;  ///< sticking, with anchors (material coordinates on a and b)
    bool flown = false;     ///< anchored, and off the surface for a substep since
    Vec3 anchor_a = Vec3::Zero(), anchor_b = Vec3::Zero();
    double interval_normal = 0.0;             ///< Σλ_n over the interval's substeps so far
    Vec3 interval_friction = Vec3::Zero();    ///< Σ friction impulses over them
    double particle_force = 0.0;  ///< held in particle steps: its force λ at the last substep's end [N]
    Vec3 friction_force = Vec3::Zero();  ///< held in particle steps: its friction force λ_t then [N]
  };
  /// A body pair from the broad phase (or a body and a collider, b < 0) with its candidate
  /// sphere pairs (s_a, s_b), sphere_pairs_[first, last), increasing; or, for two bodies whose
  /// reach holds more sphere pairs than they have spheres (fast ones: a falling clump's grains
  /// paired 4600 sphere pairs a grain), first = last = kEachSubstep: its sphere pairs are found
  /// in each substep its boxes may touch, within the substep's motion (add_contacts).
  struct BodyPair {
    int a, b, first, last;
    bool each_substep() const { return first == kEachSubstep; }
  };
  static constexpr int kEachSubstep = -1;
  static int collider_key(int collider) { return -1 - collider; }
  static bool is_collider(int b) { return b < 0; }
  static int collider_index(int b) { return -1 - b; }
  /// One body's side of a contact, as the sweeps need it: the body and its sphere s, the
  /// sphere's radius, whether the body sleeps and, soft, the sphere's anchor, taken when the
  /// contact is made (none changes within a substep), so that the sweeps read them in contact
  /// order (looked up from the state's key through the body each time, the anchor's loads were
  /// 62% of sphere_centre's samples in a settling pile of 3400). The body operations of
  /// body.hpp for this side, a soft side's on its anchor:
  struct Side {
    const Body* body = nullptr;
    const SphereAnchor* anchor = nullptr;  ///< soft only
    double radius = 0.0;
    int s = 0;
    bool asleep = false;
    Vec3 centre(const Model& model) const;
    Vec3 previous_point(const Model& model, const Vec3& point, const Positions& x_previous) const;
    double inverse_mass(const Model& model, const Vec3& point, const Vec3& n) const;
    void apply_impulse(Model& model, const Vec3& point, const Vec3& p) const;
    Vec3 velocity(const Model& model, const Vec3& point) const;
    void apply_velocity_impulse(Model& model, const Vec3& point, const Vec3& p) const;
    /// material_point and material_coordinates, now with the sphere's centre c at hand (a
    /// soft body's are c plus or minus, without summing the anchor again), or at x_previous.
    Vec3 material_point(const Model& model, const Vec3& c, const Vec3& coordinates) const;
    Vec3 coordinates_now(const Model& model, const Vec3& c, const Vec3& point) const;
    Vec3 coordinates_then(const Model& model, const Vec3& point, const Positions& x_previous) const;
  };
  struct Contact {
    int state;  ///< index into states_
    Vec3 normal;          ///< world (sphere pair) or collider frame
    Vec3 collider_point;  ///< collider frame: the surface point under the sphere at the start
    double lambda_normal = 0.0, lambda_tangent = 0.0;
    Vec3 friction = Vec3::Zero();  ///< sum of the friction impulses this substep
    bool capped = false;  ///< sliding friction reached μ_k λ_n in the last sweep
    int particle_contact = -1;  ///< index in particle_contacts_ when held in particle steps
    std::array<Side, 2> sides{};  ///< a's, and b's when b is a body
  };
  /// A contact's normal (world) and points at the current positions: p_a on a's sphere,
  /// p_b on b's sphere or on the collider, where that collider point was at the start.
  /// c_a, c_b: the two spheres' centres (c_b: b a body), kept so that a soft body's material
  /// points (its centre plus the coordinates) need not sum the embedding again.
  struct ContactPoints {
    const Side* a = nullptr;
    const Side* b = nullptr;  ///< null for a collider
    Vec3 n, ca, cb, pa, pb, pb_start = Vec3::Zero();
  };
  /// Side `body`'s sphere s, for a contact made now.
  Side side(int body, int s) const;

  /// The broad phase's steps (find_candidates): candidate sphere pairs of bodies and the
  /// colliders in motion (`moving_ones`; which grows the box padding `pad` of each body one
  /// reaches by how far it moves there), of overlapping body boxes, and of bodies and the
  /// colliders at rest, all appended to sphere_pairs_; and the contact states of body pairs
  /// still in reach.
  std::vector<BodyPair> body_candidates(const std::vector<std::pair<int, int>>& pairs, const std::vector<double>& pad);
  void add_collider_candidates(double time, double span, std::vector<double>& pad, std::vector<BodyPair>& found,
                               bool moving_ones);
  void keep_states_in_reach();
  /// Whether every sphere in `box` is farther than `reach` from the collider at rest in `pose`.
  static bool out_of_reach(const Collider& collider, const ColliderKeyframe& pose, const Box& box, double reach);
  /// The spheres s of `body` whose centre (in `centres`) is within `reach` + r_s of `box`, increasing.
  void spheres_near(int body, const std::vector<Vec3>& centres, const Box& box, double reach,
                    std::vector<int>& near) const;
  ContactPoints locate(const Contact& contact) const;
  double inverse_mass(const ContactPoints& p, const Vec3& direction) const;
  void push(const ContactPoints& p, const Vec3& impulse);
  Vec3 tangential_slip(const ContactPoints& p, const Positions& x_previous) const;
  Vec3 anchored_slip(ContactState& state, const ContactPoints& p, const Positions& x_previous) const;
  void restart_anchors(ContactState& state, const ContactPoints& p) const;
  /// end_substep for the contacts of one body pair, from `first`: their statistics (the
  /// deepest penetration so far, collider impulses), interval sums and whether the pair
  /// slides; returns the index past its last contact.
  size_t end_pair_substep(size_t first, bool end_of_interval, double& deepest);
  /// How far any point of body b can move in `span` seconds from `time`, with leeway for what
  /// contacts add: 1.5 s span + ½ |g| span², s the speed of its fastest point (rigid:
  /// |v| + |ω| r_max; soft: of its sphere centres since the last broad phase, at the first or
  /// when it was asleep then (`woken`) the fastest particle's). A sleeping body does not move.
  double motion_bound(int b, double time, double span, bool woken) const;
  /// function(k) for k in [0, count), on TBB's threads when parallel_.
  template <class Function>
  void for_each_body(int count, const Function& function) const;
  /// Sphere centres of body b now and at the substep's start (x_previous; null when they are
  /// the same), its radii when `radii`, and its start box and largest sphere motion. A sleeping
  /// body's centres are computed once per sleep.
  void update_centres(int b, const Positions* x_previous, bool radii);
  /// False when no sphere pair of the body pair can touch in this substep: the boxes of their
  /// start spheres are further apart than the two bodies' motion and the margin (the sphere
  /// test in add_contacts would then skip every one of them).
  bool may_touch(const BodyPair& pair) const;
  /// The contacts of one body pair in this substep, in key order; state_of(key) gives each
  /// its state's index.
  template <class StateOf>
  void add_contacts(const BodyPair& pair, StateOf& state_of, std::vector<CohesionBonds::Touch>& touches);
  void project_normal(Contact& contact);
  /// The particle-step form of a contact between soft spheres or a soft sphere and a collider.
  ParticleContact make_particle_contact(const Contact& contact, const Positions& x_previous) const;
  /// μ_s and μ_k against b: the collider's, or those between grains.
  double static_friction(int b) const {
    return is_collider(b) ? model_.colliders[collider_index(b)].static_friction : model_.contact.static_friction;
  }
  double dynamic_friction(int b) const {
    return is_collider(b) ? model_.colliders[collider_index(b)].dynamic_friction : model_.contact.dynamic_friction;
  }
  void project_friction(Contact& contact, const Positions& x_previous);
  void update_bonds();
  template <class Self, class Archive>
  static void transfer_state(Self& self, Archive& archive);

  Model& model_;
  bool parallel_;
  std::vector<BodyPair> body_pairs_;
  std::vector<Vec3> substep_impulses_;   ///< on each collider this substep [N s]
  std::vector<Vec3> collider_impulses_;  ///< on each collider since the interval began [N s]
  double interval_time_ = 0.0;           ///< its length so far [s]
  std::vector<std::array<int, 2>> sphere_pairs_;
  std::array<std::vector<int>, 2> near_;  ///< add_contacts' spheres near the other body, kept for their memory
  std::vector<ContactState> states_;
  std::vector<ContactState> previous_states_;  ///< begin_substep's merge: the last substep's states
  std::vector<int> sphere_offset_;                ///< first sphere of each body in the arrays below
  std::vector<Vec3> centre_now_, centre_start_;  ///< sphere centres after prediction and at the substep's start
  std::vector<Vec3> centre_at_broad_phase_;  ///< sphere centres at the last broad phase
  double broad_phase_time_ = INFINITY;        ///< its time (none yet: ∞)
  std::vector<double> radius_;  ///< sphere radii (sphere_radius), held for a radius_interval
  double radii_time_ = -INFINITY;  ///< when radius_ was last updated (ContactSettings::radius_interval)
  double radius(int body, int s) const { return radius_[sphere_offset_[body] + s]; }
  std::vector<Box> start_box_;           ///< per body: the box of its spheres at the substep's start
  std::vector<double> motion_;           ///< per body: its largest sphere-centre motion in the substep
  std::vector<char> centres_at_rest_;    ///< per body: asleep, with its centres computed
  std::vector<int> active_bodies_;       ///< bodies with candidates, increasing
  std::vector<Contact> contacts_;
  /// Each contact located at the substep's end positions (end_substep), which solve_velocities
  /// does not move: located once for both.
  std::vector<ContactPoints> located_;
  std::vector<ColliderKeyframe> pose_start_, pose_end_;  ///< collider poses at the substep's ends
  std::vector<char> present_;  ///< whether each collider is there in the substep
  ContactStatistics statistics_;
  bool has_friction_ = false;
  std::optional<CohesionBonds> bonds_;  ///< only when cohesion is on
  double h_ = 0.0;  ///< the current substep's length
  bool particle_steps_ = false;
  ParticleContacts particle_contacts_;
  std::vector<int> body_of_particle_;  ///< the soft body each particle belongs to, or −1
};

}  // namespace rice::xpbd
