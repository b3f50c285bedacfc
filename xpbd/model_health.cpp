// Soundness of a model's state; see model_health.hpp.
#include "xpbd/model_health.hpp"

#include <algorithm>
#include <cmath>

#include "xpbd/tet_stencil.hpp"

namespace rice::xpbd {

bool state_finite(const Model& model) {
  return model.particles.x.allFinite() && model.particles.v.allFinite() &&
         std::all_of(model.rigid_bodies.begin(), model.rigid_bodies.end(), [](const RigidBody& b) {
           return b.x.allFinite() && b.v.allFinite() && b.omega.allFinite() && b.q().coeffs().allFinite();
         });
}

TetVolumeRatios tet_volume_ratios(const Model& model) {
  TetVolumeRatios volumes;
  for (const NeoHookeanTet& t : model.neo_hookean) {
    Vec12 x;
    for (int k = 0; k < 4; ++k) x.segment<3>(3 * k) = model.particles.x.row(t.particles[k]).transpose();
    const double ratio = signed_volume(x) / t.rest_volume;  // det F
    volumes.inverted += ratio <= 0.0;
    volumes.smallest = std::fmin(volumes.smallest, ratio);  // fmin skips the first NaN
  }
  return volumes;
}

}  // namespace rice::xpbd
