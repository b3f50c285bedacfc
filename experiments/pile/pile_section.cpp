// Horizontal cut through grain meshes, by even–odd spans along rows; see pile_section.hpp.
#include "experiments/pile/pile_section.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace rice::experiments {

PileSection empty_section(const Eigen::Vector2d& lower, const Eigen::Vector2d& upper, double pixel) {
  if (!(pixel > 0.0) || !std::isfinite(pixel)) throw std::invalid_argument("pile section: the pixel must be positive");
  const Eigen::Vector2d extent = (upper - lower) / pixel;
  if (!(extent.minCoeff() > 0.0) || extent.prod() > double(1 << 26))
    throw std::invalid_argument("pile section: the rectangle must be non-empty and under 2^26 pixels");
  PileSection section;
  section.lower = lower;
  section.pixel = pixel;
  section.width = static_cast<int>(std::ceil(extent.x()));
  section.height = static_cast<int>(std::ceil(extent.y()));
  section.inside.assign(static_cast<size_t>(section.width) * section.height, 0);
  return section;
}

void add_to_section(PileSection& section, const grains::SurfaceMesh& mesh, double height) {
  if (mesh.V.col(2).minCoeff() > height || mesh.V.col(2).maxCoeff() < height) return;
  const Eigen::Vector2d& lower = section.lower;
  const double pixel = section.pixel;
  std::vector<std::vector<double>> crossings(section.height);  // per row
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    // The triangle's segment in the plane: the points where its edges cross z = height
    // (a vertex exactly on the plane counts as above, so each crossing is counted once).
    Eigen::Vector2d ends[2];
    int found = 0;
    for (int e = 0; e < 3; ++e) {
      const Eigen::Vector3d a = mesh.V.row(mesh.F(f, e)), b = mesh.V.row(mesh.F(f, (e + 1) % 3));
      if ((a.z() >= height) == (b.z() >= height)) continue;
      const double t = (height - a.z()) / (b.z() - a.z());
      if (found < 2) ends[found] = (a + t * (b - a)).head<2>();
      ++found;
    }
    if (found != 2) continue;
    // Rows whose pixel centres the segment spans (half-open in y, so a shared end counts once).
    const Eigen::Vector2d& p = ends[0];
    const Eigen::Vector2d& q = ends[1];
    if (p.y() == q.y()) continue;
    const double y_low = std::min(p.y(), q.y()), y_high = std::max(p.y(), q.y());
    const int first = std::max(0, static_cast<int>(std::ceil((y_low - lower.y()) / pixel - 0.5)));
    const int last = std::min(section.height - 1, static_cast<int>(std::ceil((y_high - lower.y()) / pixel - 0.5)) - 1);
    for (int j = first; j <= last; ++j) {
      const double y = lower.y() + (j + 0.5) * pixel;
      crossings[j].push_back(p.x() + (y - p.y()) / (q.y() - p.y()) * (q.x() - p.x()));
    }
  }
  for (int j = 0; j < section.height; ++j) {
    std::vector<double>& xs = crossings[j];
    std::sort(xs.begin(), xs.end());
    for (size_t k = 0; k + 1 < xs.size(); k += 2) {
      const int from = std::max(0, static_cast<int>(std::ceil((xs[k] - lower.x()) / pixel - 0.5)));
      const int to = std::min(section.width - 1, static_cast<int>(std::ceil((xs[k + 1] - lower.x()) / pixel - 0.5)) - 1);
      for (int i = from; i <= to; ++i) section.inside[static_cast<size_t>(j) * section.width + i] = 1;
    }
  }
}

PileSection cut_pile(const std::vector<grains::SurfaceMesh>& grains, double height, const Eigen::Vector2d& lower,
                     const Eigen::Vector2d& upper, double pixel) {
  PileSection section = empty_section(lower, upper, pixel);
  for (const grains::SurfaceMesh& mesh : grains) add_to_section(section, mesh, height);
  return section;
}

std::vector<char> region_around(const PileSection& section, const std::function<bool(const Eigen::Vector2d&)>& open,
                                const Eigen::Vector2d& seed) {
  std::vector<char> region(section.inside.size(), 0);
  const Eigen::Vector2d at = (seed - section.lower) / section.pixel;
  const int i0 = static_cast<int>(std::floor(at.x())), j0 = static_cast<int>(std::floor(at.y()));
  if (i0 < 0 || j0 < 0 || i0 >= section.width || j0 >= section.height || !open(section.centre(i0, j0))) return region;
  std::vector<std::pair<int, int>> stack{{i0, j0}};  // flood fill, depth first
  region[static_cast<size_t>(j0) * section.width + i0] = 1;
  while (!stack.empty()) {
    const auto [i, j] = stack.back();
    stack.pop_back();
    for (const auto& [di, dj] : {std::pair(1, 0), std::pair(-1, 0), std::pair(0, 1), std::pair(0, -1)}) {
      const int ni = i + di, nj = j + dj;
      if (ni < 0 || nj < 0 || ni >= section.width || nj >= section.height) continue;
      char& seen = region[static_cast<size_t>(nj) * section.width + ni];
      if (seen || !open(section.centre(ni, nj))) continue;
      seen = 1;
      stack.push_back({ni, nj});
    }
  }
  return region;
}

double packing_fraction(const PileSection& section, const std::vector<char>& region) {
  long pixels = 0, covered = 0;
  for (size_t k = 0; k < region.size(); ++k)
    if (region[k]) {
      ++pixels;
      covered += section.inside[k];
    }
  return pixels > 0 ? double(covered) / double(pixels) : std::numeric_limits<double>::quiet_NaN();
}

RgbImage section_image(const PileSection& section, const std::vector<char>& region) {
  RgbImage image(section.width, section.height);
  for (int j = 0; j < section.height; ++j)
    for (int i = 0; i < section.width; ++i) {
      const size_t k = static_cast<size_t>(j) * section.width + i;
      const std::uint8_t v = section.inside[k] ? 255 : region[k] ? 70 : 0;
      image.set(i, section.height - 1 - j, v, v, v);
    }
  return image;
}

}  // namespace rice::experiments
