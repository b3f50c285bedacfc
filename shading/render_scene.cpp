// Embree-backed render geometry (render_scene.hpp).
#include "shading/render_scene.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <stdexcept>
#include <string>

namespace rice::shading {

struct RenderScene::Embree {
  RTCDevice device = nullptr;
  RTCScene top = nullptr;
  ~Embree() {
    if (top) rtcReleaseScene(top);
    if (device) rtcReleaseDevice(device);
  }
};

struct RenderScene::Prototype {
  RTCScene scene = nullptr;
  std::vector<Eigen::Vector3f> positions, normals;
  std::vector<float> curvature;  // empty: flat
  std::vector<float> thickness;  // empty: none
  std::vector<Eigen::Vector3i> triangles;
  // Vertex v's triangles are vertex_triangles[first_triangle[v] .. first_triangle[v + 1]),
  // built by triangles_around at its first call.
  std::once_flag adjacency;
  std::vector<int> first_triangle, vertex_triangles;
  ~Prototype() {
    if (scene) rtcReleaseScene(scene);
  }
};

namespace {

// Embree reports errors per device; an exception cannot cross its C interface, so they are
// checked after each building call.
void check(RTCDevice device, const char* what) {
  const RTCError code = rtcGetDeviceError(device);
  if (code != RTC_ERROR_NONE)
    throw std::runtime_error(std::string("RenderScene: Embree error ") + std::to_string(static_cast<int>(code)) +
                             " in " + what);
}

}  // namespace

RenderScene::RenderScene() : embree_(std::make_unique<Embree>()) {
  embree_->device = rtcNewDevice(nullptr);
  if (!embree_->device) throw std::runtime_error("RenderScene: Embree could not create a device");
  embree_->top = rtcNewScene(embree_->device);
  rtcSetSceneFlags(embree_->top, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);
  check(embree_->device, "creating the scene");
}

RenderScene::~RenderScene() = default;

int RenderScene::add_prototype(const MeshVertices& V, const MeshTriangles& F, const Eigen::VectorXd& curvature,
                               Reuse reuse) {
  if (committed_) throw std::logic_error("RenderScene: add_prototype after commit");
  if (V.rows() == 0 || F.rows() == 0) throw std::invalid_argument("RenderScene: a prototype needs vertices and triangles");
  if (F.minCoeff() < 0 || F.maxCoeff() >= V.rows())
    throw std::invalid_argument("RenderScene: a triangle names a vertex outside 0.." + std::to_string(V.rows() - 1));
  if (curvature.size() != 0 && curvature.size() != V.rows())
    throw std::invalid_argument("RenderScene: " + std::to_string(curvature.size()) + " curvatures for " +
                                std::to_string(V.rows()) + " vertices");
  auto prototype = std::make_unique<Prototype>();
  const MeshVertices N = vertex_normals(V, F);
  for (Eigen::Index v = 0; v < V.rows(); ++v) {
    prototype->positions.push_back(V.row(v).transpose().cast<float>());
    prototype->normals.push_back(N.row(v).transpose().cast<float>());
    if (curvature.size() != 0) prototype->curvature.push_back(static_cast<float>(curvature(v)));
  }
  for (Eigen::Index f = 0; f < F.rows(); ++f) prototype->triangles.push_back(F.row(f).transpose());

  const RTCBuildQuality quality = reuse == Reuse::kShared ? RTC_BUILD_QUALITY_HIGH : RTC_BUILD_QUALITY_MEDIUM;
  RTCGeometry mesh = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetGeometryBuildQuality(mesh, quality);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                3 * sizeof(float), static_cast<size_t>(V.rows())));
  for (Eigen::Index v = 0; v < V.rows(); ++v)
    for (int k = 0; k < 3; ++k) vertices[3 * v + k] = static_cast<float>(V(v, k));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(unsigned), static_cast<size_t>(F.rows())));
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) indices[3 * f + k] = static_cast<unsigned>(F(f, k));
  rtcCommitGeometry(mesh);
  prototype->scene = rtcNewScene(embree_->device);
  rtcSetSceneFlags(prototype->scene, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION);  // occluded(…, ignore)
  rtcSetSceneBuildQuality(prototype->scene, quality);
  rtcAttachGeometry(prototype->scene, mesh);
  rtcReleaseGeometry(mesh);
  rtcCommitScene(prototype->scene);
  check(embree_->device, "add_prototype");
  prototypes_.push_back(std::move(prototype));
  return static_cast<int>(prototypes_.size()) - 1;
}

RenderScene::Prototype& RenderScene::prototype_for_vertex_data(int prototype, Eigen::Index count,
                                                               const std::string& what) {
  if (committed_) throw std::logic_error("RenderScene: " + what + " after commit");
  if (prototype < 0 || prototype >= prototype_count())
    throw std::invalid_argument("RenderScene: no prototype " + std::to_string(prototype));
  Prototype& p = *prototypes_[prototype];
  if (count != static_cast<Eigen::Index>(p.positions.size()))
    throw std::invalid_argument("RenderScene: " + what + ": " + std::to_string(count) + " values for " +
                                std::to_string(p.positions.size()) + " vertices");
  return p;
}

void RenderScene::set_thickness(int prototype, const Eigen::VectorXd& thickness) {
  Prototype& p = prototype_for_vertex_data(prototype, thickness.size(), "set_thickness");
  p.thickness.assign(thickness.data(), thickness.data() + thickness.size());
}

void RenderScene::set_shading_normals(int prototype, const MeshVertices& N) {
  Prototype& p = prototype_for_vertex_data(prototype, N.rows(), "set_shading_normals");
  for (Eigen::Index v = 0; v < N.rows(); ++v) p.normals[v] = N.row(v).transpose().cast<float>().normalized();
}

int RenderScene::add_instance(int prototype, const Eigen::Affine3d& transform, int material, int label) {
  if (committed_) throw std::logic_error("RenderScene: add_instance after commit");
  if (prototype < 0 || prototype >= prototype_count())
    throw std::invalid_argument("RenderScene: no prototype " + std::to_string(prototype));
  const Eigen::Matrix3d L = transform.linear();
  const double det = L.determinant();
  const double scale = std::cbrt(det);
  if (!(det > 0.0) || !(L.transpose() * L).isApprox(scale * scale * Eigen::Matrix3d::Identity(), 1e-6)) {
    throw std::invalid_argument("RenderScene: instance transforms must be a rotation, a uniform scale and a translation");
  }
  Instance instance;
  instance.prototype = prototype;
  instance.material = material;
  instance.label = label;
  instance.linear = L.cast<float>();
  instance.inverse_linear = L.inverse().cast<float>();
  instance.normal_matrix = (L.inverse().transpose()).cast<float>();
  instance.translation = transform.translation().cast<float>();
  instance.curvature_scale = static_cast<float>(1.0 / scale);

  RTCGeometry geometry = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(geometry, prototypes_[prototype]->scene);
  float xfm[12];  // 3×4, column major: the three columns of L, then the translation
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r) xfm[3 * c + r] = static_cast<float>(L(r, c));
  for (int r = 0; r < 3; ++r) xfm[9 + r] = static_cast<float>(transform.translation()(r));
  rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
  rtcCommitGeometry(geometry);
  const unsigned id = static_cast<unsigned>(instances_.size());
  rtcAttachGeometryByID(embree_->top, geometry, id);  // geometry id = instance index
  rtcReleaseGeometry(geometry);
  check(embree_->device, "add_instance");
  instances_.push_back(instance);
  return static_cast<int>(id);
}

void RenderScene::commit() {
  rtcCommitScene(embree_->top);
  check(embree_->device, "commit");
  RTCBounds b;
  rtcGetSceneBounds(embree_->top, &b);
  const float diagonal = Eigen::Vector3f(b.upper_x - b.lower_x, b.upper_y - b.lower_y, b.upper_z - b.lower_z).norm();
  offset_ = instances_.empty() ? 1e-7f : std::max(1e-9f, 1e-6f * diagonal);
  committed_ = true;
}

void RenderScene::set_vertex_values(int instance, std::vector<float> values) {
  Instance& i = instances_.at(instance);
  if (values.size() != prototypes_[i.prototype]->positions.size())
    throw std::invalid_argument("RenderScene: " + std::to_string(values.size()) + " vertex values for " +
                                std::to_string(prototypes_[i.prototype]->positions.size()) + " vertices");
  i.vertex_values = std::move(values);
}

Eigen::Vector3i RenderScene::triangle(int instance, int primitive) const {
  return prototypes_[instances_.at(instance).prototype]->triangles.at(primitive);
}

void RenderScene::triangles_around(int instance, int primitive, std::vector<int>& out) const {
  Prototype& p = *prototypes_[instances_.at(instance).prototype];
  std::call_once(p.adjacency, [&p] {
    p.first_triangle.assign(p.positions.size() + 1, 0);
    for (const Eigen::Vector3i& t : p.triangles)
      for (int k = 0; k < 3; ++k) ++p.first_triangle[t[k] + 1];
    for (size_t v = 0; v < p.positions.size(); ++v) p.first_triangle[v + 1] += p.first_triangle[v];
    p.vertex_triangles.resize(p.first_triangle.back());
    std::vector<int> next(p.first_triangle.begin(), p.first_triangle.end() - 1);
    for (size_t f = 0; f < p.triangles.size(); ++f)
      for (int k = 0; k < 3; ++k) p.vertex_triangles[next[p.triangles[f][k]]++] = static_cast<int>(f);
  });
  out.clear();
  for (int k = 0; k < 3; ++k) {
    const int v = p.triangles.at(primitive)[k];
    out.insert(out.end(), p.vertex_triangles.begin() + p.first_triangle[v],
               p.vertex_triangles.begin() + p.first_triangle[v + 1]);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

std::array<Eigen::Vector3f, 3> RenderScene::world_triangle(int instance, int primitive) const {
  const Instance& i = instances_.at(instance);
  const Prototype& p = *prototypes_[i.prototype];
  const Eigen::Vector3i& t = p.triangles.at(primitive);
  std::array<Eigen::Vector3f, 3> corners;
  for (int k = 0; k < 3; ++k) corners[k] = i.linear * p.positions[t[k]] + i.translation;
  return corners;
}

int RenderScene::vertex_count(int instance) const {
  return static_cast<int>(prototypes_[instances_.at(instance).prototype]->positions.size());
}

std::vector<double> RenderScene::vertex_areas(int instance) const {
  const Instance& i = instances_.at(instance);
  const Prototype& p = *prototypes_[i.prototype];
  const double scale = 1.0 / i.curvature_scale;  // uniform scale s: areas grow by s²
  std::vector<double> area(p.positions.size(), 0.0);
  for (const Eigen::Vector3i& t : p.triangles) {
    const double a = 0.5 * scale * scale *
                     (p.positions[t[1]] - p.positions[t[0]]).cross(p.positions[t[2]] - p.positions[t[0]]).cast<double>().norm();
    for (int k = 0; k < 3; ++k) area[t[k]] += a / 3.0;
  }
  return area;
}

std::pair<Eigen::Vector3f, float> RenderScene::bounding_sphere(int instance) const {
  const Instance& i = instances_.at(instance);
  const Prototype& p = *prototypes_[i.prototype];
  Eigen::AlignedBox3f box;
  for (const Eigen::Vector3f& x : p.positions) box.extend(i.linear * x + i.translation);
  float radius = 0.0f;
  for (const Eigen::Vector3f& x : p.positions) radius = std::max(radius, (i.linear * x + i.translation - box.center()).norm());
  return {box.center(), radius};
}

namespace {

RTCRay embree_ray(const Ray& ray) {
  RTCRay r;
  r.org_x = ray.origin.x();
  r.org_y = ray.origin.y();
  r.org_z = ray.origin.z();
  r.dir_x = ray.direction.x();
  r.dir_y = ray.direction.y();
  r.dir_z = ray.direction.z();
  r.tnear = ray.t_min;
  r.tfar = ray.t_max;
  r.time = 0.0f;
  r.mask = ~0u;
  r.id = 0;
  r.flags = 0;
  return r;
}

void ignore_instance(const RTCFilterFunctionNArguments* args);

/// Embree's first hit of `ray` in `scene` (geomID invalid: none), seeing through top-level
/// instance `ignore` (−1: none).
RTCRayHit first_hit(RTCScene scene, const Ray& ray, int ignore = -1) {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit hit;
  hit.ray = embree_ray(ray);
  if (ignore >= 0) {
    context.filter = ignore_instance;
    hit.ray.id = static_cast<unsigned>(ignore);
  }
  hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  hit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene, &context, &hit);
  return hit;
}

}  // namespace

std::optional<ShadingPoint> RenderScene::intersect(const Ray& ray, int ignore) const {
  if (!committed_) throw std::logic_error("RenderScene: intersect before commit");
  const RTCRayHit hit = first_hit(embree_->top, ray, ignore);
  return shading_point(ray, hit.ray.tfar, hit.hit.instID[0], hit.hit.primID, hit.hit.u, hit.hit.v);
}

std::optional<ShadingPoint> RenderScene::intersect_instance(const Ray& ray, int instance) const {
  if (!committed_) throw std::logic_error("RenderScene: intersect before commit");
  const Instance& i = instances_.at(instance);
  // The ray in the prototype's frame, x = L⁻¹(x_world − t): the direction is not normalised,
  // so the ray parameter, and with it the hit's t, is the world ray's.
  Ray local = ray;
  local.origin = i.inverse_linear * (ray.origin - i.translation);
  local.direction = i.inverse_linear * ray.direction;
  const RTCRayHit hit = first_hit(prototypes_[i.prototype]->scene, local);
  if (hit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return shading_point(ray, hit.ray.tfar, static_cast<unsigned>(instance), hit.hit.primID, hit.hit.u, hit.hit.v);
}

void RenderScene::intersect_coherent(const std::vector<Ray>& rays, std::vector<std::optional<ShadingPoint>>& hits) const {
  if (!committed_) throw std::logic_error("RenderScene: intersect before commit");
  thread_local std::vector<RTCRayHit> batch;
  batch.resize(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    batch[i].ray = embree_ray(rays[i]);
    batch[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
    batch[i].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  rtcIntersect1M(embree_->top, &context, batch.data(), static_cast<unsigned>(batch.size()), sizeof(RTCRayHit));
  hits.resize(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const RTCRayHit& h = batch[i];
    hits[i] = shading_point(rays[i], h.ray.tfar, h.hit.instID[0], h.hit.primID, h.hit.u, h.hit.v);
  }
}

std::optional<ShadingPoint> RenderScene::shading_point(const Ray& ray, float t, unsigned instance_id, unsigned primitive,
                                                       float u, float v) const {
  if (instance_id == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  const Instance& instance = instances_[instance_id];
  const Prototype& prototype = *prototypes_[instance.prototype];
  const Eigen::Vector3i& tri = prototype.triangles[primitive];
  const float w = 1.0f - u - v;
  ShadingPoint p;
  p.t = t;
  p.position = ray.origin + p.t * ray.direction;
  const Eigen::Vector3f& a = prototype.positions[tri[0]];
  const Eigen::Vector3f& b = prototype.positions[tri[1]];
  const Eigen::Vector3f& c = prototype.positions[tri[2]];
  p.geometric_normal = (instance.normal_matrix * (b - a).cross(c - a)).normalized();
  const Eigen::Vector3f n = w * prototype.normals[tri[0]] + u * prototype.normals[tri[1]] + v * prototype.normals[tri[2]];
  p.shading_normal = (instance.normal_matrix * n).normalized();
  if (!prototype.curvature.empty()) {
    p.curvature = instance.curvature_scale * (w * prototype.curvature[tri[0]] + u * prototype.curvature[tri[1]] +
                                              v * prototype.curvature[tri[2]]);
  }
  if (!prototype.thickness.empty()) {
    p.thickness = (w * prototype.thickness[tri[0]] + u * prototype.thickness[tri[1]] + v * prototype.thickness[tri[2]]) /
                  instance.curvature_scale;
  }
  if (!instance.vertex_values.empty()) {
    p.baked = w * instance.vertex_values[tri[0]] + u * instance.vertex_values[tri[1]] + v * instance.vertex_values[tri[2]];
  }
  p.material = instance.material;
  p.instance = static_cast<int>(instance_id);
  p.primitive = static_cast<int>(primitive);
  p.barycentric = Eigen::Vector3f(w, u, v);
  return p;
}

namespace {

// Embree's context filter for rays that see through one instance: the instance's index
// travels in the ray's id (RTC_INVALID_GEOMETRY_ID: none).
void ignore_instance(const RTCFilterFunctionNArguments* args) {
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    if (RTCHitN_instID(args->hit, args->N, i, 0) == RTCRayN_id(args->ray, args->N, i)) args->valid[i] = 0;
  }
}

RTCRay occlusion_ray(const Ray& ray, int ignore) {
  RTCRay r = embree_ray(ray);
  r.id = ignore >= 0 ? static_cast<unsigned>(ignore) : RTC_INVALID_GEOMETRY_ID;
  return r;
}

}  // namespace

bool RenderScene::occluded(const Ray& ray, int ignore) const {
  if (!committed_) throw std::logic_error("RenderScene: occluded before commit");
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.filter = ignore_instance;
  RTCRay r = occlusion_ray(ray, ignore);
  rtcOccluded1(embree_->top, &context, &r);
  return r.tfar < 0.0f;  // Embree sets tfar to −∞ on a hit
}

void RenderScene::occluded_many(const std::vector<Ray>& rays, const std::vector<int>& ignore,
                                    std::vector<char>& occluded) const {
  if (!committed_) throw std::logic_error("RenderScene: occluded before commit");
  thread_local std::vector<RTCRay> batch;
  batch.resize(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) batch[i] = occlusion_ray(rays[i], ignore[i]);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.filter = ignore_instance;
  rtcOccluded1M(embree_->top, &context, batch.data(), static_cast<unsigned>(batch.size()), sizeof(RTCRay));
  occluded.resize(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) occluded[i] = batch[i].tfar < 0.0f;
}

}  // namespace rice::shading
