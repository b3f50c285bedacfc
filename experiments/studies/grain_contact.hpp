// The grain scenes of `rice study contact` (issue 12, §3): XPBD's and vertex block descent's
// rest shape and contact forces against the reference's static solve, over substeps N and
// iterations K — what contact accuracy costs in time. See contact_study.hpp for the study.
//
//   ground    one grain set down undeformed, in a pose where it rests stably (found by the
//             reference), on a frictionless ground under gravity;
//   pair      two grain-sized boxes (7 × 3 × 2 mm, 8 × 4 × 2 cells, two rows of five
//             spheres of 1 mm radius, the layout of the contact tests' grain) one on the
//             other, the upper shifted by half a sphere spacing along the length so its spheres
//             sit in the dips between the lower's; the lower's bottom face held (glued to a
//             plate), the upper pressed on it by a load of `load` times its weight: grain–grain
//             contact through the collision spheres (xpbd/contact_solver.hpp,
//             fem_reference/sphere_contact_form.hpp). Across the rows a sphere on a sphere
//             without friction is unstable, so four weak springs hold the upper box at its
//             bottom corners, the same springs in every solver. A load, not a plate lowered
//             by a set distance: a soft grain's spheres thin with its smallest stretch
//             (xpbd::sphere_radius), so a lowered plate would set how thin they get, and a
//             reference that holds radii over a solve cannot start clear of its barrier with
//             the radii its solution has. Under a load the radii only shrink, so the reference
//             repeats its static solve from the undeformed start with the radii of its last
//             solution until radii and shape agree: XPBD's rest state, whose radii follow the
//             shape every substep.
//
// Each starts from the same state in every solver, the bodies undeformed. XPBD and VBD run one
// second of 1/60 s frames; the end state is compared with the reference's: the RMS distance
// of the particles (on the ground less the horizontal shift and turn a frictionless ground
// leaves free) and the contact forces per particle (f_i = ∂U/∂x_i − m_i g − f_ext,i − spring
// force, what contacts hold each particle with at rest).
#pragma once

#include <string>
#include <vector>

#include "experiments/studies/contact_study.hpp"

namespace rice::experiments {

/// One row of contact_grain.csv or contact_pair.csv.
struct GrainContactRow {
  std::string method;  ///< "xpbd" or "vbd"
  int substeps = 0, iterations = 0;
  bool stable = false;         ///< finite, no inverted tet, slower than 1 cm/s at the end
  double shape_error = 0.0;    ///< RMS distance to the reference's rest shape / grain length
  double force_error = 0.0;    ///< ‖f − f_ref‖ / ‖f_ref‖ over particles (contact forces)
  double wall = 0.0;           ///< [s per simulated second]
};

/// The ground scene's rows.
std::vector<GrainContactRow> run_grain_contact(const ContactStudySettings& settings);

/// The pair scene's rows.
std::vector<GrainContactRow> run_grain_pair(const ContactStudySettings& settings);

}  // namespace rice::experiments
