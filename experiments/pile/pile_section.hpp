// A horizontal cut through a pile of grains (paper Fig. 16 b, the onigiri's cross-section):
// which points of the plane z = height lie inside a grain, from the grains' closed render
// meshes (each triangle cut by the plane gives a segment; along each row of pixels, the
// crossings of one grain's segments pair up, even–odd, into the spans inside it), and the
// packing fraction: the share of a container's room in that plane (a mould's outline, the
// inside of a bowl) that grains cover.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

#include "experiments/io/png_image.hpp"
#include "grains/mesh_types.hpp"

namespace rice::experiments {

struct PileSection {
  Eigen::Vector2d lower = Eigen::Vector2d::Zero();  ///< (x, y) of pixel (0, 0)'s corner [m]
  double pixel = 0.0;                               ///< a pixel's side [m]
  int width = 0, height = 0;
  std::vector<char> inside;  ///< per pixel (row-major, row 0 at lower.y()): its centre is in a grain

  Eigen::Vector2d centre(int i, int j) const { return lower + pixel * Eigen::Vector2d(i + 0.5, j + 0.5); }
  bool at(int i, int j) const { return inside[static_cast<size_t>(j) * width + i]; }
};

/// A section with no grain in it over the rectangle [lower, upper], in pixels of side `pixel`.
/// Throws std::invalid_argument for a pixel that is not positive or over 2^26 pixels.
PileSection empty_section(const Eigen::Vector2d& lower, const Eigen::Vector2d& upper, double pixel);

/// Marks the pixels whose centres lie inside `mesh`'s cut at z = `height` (even–odd along rows).
void add_to_section(PileSection& section, const grains::SurfaceMesh& mesh, double height);

/// The cut at z = `height` over the rectangle [lower, upper] in pixels of side `pixel`:
/// empty_section, then add_to_section for each grain.
PileSection cut_pile(const std::vector<grains::SurfaceMesh>& grains, double height, const Eigen::Vector2d& lower,
                     const Eigen::Vector2d& upper, double pixel);

/// The pixels (a mask like `inside`) reachable from the one holding `seed` through pixels
/// whose centres `open` holds, stepping to the four neighbours: a container's room in the cut
/// without the open space beyond its walls. Empty of pixels when the seed's is not open or
/// lies outside the section.
std::vector<char> region_around(const PileSection& section, const std::function<bool(const Eigen::Vector2d&)>& open,
                                const Eigen::Vector2d& seed);

/// The share of the region's pixels that lie in a grain; NaN for an empty region.
double packing_fraction(const PileSection& section, const std::vector<char>& region);

/// The section as a picture, +y up: grains white, the region grey, the rest black.
RgbImage section_image(const PileSection& section, const std::vector<char>& region);

}  // namespace rice::experiments
