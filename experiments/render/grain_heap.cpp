// The render study's heap of grains; see grain_heap.hpp.
#include "experiments/render/grain_heap.hpp"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <numbers>
#include <random>
#include <unordered_map>

#include "experiments/render/scene_pieces.hpp"

namespace rice::experiments {
namespace {

/// The highest point placed so far over each cell of a square grid in x, y.
class HeightField {
 public:
  explicit HeightField(double cell) : cell_(cell) {}
  double at(double x, double y) const {
    const auto it = heights_.find(key(x, y));
    return it == heights_.end() ? 0.0 : it->second;
  }
  void raise(double x, double y, double z) {
    double& h = heights_[key(x, y)];
    h = std::max(h, z);
  }

 private:
  std::uint64_t key(double x, double y) const {  // the two cell indices, 32 bits each (wrapping)
    const auto index = [&](double t) { return static_cast<std::uint32_t>(static_cast<std::int64_t>(std::floor(t / cell_))); };
    return (static_cast<std::uint64_t>(index(x)) << 32) | index(y);
  }
  double cell_;
  std::unordered_map<std::uint64_t, double> heights_;
};

/// The lowest centre height at which the mesh P (rotated, centred at x, y) lies wholly above
/// the field, testing every `stride`-th vertex.
double landing(const HeightField& field, const shading::MeshVertices& P, double x, double y, int stride) {
  double z = -1e9;
  for (Eigen::Index v = 0; v < P.rows(); v += stride) z = std::max(z, field.at(x + P(v, 0), y + P(v, 1)) - P(v, 2));
  return z;
}

/// Drops the mesh (rotated by R) at x, y and lets it slide: it moves to the lowest landing
/// among spots a quarter of its length around while that is lower, as a grain rolls down a
/// heap's flank (without this the drops stack into a tower). Raises the field by its vertices
/// where it rests; returns its centre.
Eigen::Vector3d drop(HeightField& field, const shading::MeshVertices& V, const Eigen::Matrix3d& R, double x, double y,
                     double length) {
  const shading::MeshVertices P = V * R.transpose();
  constexpr int kCoarse = 16, kSpots = 8;
  double z = landing(field, P, x, y, kCoarse);
  for (int step = 0; step < 40; ++step) {
    double best_x = x, best_y = y, best_z = z;
    for (int k = 0; k < kSpots; ++k) {
      const double a = 2.0 * std::numbers::pi * k / kSpots, r = 0.25 * length;
      const double zk = landing(field, P, x + r * std::cos(a), y + r * std::sin(a), kCoarse);
      if (zk < best_z - 1e-6 * length) {
        best_x = x + r * std::cos(a);
        best_y = y + r * std::sin(a);
        best_z = zk;
      }
    }
    if (best_z == z) break;
    x = best_x;
    y = best_y;
    z = best_z;
  }
  z = landing(field, P, x, y, 1);
  for (Eigen::Index v = 0; v < P.rows(); ++v) field.raise(x + P(v, 0), y + P(v, 1), z + P(v, 2));
  return {x, y, z};
}

}  // namespace

void build_grain_heap(GrainPlate& heap, int grains, std::uint64_t seed) {
  const GrainVariants variants = add_grain_variants(heap.scene, seed);
  const std::vector<int>& prototypes = variants.prototypes;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> spread(0.0, 1.0);
  // A heap's width grows as the cube root of its grains: 200 grains dropped over σ = 3 mm.
  const double sigma = 3e-3 * std::cbrt(grains / 200.0);
  HeightField field(0.25e-3);
  double top = 0.0;
  std::vector<double> reach_out;  // each grain's distance from the axis
  for (int g = 0; g < grains; ++g) {
    const double x = sigma * spread(rng), y = sigma * spread(rng);
    const Eigen::Matrix3d R = (Eigen::AngleAxisd(2.0 * std::numbers::pi * unit(rng), Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(0.6 * (unit(rng) - 0.5), Eigen::Vector3d::UnitX()) *
                               Eigen::AngleAxisd(0.6 * (unit(rng) - 0.5), Eigen::Vector3d::UnitY()))
                                  .toRotationMatrix();
    const int variant = g % static_cast<int>(prototypes.size());
    const Eigen::Vector3d centre = drop(field, variants.meshes[variant], R, x, y, variants.length);
    top = std::max(top, centre.z());
    reach_out.push_back(centre.head<2>().norm());
    Eigen::Affine3d place = Eigen::Affine3d::Identity();
    place.linear() = R;
    place.translation() = centre;
    heap.grain_instances.push_back(heap.scene.add_instance(prototypes[variant], place, 0));
  }
  add_ground(heap.scene, -0.1, -0.1, 0.1, 0.1, 0.0, 1);
  heap.scene.commit();
  heap.lights = study_lights();
  // A crop: the heap's upper middle, as high as 0.6 of its radius (where 90% of its grains lie).
  std::sort(reach_out.begin(), reach_out.end());
  const double radius = reach_out[static_cast<std::size_t>(0.9 * (reach_out.size() - 1))];
  const Eigen::Vector3d centre(0.0, 0.0, 0.6 * top);
  heap.camera.target = centre;
  heap.camera.vertical_fov_degrees = 30.0;
  const double reach = 0.6 * radius / std::tan(15.0 * std::numbers::pi / 180.0);
  heap.camera.position = centre + reach * Eigen::Vector3d(0.0, -std::cos(0.7), std::sin(0.7));
}

}  // namespace rice::experiments
