// What a scene run measured, for the drivers built on it (table 1, figure 10, the studies):
// the observers (observer.hpp) fill it in at the end of the run.
#pragma once

#include "xpbd/penetration.hpp"

namespace rice::experiments {

struct SceneResult {
  double simulation_seconds = 0.0;  ///< wall time of the frames
  double render_seconds = 0.0;      ///< the [render] section's image (0: the scene has none)
  int awake = 0;                    ///< grains awake at the end
  double kinetic_energy = 0.0;      ///< of every grain at the end [J]
  xpbd::Penetration penetration;    ///< the deepest overlaps at the end
  bool finite = true;               ///< every position and velocity finite at the end (model_health.hpp)
  int inverted_tets = 0;            ///< soft tets with det F ≤ 0 at the end
  double grain_thickness = 0.0;     ///< the thinnest variant's thickness T [m]: overlaps are judged against it
  /// On a plate: the heap's angle of repose [°] and its apex above the lowest centre [m]; NaN
  /// in a bowl or for grains scattered one deep.
  double angle_of_repose_degrees = 0.0, heap_height = 0.0;
  /// The pile from above (pile_measures.hpp): the radius holding 90% of the grains' centres
  /// [m], and the groups of grains that touch (within 0.1 mm).
  double footprint_radius = 0.0;
  int clusters = 0;
  /// The highest grain centre [m] at the end, and just before the first collider's removal
  /// (a mould taken away; NaN when none is removed): whether the shape stands.
  double top = 0.0, top_before_removal = 0.0;
  /// A mould's fill or the chawan (paper Fig. 16 b, Fig. 15): the pile cut half way from the
  /// room's floor to the pile's top (pile_measures.hpp) (section.png), and the share of the room
  /// there that grains cover.
  double section_height = 0.0, packing_fraction = 0.0;
  /// Grains in the mould's room or within the bowl's rim at the end (-1: a plate).
  int in_container = -1;
  int released = 0;  ///< grains the emitter placed in the scene (a fill may find no room for some)
  double grain_length = 0.0;  ///< the world's largest grain length L [m]
  /// A dropped clump (impact_observer.hpp): the grains' mean rebound [m], and the soft tets'
  /// largest mean principal strain over the frames (NaN for rigid grains).
  double rebound_height = 0.0, peak_strain = 0.0;
};

}  // namespace rice::experiments
