// The AOV pass; see aovs.hpp.
#include "shading/aovs.hpp"

#include <limits>

namespace rice::shading {

Aovs render_aovs(const RenderScene& scene, const std::vector<Material>& materials, const Camera& camera, int width,
                 int height, const PixelWindow& window) {
  check_instance_materials(scene, materials.size(), "render_aovs");
  const PixelWindow pixels = rendered_pixels(width, height, window, "render_aovs");
  const std::size_t n = static_cast<std::size_t>(pixels.width()) * pixels.height();
  Aovs aovs{pixels.width(), pixels.height(), std::vector<Eigen::Vector3f>(n, Eigen::Vector3f::Zero()),
            std::vector<float>(n, std::numeric_limits<float>::infinity()), std::vector<Color>(n, Color::Zero()),
            std::vector<float>(n, -1.0f)};
  const Camera::Frame frame = camera.frame(static_cast<double>(width) / height);
  const Eigen::Vector3f forward = frame.forward.cast<float>();
  for_each_tile(pixels, {}, {}, [&](int x0, int y0, int x1, int y1) {
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const CameraRay r = frame.ray((x + 0.5) / width, (y + 0.5) / height, 0.0, 0.0);
        const auto hit = scene.intersect({r.origin, r.direction});
        if (!hit) continue;
        const std::size_t i = static_cast<std::size_t>(y - pixels.y0) * pixels.width() + (x - pixels.x0);
        aovs.normal[i] = hit->shading_normal;
        aovs.depth[i] = hit->t * r.direction.dot(forward);
        aovs.albedo[i] = materials[hit->material].albedo;
        aovs.label[i] = static_cast<float>(scene.label_of(hit->instance));
      }
  });
  return aovs;
}

}  // namespace rice::shading
