// Image comparison (image.hpp).
#include "shading/image.hpp"

#include <cmath>
#include <stdexcept>

namespace rice::shading {

double rms_difference(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("rms_difference: images of different sizes");
  double sum = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) sum += (a.pixels[i] - b.pixels[i]).cast<double>().square().sum();
  return a.pixels.empty() ? 0.0 : std::sqrt(sum / (3.0 * a.pixels.size()));
}

double mean_radiance(const Image& image) {
  double sum = 0.0;
  for (const Eigen::Array3f& p : image.pixels) sum += p.cast<double>().mean();
  return image.pixels.empty() ? 0.0 : sum / static_cast<double>(image.pixels.size());
}

}  // namespace rice::shading
