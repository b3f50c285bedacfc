// Colliders as drawn; see collider_drawing.hpp.
#include "experiments/render/collider_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "experiments/io/atomic_file.hpp"
#include "experiments/io/csv_table.hpp"
#include "experiments/io/numeric_csv.hpp"
#include "experiments/render/crease_split.hpp"
#include "grains/mesh_io.hpp"

namespace rice::experiments {
namespace {

/// The surface of revolution about z of the profile (r_i, z_i), from the bottom pole (r = 0)
/// to the top pole (r = 0), in `segments` slices: outward when z increases along the profile.
grains::SurfaceMesh lathe(const std::vector<std::pair<double, double>>& profile, int segments) {
  const int rings = static_cast<int>(profile.size()) - 2;  // the rings between the poles
  grains::SurfaceMesh m{grains::Vertices(2 + rings * segments, 3), grains::Triangles(2 * segments * rings, 3)};
  m.V.row(0) << 0, 0, profile.front().second;
  m.V.row(1) << 0, 0, profile.back().second;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / segments, r = profile[i + 1].first;
      m.V.row(2 + i * segments + j) << r * std::cos(phi), r * std::sin(phi), profile[i + 1].second;
    }
  const auto at = [&](int i, int j) { return 2 + i * segments + (j % segments); };
  int f = 0;
  for (int j = 0; j < segments; ++j) {
    m.F.row(f++) << 0, at(0, j + 1), at(0, j);
    m.F.row(f++) << 1, at(rings - 1, j), at(rings - 1, j + 1);
    for (int i = 0; i + 1 < rings; ++i) {
      m.F.row(f++) << at(i, j), at(i, j + 1), at(i + 1, j + 1);
      m.F.row(f++) << at(i, j), at(i + 1, j + 1), at(i + 1, j);
    }
  }
  return m;
}

/// A capsule's profile: hemispheres of radius r about z = ±h (h = 0: a sphere).
std::vector<std::pair<double, double>> capsule_profile(double r, double h) {
  constexpr int kQuarter = 12;
  std::vector<std::pair<double, double>> profile;
  for (int k = 0; k <= kQuarter; ++k) {
    const double a = -std::numbers::pi / 2 + std::numbers::pi / 2 * k / kQuarter;
    profile.emplace_back(r * std::cos(a), -h + r * std::sin(a));
  }
  for (int k = h > 0.0 ? 0 : 1; k <= kQuarter; ++k) {
    const double a = std::numbers::pi / 2 * k / kQuarter;
    profile.emplace_back(r * std::cos(a), h + r * std::sin(a));
  }
  return profile;
}

/// A box's six faces, each its own four vertices: the renderer interpolates vertex normals,
/// and corners shared by a large top and a thin side bent the side's normals down (black).
grains::SurfaceMesh box(const xpbd::Vec3& half) {
  grains::SurfaceMesh m{grains::Vertices(24, 3), grains::Triangles(12, 3)};
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int face = 2 * axis + side, u = (axis + 1) % 3, v = (axis + 2) % 3;
      const double sign = side ? 1.0 : -1.0;
      const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (int c = 0; c < 4; ++c) {
        xpbd::Vec3 p;
        p[axis] = sign * half[axis];
        p[u] = corners[c][0] * half[u];
        p[v] = corners[c][1] * half[v];
        m.V.row(4 * face + c) = p.transpose();
      }
      // (u, v, axis) is right-handed: counter-clockwise in (u, v) faces +axis.
      const int a = 4 * face;
      m.F.row(2 * face) = side ? Eigen::RowVector3i(a, a + 1, a + 2) : Eigen::RowVector3i(a, a + 2, a + 1);
      m.F.row(2 * face + 1) = side ? Eigen::RowVector3i(a, a + 2, a + 3) : Eigen::RowVector3i(a, a + 3, a + 2);
    }
  return m;
}

}  // namespace

grains::SurfaceMesh collider_surface(const xpbd::Collider& c) {
  switch (c.shape) {
    case xpbd::ColliderShape::kHalfSpace: {
      grains::SurfaceMesh m{grains::Vertices(4, 3), grains::Triangles(2, 3)};
      m.V << -0.1, -0.1, 0, 0.1, -0.1, 0, 0.1, 0.1, 0, -0.1, 0.1, 0;
      m.F << 0, 1, 2, 0, 2, 3;
      return m;
    }
    case xpbd::ColliderShape::kSphere: return lathe(capsule_profile(c.radius, 0.0), 48);
    case xpbd::ColliderShape::kCapsule: return lathe(capsule_profile(c.radius, c.half_length), 48);
    case xpbd::ColliderShape::kBox: return box(c.half_extents);
    case xpbd::ColliderShape::kDistanceGrid: break;
  }
  throw std::invalid_argument("collider_surface: a distance-grid collider has no analytic surface");
}

grains::SurfaceMesh cutaway_walls(const grains::SurfaceMesh& room, const Eigen::Vector3d& eye) {
  std::vector<Eigen::RowVector3i> kept;
  for (Eigen::Index f = 0; f < room.F.rows(); ++f) {
    const Eigen::Vector3d a = room.V.row(room.F(f, 0)), b = room.V.row(room.F(f, 1)), c = room.V.row(room.F(f, 2));
    if ((b - a).cross(c - a).dot(eye - a) < 0.0) kept.emplace_back(room.F(f, 0), room.F(f, 2), room.F(f, 1));
  }
  grains::SurfaceMesh walls{room.V, grains::Triangles(static_cast<Eigen::Index>(kept.size()), 3)};
  for (std::size_t f = 0; f < kept.size(); ++f) walls.F.row(static_cast<Eigen::Index>(f)) = kept[f];
  return walls;
}

namespace {

/// The yield offset at `time`, linear between the rows of yield.csv around it, the nearest
/// row's beyond them.
Eigen::Vector3d yielded_offset(const ColliderDrawing& collider, double time) {
  const auto& rows = collider.yielded;
  if (rows.empty()) return Eigen::Vector3d::Zero();
  if (time <= rows.front().first) return rows.front().second;
  if (time >= rows.back().first) return rows.back().second;
  const auto next = std::upper_bound(rows.begin(), rows.end(), time,
                                     [](double t, const auto& row) { return t < row.first; });
  const auto& [t0, a] = *(next - 1);
  const auto& [t1, b] = *next;
  const double s = (time - t0) / (t1 - t0);
  return (1.0 - s) * a + s * b;
}

/// yield.csv's rows into the drawings they name (the collider numbers of colliders.csv).
void read_yield_offsets(const std::filesystem::path& path, std::vector<ColliderDrawing>& drawings) {
  const NumericCsv table = read_numeric_csv(path);
  for (const std::vector<double>& row : table.rows) {
    const auto value = [&](const char* name) { return row[table.column(name)]; };
    const double k = value("collider");
    if (!(k >= 1.0 && k <= static_cast<double>(drawings.size())))
      throw std::runtime_error(path.string() + ": a row names collider " + cell(k) + ", of " +
                               cell(static_cast<long>(drawings.size())));
    const Eigen::Vector3d axis(value("axis_x"), value("axis_y"), value("axis_z"));
    drawings[static_cast<size_t>(k) - 1].yielded.emplace_back(value("time_s"), value("offset_m") * axis);
  }
}

}  // namespace

Eigen::Affine3d collider_placement(const ColliderDrawing& collider, double time) {
  const xpbd::ColliderKeyframe pose = xpbd::collider_pose(collider.motion, time);
  return Eigen::Translation3d(pose.translation + yielded_offset(collider, time)) * pose.rotation *
         Eigen::Scaling(pose.scale);
}

Eigen::AlignedBox3d drawn_colliders_box(const std::vector<ColliderDrawing>& colliders,
                                        const std::vector<double>& times) {
  Eigen::AlignedBox3d box;
  for (const ColliderDrawing& c : colliders) {
    for (const double time : times) {
      if (!xpbd::collider_present(c.motion, time)) continue;
      const Eigen::Affine3d place = collider_placement(c, time);
      for (Eigen::Index v = 0; v < c.mesh.V.rows(); ++v) box.extend(place * c.mesh.V.row(v).transpose());
    }
  }
  return box;
}

void write_collider_drawings(const std::vector<ColliderDrawing>& drawings, const std::filesystem::path& run) {
  if (drawings.empty()) return;
  make_output_folder(run / "colliders");
  CsvTable table({"collider", "material", "hollow", "removed_at_s", "time_s", "x", "y", "z", "qw", "qx", "qy", "qz", "scale"});
  for (std::size_t k = 0; k < drawings.size(); ++k) {
    const ColliderDrawing& d = drawings[k];
    write_file_atomically(run / "colliders" / ("collider_" + std::to_string(k + 1) + ".obj"),
                          [&](std::ostream& out) { grains::write_obj(out, d.mesh); });
    const long material = std::find(collider_material_names().begin(), collider_material_names().end(), d.material) -
                          collider_material_names().begin();
    for (const xpbd::ColliderKeyframe& p : d.motion.motion)
      table.add_row({cell(static_cast<long>(k + 1)), cell(material), cell(d.hollow ? 1 : 0), cell(d.motion.removal_time),
                     cell(p.time),
                     cell(p.translation.x()), cell(p.translation.y()), cell(p.translation.z()), cell(p.rotation.w()),
                     cell(p.rotation.x()), cell(p.rotation.y()), cell(p.rotation.z()), cell(p.scale)});
  }
  write_file_atomically(run / "colliders" / "colliders.csv", table.text());
}

std::vector<ColliderDrawing> read_collider_drawings(const std::filesystem::path& run) {
  const std::filesystem::path table_path = run / "colliders" / "colliders.csv";
  if (!std::filesystem::exists(table_path)) return {};
  const NumericCsv table = read_numeric_csv(table_path);
  std::vector<ColliderDrawing> drawings;
  for (const std::vector<double>& row : table.rows) {
    const auto value = [&](const char* name) { return row[table.column(name)]; };
    const double k_value = value("collider"), material_value = value("material");
    if (!(std::abs(k_value) < 1e6 && std::abs(material_value) < 1e6))  // before the casts: no NaN, inf or huge
      throw std::runtime_error(table_path.string() + ": a row's collider or material is not a small number");
    const int k = static_cast<int>(k_value), material = static_cast<int>(material_value);
    if (k < 1 || k > static_cast<int>(drawings.size()) + 1 || material < 0 ||
        material >= static_cast<int>(collider_material_names().size()))
      throw std::runtime_error(table_path.string() + ": a row names collider " + std::to_string(k) + ", material " +
                               std::to_string(material));
    if (k == static_cast<int>(drawings.size()) + 1) {
      ColliderDrawing& d = drawings.emplace_back();
      d.mesh = split_creases(grains::read_surface_mesh(run / "colliders" / ("collider_" + std::to_string(k) + ".obj")));
      d.material = collider_material_names()[material];
      d.hollow = value("hollow") != 0.0;
      d.motion.motion.clear();
      d.motion.removal_time = value("removed_at_s");
    }
    drawings.back().motion.motion.push_back(
        {value("time_s"), xpbd::Vec3(value("x"), value("y"), value("z")),
         xpbd::Quat(value("qw"), value("qx"), value("qy"), value("qz")), value("scale")});
  }
  if (std::filesystem::exists(run / "yield.csv")) read_yield_offsets(run / "yield.csv", drawings);
  return drawings;
}

}  // namespace rice::experiments
