// The renderer's geometry on Embree 3: each distinct mesh (a grain variant, a bowl, the
// ground) is a prototype in its own Embree scene, and the top-level scene holds instances of
// them, each with a transform and a material (Embree's instanced_geometry tutorial), so
// thousands of grains cost a few dozen meshes of memory. Embree answers every ray query; this
// class turns its hits into shading points: position, geometric and interpolated shading
// normal, and the interpolated vertex curvature for the CDRF.
#pragma once

#include <Eigen/Geometry>

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "shading/curvature.hpp"

namespace rice::shading {

struct Ray {
  Eigen::Vector3f origin, direction;  ///< direction unit length
  float t_min = 0.0f, t_max = std::numeric_limits<float>::infinity();
};

struct ShadingPoint {
  float t = 0.0f;
  Eigen::Vector3f position, geometric_normal, shading_normal;  ///< normals unit, outward
  double curvature = 0.0;  ///< mean curvature [1/m] in world units
  double thickness = 0.0;  ///< local thickness [m] in world units (set_thickness; 0 if none)
  double baked = 0.0;      ///< interpolated per-vertex value set by set_vertex_values (0 if none)
  int material = 0;
  int instance = 0;
  int primitive = 0;                      ///< triangle of the instance's prototype
  Eigen::Vector3f barycentric{1, 0, 0};   ///< weights of the triangle's three vertices
};

class RenderScene {
 public:
  RenderScene();
  ~RenderScene();
  RenderScene(const RenderScene&) = delete;
  RenderScene& operator=(const RenderScene&) = delete;

  /// How often a prototype is placed, which picks its hierarchy's build quality.
  enum class Reuse {
    kShared,  ///< by many instances (a grain variant): Embree's high quality, spatial splits
    /// by one instance (a soft grain's deformed mesh, rebuilt every frame): medium quality,
    /// which halves the time to render a soft run's frame of many grains, for the same image
    /// (docs/rendering.md)
    kSingle,
  };
  /// A mesh to instance (V #V×3, F #F×3, outward counter-clockwise). `curvature` is #V vertex
  /// mean curvatures or empty (zero: flat). Returns its prototype index. Throws
  /// std::invalid_argument for an empty mesh, bad indices or a curvature of the wrong size.
  int add_prototype(const MeshVertices& V, const MeshTriangles& F, const Eigen::VectorXd& curvature = {},
                    Reuse reuse = Reuse::kShared);

  /// Per-vertex thickness of a prototype (#V, thickness.hpp), read back interpolated and in
  /// world units as ShadingPoint::thickness. Call before commit; throws
  /// std::invalid_argument for a wrong size or an unknown prototype.
  void set_thickness(int prototype, const Eigen::VectorXd& thickness);

  /// Per-vertex shading normals of a prototype (#V by 3, unit, outward), interpolated in
  /// place of its area-weighted vertex normals: normals smoothed at the scale light averages
  /// over (smooth_normals.hpp). Call before commit; throws std::invalid_argument for a wrong
  /// size or an unknown prototype.
  void set_shading_normals(int prototype, const MeshVertices& N);

  /// Places a prototype: `transform` must be a rotation, a uniform scale and a translation
  /// (curvature scales by 1/s); throws std::invalid_argument otherwise. `label` is the caller's
  /// name for it (a grain's id; −1: none), written to the grain-id AOV. Returns its index.
  int add_instance(int prototype, const Eigen::Affine3d& transform, int material, int label = -1);

  /// Builds Embree's hierarchies; call after the last add and before any query.
  void commit();

  /// The first hit along the ray of anything but instance `ignore` (−1: none).
  std::optional<ShadingPoint> intersect(const Ray& ray, int ignore = -1) const;
  /// The first hits of many rays at once, through Embree's stream interface told they are
  /// coherent (a pixel's camera rays): the same answers as intersect, faster.
  void intersect_coherent(const std::vector<Ray>& rays, std::vector<std::optional<ShadingPoint>>& hits) const;
  /// The first hit of the ray on one instance alone, the others ignored: a path inside a
  /// grain meets only that grain's surface (grains of a pile may overlap a little).
  std::optional<ShadingPoint> intersect_instance(const Ray& ray, int instance) const;
  /// Whether anything other than instance `ignore` (−1: none) lies along the ray within
  /// [t_min, t_max].
  bool occluded(const Ray& ray, int ignore = -1) const;
  /// occluded for many rays at once (a pixel's shadow rays towards the suns) through Embree's
  /// stream interface; `ignore` holds one instance (or −1) per ray. Not flagged coherent:
  /// with the see-through filter, Embree 3.13's coherent stream never returned.
  void occluded_many(const std::vector<Ray>& rays, const std::vector<int>& ignore, std::vector<char>& occluded) const;

  /// Per-vertex values of one instance (its prototype's #V), read back interpolated as
  /// ShadingPoint::baked; used for the subsurface reference's exitance. Callable after commit.
  void set_vertex_values(int instance, std::vector<float> values);
  /// The prototype's vertex indices of triangle `primitive` of `instance`.
  Eigen::Vector3i triangle(int instance, int primitive) const;
  /// The triangles of an instance's prototype that share a vertex with triangle `primitive`,
  /// itself included, into `out` (cleared first). The prototype's vertex-to-triangle index is
  /// built at the first call, once, on any thread.
  void triangles_around(int instance, int primitive, std::vector<int>& out) const;
  /// Triangle `primitive` of `instance` in world coordinates.
  std::array<Eigen::Vector3f, 3> world_triangle(int instance, int primitive) const;
  /// Vertex count of an instance's prototype.
  int vertex_count(int instance) const;
  /// Each vertex's share of the instance's surface in world units: a third of the area of
  /// every triangle around it (#V, summing to the surface area).
  std::vector<double> vertex_areas(int instance) const;
  /// World-space bounding sphere of one instance: centre and radius.
  std::pair<Eigen::Vector3f, float> bounding_sphere(int instance) const;

  /// Offset along the normal for rays leaving a surface: 1e-6 of the scene's diagonal.
  float ray_offset() const { return offset_; }

  int prototype_count() const { return static_cast<int>(prototypes_.size()); }
  int instance_count() const { return static_cast<int>(instances_.size()); }
  int material_of(int instance) const { return instances_.at(instance).material; }
  int label_of(int instance) const { return instances_.at(instance).label; }

 private:
  struct Prototype;
  struct Instance {
    int prototype = 0, material = 0, label = -1;
    Eigen::Matrix3f linear, inverse_linear, normal_matrix;
    Eigen::Vector3f translation;
    float curvature_scale = 1.0f;
    std::vector<float> vertex_values;  // empty: none
  };
  struct Embree;
  /// The prototype for per-vertex data of `count` values; throws naming `what` after commit,
  /// for an unknown prototype or a wrong count.
  Prototype& prototype_for_vertex_data(int prototype, Eigen::Index count, const std::string& what);
  std::optional<ShadingPoint> shading_point(const Ray& ray, float t, unsigned instance, unsigned primitive, float u,
                                            float v) const;

  std::unique_ptr<Embree> embree_;
  std::vector<std::unique_ptr<Prototype>> prototypes_;
  std::vector<Instance> instances_;
  float offset_ = 1e-7f;
  bool committed_ = false;
};

}  // namespace rice::shading
