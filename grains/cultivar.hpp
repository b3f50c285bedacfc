// Cultivar shape models: the dimension distributions of raw (milled) grains of japonica,
// indica, aromatic (basmati) and glutinous rice, the proportions cooking gives them, and the
// range of the swell factor P of paper eq. 2. A grain's cooked size is
//   cooked = P · (r / (r_L r_W r_T)^(1/3)) ∘ raw,
// where r is the cultivar's per-axis cooked/raw ratio: r changes proportions at constant
// volume (basmati's elongation), and P — a linear factor, as eq. 2 scales voxel coordinates
// [x, y, z] = P [r, s, t] — multiplies the volume by P³. The default P ranges are centred
// on (r_L r_W r_T)^(1/3), so the mean grain has the published cooked dimensions raw ∘ r;
// see cultivar.cpp for sources.
#pragma once

#include <string>
#include <vector>

#include "grains/random_stream.hpp"

namespace rice::grains {

/// A normally distributed dimension [m], clipped to mean ± 3 standard deviations.
struct Dimension {
  double mean = 0.0;
  double standard_deviation = 0.0;
};

struct Cultivar {
  std::string name;
  Dimension length, width, thickness;  ///< raw milled grain [m]
  double cooked_length_ratio = 1.0;    ///< cooked/raw length, measured (elongation ratio)
  double cooked_width_ratio = 1.0;     ///< cooked/raw width
  double cooked_thickness_ratio = 1.0; ///< cooked/raw thickness
  double tip_exponent = 2.0;  ///< p of the profile (1 − |u|^p)^(1/p): 2 ellipsoidal, larger blunter
  double asymmetry = 0.0;     ///< dorsal side (+y) wider than ventral by this fraction of width
  double notch_depth = 0.0;   ///< embryo notch depth as a fraction of thickness
  double notch_size = 0.0;    ///< embryo notch radius as a fraction of length
  double swell_min = 1.0;     ///< P range of eq. 2, within [1, 1.5]
  double swell_max = 1.0;
  /// Force to pull two touching cooked grains apart, in grain weights, at the reference soak
  /// of water_content.hpp: about 15 for sticky cultivars (japonica, glutinous) and 3 for
  /// non-sticky ones (indica, basmati), after the cohesion index of Peleg (2020),
  /// "Quantitative instrumental assessment of cooked rice stickiness". ESTIMATE.
  double stickiness = 0.0;
};

/// The sampled shape of one grain, cooked dimensions included.
struct GrainShape {
  /// Cooked proportions at raw volume [m]; the cooked grain is `swell` times larger.
  double length = 0.0, width = 0.0, thickness = 0.0;
  double tip_exponent = 2.0;
  double asymmetry = 0.0;
  double notch_depth = 0.0;  ///< [m]
  double notch_size = 0.0;   ///< [m]
  double swell = 1.0;        ///< P of eq. 2
};

/// Names of the built-in cultivars: japonica, indica, aromatic, glutinous.
std::vector<std::string> cultivar_names();

/// A built-in cultivar by name; throws std::invalid_argument listing the known names.
Cultivar cultivar_by_name(const std::string& name);

/// Checks every field (positive dimensions, ratios and sizes; 1 ≤ P_min ≤ P_max ≤ 1.5; ...),
/// throwing std::invalid_argument naming the field and the accepted range.
void validate(const Cultivar& cultivar);

/// Draws one grain: dimensions from their clipped normals, P uniform in [P_min, P_max].
GrainShape sample_grain_shape(const Cultivar& cultivar, RandomStream& random);

}  // namespace rice::grains
