// Cohesive bonds between sticky grains: the water-content constraint of the paper. A bond
// forms wherever a sphere of one cohesive body comes within ContactSettings::bond_distance of
// a sphere of another, and joins two anchors, the material points of either body at that
// contact, by the compliant constraint C = |A_a − A_b| − d₀ ≤ 0, d₀ the anchors' distance
// when it formed: it pulls once stretched past d₀, the contact pushes. (With d₀ = 0 a bond
// snapped its gap shut in one substep, harder than a grain weight for an 8 µm gap at
// h = 1/2400 s, and a pair forming several at once broke as it formed.) Two sleeping bodies'
// bonds carry no force. Several bonds over a contact patch also resist rolling and twisting
// (one bond alone is a ball joint: a grain hung from one swung 2.5 mm down). A body pair's bonds
// all break when their summed force Σ|λ|/h² exceeds the pair's strength, the smaller of the
// two bodies' Body::bond_strength, so that strength is the pull-off force of the pair
// whatever the number of bonds. The strength law lives in grains/water_content.
// Under vertex block descent a compliant bond between two soft bodies is instead a spring term
// of each particle's step (particle_contacts.hpp): hold_in_particle_steps hands those over,
// and take_particle_forces reads back the force that breaks them.
#pragma once

#include <array>
#include <map>
#include <vector>

#include "xpbd/model.hpp"
#include "xpbd/particle_contacts.hpp"

namespace rice::xpbd {

class StateWriter;
class StateReader;

class CohesionBonds {
 public:
  /// Two spheres within the bond distance at the start of a substep: sphere sa of body a and
  /// sphere sb of body b, with their contact points pa (on a) and pb (on b) then.
  struct Touch {
    std::array<int, 4> key;  ///< (a, b, sa, sb)
    Vec3 pa, pb;
  };
  /// One Gauss–Seidel sweep over the bonds (XPBD eq. 18 with compliance α of the settings).
  void project(Model& model, double h);
  /// Starts a substep: bonds every touch that has no bond, unless its body pair broke and has
  /// neither separated since nor touched for ContactSettings::bond_heal_time (a pair pulled
  /// apart is not glued back before it moves), and resets the multipliers. `x_previous`: the
  /// particle positions at the substep's start.
  void begin_substep(const Model& model, const std::vector<Touch>& touches, const Positions& x_previous);
  /// Adds every bond between two soft bodies, not both asleep, to `terms` as a spring of
  /// stiffness min(1/α, ContactSettings::particle_stiffness) (α > 0); project() then skips
  /// them. Call after begin_substep.
  void hold_in_particle_steps(const Model& model, ParticleContacts& terms);
  /// After the sweeps: each held bond's impulse λ = −k* C_b h² at x, for end_substep.
  void take_particle_forces(const ParticleContacts& terms, const Positions& x, double h);
  /// Breaks the body pairs whose bonds' force over the substep exceeded their strength, and
  /// counts h into how long each broken pair has touched.
  void end_substep(double h);
  int count() const { return static_cast<int>(bonds_.size()); }
  int broken() const { return broken_; }  ///< body pairs whose bonds broke
  /// For each of `bodies` bodies, how many others it is bonded to (body pairs with a bond).
  std::vector<int> bonded_neighbours(int bodies) const;
  /// Its state between steps, for checkpoints (state_archive.hpp).
  void save_state(StateWriter& out) const;
  void load_state(StateReader& in);

 private:
  struct Bond {
    std::array<int, 4> key;  ///< (a, b, sa, sb), a < b
    Vec3 anchor_a, anchor_b;  ///< material coordinates (body.hpp)
    double length;            ///< d₀ [m]
    double strength;          ///< [N]
    double lambda = 0.0;      ///< this substep's positional impulse [kg m]
    int held = -1;            ///< its index among the particle terms' bonds, when held there
  };
  void sort_bonds();
  template <class Self, class Archive>
  static void transfer_state(Self& self, Archive& archive);
  /// Sorted by key at each substep's end (a substep's new bonds are appended), so a pair's
  /// bonds are contiguous.
  std::vector<Bond> bonds_;
  /// Broken and neither separated nor healed yet: how long each has touched since [s].
  std::map<std::pair<int, int>, double> broken_pairs_;
  bool sorted_ = true;
  int broken_ = 0;
};

}  // namespace rice::xpbd
