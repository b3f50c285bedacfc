// The box a render's default camera frames (experiments/render/framing_box.hpp): a heap's flank
// stays in it, a grain thrown far off the heap does not, a few grains are all framed; the
// camera that frames a box sees all its corners and fills the image.
#include <gtest/gtest.h>

#include <random>

#include "experiments/render/framing_box.hpp"

namespace rice::experiments {
namespace {

Eigen::AlignedBox3d grain_at(const Eigen::Vector3d& c) {
  const Eigen::Vector3d half(2.5e-3, 1.5e-3, 1e-3);
  return {c - half, c + half};
}

/// n grains with centres uniform in a 5 cm × 5 cm × 3 cm block at the origin.
std::vector<Eigen::AlignedBox3d> heap(int n) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> xy(-0.025, 0.025), z(0.0, 0.03);
  std::vector<Eigen::AlignedBox3d> grains;
  for (int g = 0; g < n; ++g) grains.push_back(grain_at({xy(random), xy(random), z(random)}));
  return grains;
}

Eigen::AlignedBox3d union_of(const std::vector<Eigen::AlignedBox3d>& grains) {
  Eigen::AlignedBox3d box;
  for (const auto& g : grains) box.extend(g);
  return box;
}

TEST(FramingBox, AGrainThrownFarOffTheHeapIsLeftOutOfTheFrame) {
  std::vector<Eigen::AlignedBox3d> grains = heap(3600);
  const Eigen::AlignedBox3d bulk = union_of(grains);
  grains.push_back(grain_at({0.17, 0.05, 0.001}));
  const Eigen::AlignedBox3d box = framing_box(grains);
  EXPECT_TRUE(box.isApprox(bulk)) << box.min().transpose() << " .. " << box.max().transpose();
}

TEST(FramingBox, AHeapsOwnFlankStaysInTheFrame) {
  std::vector<Eigen::AlignedBox3d> grains = heap(3600);
  // A grain just past the heap's side, as a flank's lowest grain rolls out.
  grains.push_back(grain_at({0.031, 0.0, 0.001}));
  EXPECT_TRUE(framing_box(grains).isApprox(union_of(grains)));
}

TEST(FramingBox, AFewGrainsAreAllFramedAndNoneFrameNothing) {
  // Under 100 grains the percentiles are the extremes: every grain is kept, even one alone.
  const std::vector<Eigen::AlignedBox3d> few = {grain_at({0, 0, 0}), grain_at({0.2, 0, 0})};
  EXPECT_TRUE(framing_box(few).isApprox(union_of(few)));
  EXPECT_TRUE(framing_box({grain_at({0.1, 0.2, 0.3})}).isApprox(grain_at({0.1, 0.2, 0.3})));
  EXPECT_TRUE(framing_box({}).isEmpty());
}

/// The corners' film coordinates in [-1, 1]² when in the image: the lowest and highest on each axis.
std::pair<Eigen::Vector2d, Eigen::Vector2d> film_extent(const shading::Camera& camera, const Eigen::AlignedBox3d& box,
                                                        double aspect) {
  const shading::Camera::Frame f = camera.frame(aspect);
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = -lo;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d q = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k)) - f.position;
    const double depth = q.dot(f.forward);
    const Eigen::Vector2d film(q.dot(f.right) / (f.right.squaredNorm() * depth), q.dot(f.up) / (f.up.squaredNorm() * depth));
    lo = lo.cwiseMin(film);
    hi = hi.cwiseMax(film);
  }
  return {lo, hi};
}

TEST(FramingCamera, SeesEveryCornerCentredAndFillsTheImage) {
  // A row of grains 10 cm long and a cube; wide and tall images. The bounding sphere's fit
  // left the row a thin line across half the width.
  const std::vector<Eigen::AlignedBox3d> boxes = {{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.1, 0.004, 0.003)},
                                                  {Eigen::Vector3d(-0.01, 0.02, 0), Eigen::Vector3d(0.01, 0.04, 0.02)}};
  for (const auto& box : boxes)
    for (const double aspect : {16.0 / 9.0, 0.75}) {
      const auto [lo, hi] = film_extent(framing_camera(box, 35.0, -60.0, 30.0, aspect), box, aspect);
      EXPECT_GE(lo.minCoeff(), -1.0);
      EXPECT_LE(hi.maxCoeff(), 1.0);
      EXPECT_NEAR((lo + hi).x(), 0.0, 0.02) << "left and right margins differ";
      EXPECT_NEAR((lo + hi).y(), 0.0, 0.02) << "top and bottom margins differ";
      EXPECT_GT((hi - lo).maxCoeff(), 2.0 / 1.05 - 0.01) << "the box fills neither the width nor the height";
    }
}

}  // namespace
}  // namespace rice::experiments
