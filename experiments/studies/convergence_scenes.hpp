// The two scenes of the convergence study (issue 3, §3), built on the shared model so that the
// XPBD solver and the reference solve the same thing:
//   hanging cantilever — a bar clamped at x = 0 released from rest under gravity;
//   twisted bar        — the same bar under gravity, released with a twisting velocity field
//                        ω(x) = ω_end x / L about its axis.
// Bodies are stable Neo-Hookean, or springs plus tet volumes for the PBD contrast.
#pragma once

#include <string>

#include "xpbd/model.hpp"

namespace rice::experiments {

enum class ConvergenceScene { kHangingCantilever, kTwistedBar };
enum class BodyModel { kNeoHookean, kSprings };

const char* scene_name(ConvergenceScene scene);
const char* body_model_name(BodyModel model);

struct BarSettings {
  double length = 0.1;       ///< L [m], along x
  double width = 0.02;       ///< square section side [m]
  double young = 1e5;        ///< E [Pa]
  double poisson = 0.3;
  double density = 1000.0;   ///< ρ [kg/m³]
  double twist_rate = 20.0;  ///< ω_end [rad/s] of the twisted bar's free end
};

/// How the damped scenes are damped: Rayleigh damping of each constraint (β = τ/α, XPBD
/// eq. 26), or the strain-rate damping ½τĖ:𝒞:Ė (xpbd/strain_rate_damping.hpp, Neo-Hookean
/// bodies and vertex block descent only).
enum class Damping { kNone, kConstraint, kStrainRate };

const char* damping_name(Damping damping);

/// The scene at `resolution` cubes across the section (5 × resolution along), damped with
/// time τ as `damping` says.
xpbd::Model make_scene(ConvergenceScene scene, BodyModel body, const BarSettings& bar, int resolution, Damping damping,
                       double tau);

}  // namespace rice::experiments
