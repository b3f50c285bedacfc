// Built-in cultivar parameters and their sources.
//
// Raw milled-grain dimensions are rounded typical values of each class, consistent with the
// grain-length and shape classes of the IRRI Standard Evaluation System for Rice (2013):
// short < 5.5 mm, medium 5.5–6.6, long 6.6–7.5, extra long > 7.5; slender shapes have
// length/width > 3, bold ones < 2. Japonica and glutinous follow published measurements of
// Japanese short-grain rice (about 5.0 × 2.9 × 2.1 mm, e.g. Koshihikari); indica a long-grain
// variety such as IR64 (about 6.7 × 2.1 × 1.8 mm); aromatic is basmati (about 7.2 × 1.85 ×
// 1.65 mm). Standard deviations are ESTIMATES (about 4% of the mean, the spread seen within
// one lot), not measured values.
//
// Cooked/raw ratios: basmati is known for its elongation on cooking, length ratio 1.7–2.1
// with little widening (Juliano, "Rice in Human Nutrition", FAO 1993, ch. on grain quality;
// the "basmati roughly doubles in length"); other cultivars elongate 1.2–1.4. The
// width and thickness ratios (1.1–1.25) are ESTIMATES chosen to give cooked japonica grains
// of about 7 × 3.6 × 2.8 mm, as cooked short-grain rice measures.
//
// Swell factor P: the base shape has the cooked proportions at the raw volume, so P alone
// carries the volume change, P³ = volume ratio. Its range is centred on the cube root of the
// product of the three cooked/raw ratios, so that the mean cooked grain has the published
// cooked dimensions (raw × ratio, per axis): japonica (1.30·1.15·1.25)^(1/3) = 1.23, indica
// 1.26, basmati 1.38, glutinous 1.15; the ± 0.08 spread around it is an ESTIMATE of the
// grain-to-grain variation. The paper observes that indica "does not expand easily"; by the
// measured ratios it expands about as much as japonica. Bulk measurements of cooked rice
// report larger volume expansion (2.5–4, Juliano 1993) because they include the water held
// between grains; per-grain dimensions are what a grain model needs.
#include "grains/cultivar.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rice::grains {
namespace {

Cultivar japonica() {
  Cultivar c;
  c.name = "japonica";
  c.length = {5.0e-3, 0.2e-3};
  c.width = {2.9e-3, 0.12e-3};
  c.thickness = {2.1e-3, 0.08e-3};
  c.cooked_length_ratio = 1.30;
  c.cooked_width_ratio = 1.15;
  c.cooked_thickness_ratio = 1.25;
  c.tip_exponent = 2.5;
  c.asymmetry = 0.10;
  c.notch_depth = 0.15;
  c.notch_size = 0.10;
  c.swell_min = 1.15;
  c.swell_max = 1.31;
  c.stickiness = 15.0;
  return c;
}

Cultivar indica() {
  Cultivar c;
  c.name = "indica";
  c.length = {6.7e-3, 0.27e-3};
  c.width = {2.1e-3, 0.08e-3};
  c.thickness = {1.8e-3, 0.07e-3};
  c.cooked_length_ratio = 1.35;
  c.cooked_width_ratio = 1.15;
  c.cooked_thickness_ratio = 1.15;
  c.tip_exponent = 2.2;
  c.asymmetry = 0.08;
  c.notch_depth = 0.12;
  c.notch_size = 0.08;
  c.swell_min = 1.18;
  c.swell_max = 1.34;
  c.stickiness = 3.0;
  return c;
}

Cultivar aromatic() {
  Cultivar c;
  c.name = "aromatic";
  c.length = {7.2e-3, 0.3e-3};
  c.width = {1.85e-3, 0.07e-3};
  c.thickness = {1.65e-3, 0.07e-3};
  c.cooked_length_ratio = 1.90;
  c.cooked_width_ratio = 1.15;
  c.cooked_thickness_ratio = 1.15;
  c.tip_exponent = 2.2;
  c.asymmetry = 0.06;
  c.notch_depth = 0.12;
  c.notch_size = 0.06;
  c.swell_min = 1.30;
  c.swell_max = 1.46;
  c.stickiness = 3.0;
  return c;
}

Cultivar glutinous() {
  Cultivar c = japonica();
  c.name = "glutinous";
  c.length = {4.9e-3, 0.2e-3};
  c.width = {2.95e-3, 0.12e-3};
  c.thickness = {2.05e-3, 0.08e-3};
  c.cooked_length_ratio = 1.20;
  c.cooked_width_ratio = 1.10;
  c.cooked_thickness_ratio = 1.15;
  c.tip_exponent = 2.6;
  c.swell_min = 1.07;
  c.swell_max = 1.23;
  return c;
}

double sample_clipped(const Dimension& d, RandomStream& random) {
  const double value = random.normal(d.mean, d.standard_deviation);
  return std::clamp(value, d.mean - 3.0 * d.standard_deviation, d.mean + 3.0 * d.standard_deviation);
}

void require(bool ok, const Cultivar& c, const std::string& field, const std::string& expected) {
  if (!ok) throw std::invalid_argument("cultivar '" + c.name + "': " + field + " must be " + expected);
}

}  // namespace

std::vector<std::string> cultivar_names() { return {"japonica", "indica", "aromatic", "glutinous"}; }

Cultivar cultivar_by_name(const std::string& name) {
  if (name == "japonica") return japonica();
  if (name == "indica") return indica();
  if (name == "aromatic") return aromatic();
  if (name == "glutinous") return glutinous();
  std::string known;
  for (const std::string& n : cultivar_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown cultivar '" + name + "' (known: " + known + ")");
}

void validate(const Cultivar& c) {
  const auto dimension_ok = [](const Dimension& d) {
    return d.mean > 0.0 && d.standard_deviation >= 0.0 && d.mean - 3.0 * d.standard_deviation > 0.0;
  };
  require(dimension_ok(c.length), c, "length", "positive, with mean - 3 sd > 0");
  require(dimension_ok(c.width), c, "width", "positive, with mean - 3 sd > 0");
  require(dimension_ok(c.thickness), c, "thickness", "positive, with mean - 3 sd > 0");
  require(c.cooked_length_ratio > 0.0 && c.cooked_width_ratio > 0.0 && c.cooked_thickness_ratio > 0.0, c,
          "cooked ratios", "positive");
  require(c.tip_exponent >= 1.0 && c.tip_exponent <= 8.0, c, "tip_exponent", "in [1, 8]");
  require(c.asymmetry >= 0.0 && c.asymmetry < 0.5, c, "asymmetry", "in [0, 0.5)");
  require(c.notch_depth >= 0.0 && c.notch_depth < 0.5, c, "notch_depth", "in [0, 0.5)");
  require(c.notch_size >= 0.0 && c.notch_size < 0.5, c, "notch_size", "in [0, 0.5)");
  require(c.swell_min >= 1.0 && c.swell_min <= c.swell_max && c.swell_max <= 1.5, c, "swell range",
          "1 <= swell_min <= swell_max <= 1.5 (got [" + std::to_string(c.swell_min) + ", " +
              std::to_string(c.swell_max) + "])");
  require(c.stickiness >= 0.0 && c.stickiness <= 1000.0, c, "stickiness",
          "in [0, 1000] grain weights (got " + std::to_string(c.stickiness) + ")");
}

GrainShape sample_grain_shape(const Cultivar& c, RandomStream& random) {
  const double volume_neutral =
      std::cbrt(c.cooked_length_ratio * c.cooked_width_ratio * c.cooked_thickness_ratio);
  GrainShape shape;
  shape.length = sample_clipped(c.length, random) * c.cooked_length_ratio / volume_neutral;
  shape.width = sample_clipped(c.width, random) * c.cooked_width_ratio / volume_neutral;
  shape.thickness = sample_clipped(c.thickness, random) * c.cooked_thickness_ratio / volume_neutral;
  shape.tip_exponent = c.tip_exponent;
  shape.asymmetry = c.asymmetry;
  shape.notch_depth = c.notch_depth * shape.thickness;
  shape.notch_size = c.notch_size * shape.length;
  shape.swell = random.uniform(c.swell_min, c.swell_max);
  return shape;
}

}  // namespace rice::grains
