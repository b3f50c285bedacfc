// Soundness of a model's state; see model_health.hpp.
#include "xpbd/model_health.hpp"

#include <algorithm>

#include "xpbd/tet_stencil.hpp"

namespace rice::xpbd {

bool state_finite(const Model& model) {
  return model.particles.x.allFinite() && model.particles.v.allFinite() &&
         std::all_of(model.rigid_bodies.begin(), model.rigid_bodies.end(), [](const RigidBody& b) {
           return b.x.allFinite() && b.v.allFinite() && b.omega.allFinite() && b.q().coeffs().allFinite();
         });
}

int inverted_tets(const Model& model) {
  int inverted = 0;
  for (const NeoHookeanTet& t : model.neo_hookean) {
    Vec12 x;
    for (int k = 0; k < 4; ++k) x.segment<3>(3 * k) = model.particles.x.row(t.particles[k]).transpose();
    inverted += signed_volume(x) <= 0.0;
  }
  return inverted;
}

}  // namespace rice::xpbd
