// Per-vertex thickness and outer-surface flags of a closed mesh (thickness.hpp).
#include "shading/thickness.hpp"

#include "shading/render_scene.hpp"

namespace rice::shading {
namespace {

/// The mesh alone, as instance 0.
void add_mesh(RenderScene& scene, const MeshVertices& V, const MeshTriangles& F) {
  scene.add_instance(scene.add_prototype(V, F), Eigen::Affine3d::Identity(), 0);
  scene.commit();
}

}  // namespace

Eigen::VectorXd vertex_thickness(const MeshVertices& V, const MeshTriangles& F) {
  RenderScene scene;
  add_mesh(scene, V, F);
  const MeshVertices N = vertex_normals(V, F);
  Eigen::VectorXd d = Eigen::VectorXd::Zero(V.rows());
  const float offset = scene.ray_offset();
  for (Eigen::Index v = 0; v < V.rows(); ++v) {
    const Eigen::Vector3f inward = -N.row(v).transpose().cast<float>();
    Ray ray{V.row(v).transpose().cast<float>() + offset * inward, inward};
    // The last surface along the line is where it leaves the body for good; pores and folds
    // before it are crossed. A bounded count of hits guards against a ray grazing along a
    // triangle forever.
    for (int hits = 0; hits < 1000; ++hits) {
      const std::optional<ShadingPoint> hit = scene.intersect_instance(ray, 0);
      if (!hit) break;
      d(v) = hit->t;
      ray.t_min = hit->t + offset;
    }
  }
  return d;
}

std::vector<bool> vertex_sees_out(const MeshVertices& V, const MeshTriangles& F) {
  RenderScene scene;
  add_mesh(scene, V, F);
  const MeshVertices N = vertex_normals(V, F);
  std::vector<bool> out(static_cast<std::size_t>(V.rows()));
  const float offset = scene.ray_offset();
  for (Eigen::Index v = 0; v < V.rows(); ++v) {
    const Eigen::Vector3f n = N.row(v).transpose().cast<float>();
    out[v] = !scene.occluded({V.row(v).transpose().cast<float>() + offset * n, n});
  }
  return out;
}

}  // namespace rice::shading
