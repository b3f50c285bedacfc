// A dropped clump's impact (paper Fig. 10), from the time it is let go: on for the clump
// emitter (from the start) and for grains filled into a cup that is then taken away from under
// them (from its removal; scene_parts.hpp, drop_time), off and free otherwise:
//  - rebound: for each grain, the most its centre rose above the lowest point it had reached,
//    h_g = max_t (z_g(t) − min_{s≤t} z_g(s)); the mean over the grains;
//  - deformation, soft grains only: each frame, the mean over the grains' tets (by rest volume)
//    of the largest principal strain max_i |σ_i(F) − 1|, F = D_s D_m⁻¹ and σ_i its singular
//    values; the largest over the frames, and its frame.
// Both are sampled once a frame: the impact of one grain lasts about a grain's length over the
// speed of sound in it (5 mm / 10 m/s = 0.5 ms), far under a frame, so the deformation is the
// largest a frame saw while the clump lands and settles, not the peak of a single impact.
#pragma once

#include <vector>

#include "experiments/scene/observer.hpp"

namespace rice::experiments {

class ImpactObserver : public Observer {
 public:
  /// Watches from `drop_time` [s] on.
  explicit ImpactObserver(double drop_time) : drop_time_(drop_time) {}
  void begin(const World& world) override;
  void observe(const World& world, const Stepper& stepper, int frame, double wall_seconds) override;
  void end(const World& world, const Stepper& stepper, SceneReport& report) override;
  /// The lowest and rebound heights and the peak strain so far.
  void save_state(xpbd::StateWriter& out) const override;
  void load_state(xpbd::StateReader& in) override;

 private:
  /// The mean largest principal strain of the released soft grains' tets now.
  double mean_principal_strain(const World& world) const;

  std::vector<int> body_of_tet_;  ///< model.neo_hookean[t]'s grain
  std::vector<double> lowest_, rebound_;
  double drop_time_;
  double peak_strain_ = 0.0;
  int peak_frame_ = 0;
};

}  // namespace rice::experiments
