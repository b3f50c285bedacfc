// CGAL Mesh_3 on a polyhedral domain (see simulation_mesh.hpp). Kept in its own translation
// unit: it is the slowest file of the project to compile.
#include "grains/simulation_mesh.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polyhedral_mesh_domain_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/make_mesh_3.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "grains/surface_measures.hpp"
#include "grains/tet_quality.hpp"

namespace rice::grains {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Polyhedron = CGAL::Surface_mesh<Point>;
using Domain = CGAL::Polyhedral_mesh_domain_3<Polyhedron, Kernel>;
using Triangulation = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using Complex = CGAL::Mesh_complex_3_in_triangulation_3<Triangulation>;
using Criteria = CGAL::Mesh_criteria_3<Triangulation>;

void check_mesh(bool ok, const std::string& parameter, const std::string& expected) {
  if (!ok) throw std::invalid_argument("simulation mesh parameter " + parameter + " must be " + expected);
}

Polyhedron to_cgal(const SurfaceMesh& surface) {
  Polyhedron polyhedron;
  std::vector<Polyhedron::Vertex_index> vertices;
  for (Eigen::Index v = 0; v < surface.V.rows(); ++v)
    vertices.push_back(polyhedron.add_vertex(Point(surface.V(v, 0), surface.V(v, 1), surface.V(v, 2))));
  for (Eigen::Index f = 0; f < surface.F.rows(); ++f)
    if (polyhedron.add_face(vertices[surface.F(f, 0)], vertices[surface.F(f, 1)], vertices[surface.F(f, 2)]) ==
        Polyhedron::null_face())
      throw std::invalid_argument("simulation mesh: face " + std::to_string(f) + " breaks the surface's manifoldness");
  return polyhedron;
}

// Tets of the complex as plain matrices, only the vertices they use, positively oriented.
VolumeMesh from_complex(const Complex& complex) {
  std::map<Triangulation::Vertex_handle, int> index;
  VolumeMesh mesh;
  std::vector<Vec3> vertices;
  std::vector<Eigen::Vector4i> tets;
  for (auto cell = complex.cells_in_complex_begin(); cell != complex.cells_in_complex_end(); ++cell) {
    Eigen::Vector4i tet;
    for (int k = 0; k < 4; ++k) {
      const auto vertex = cell->vertex(k);
      const auto [it, inserted] = index.emplace(vertex, static_cast<int>(vertices.size()));
      if (inserted) {
        const auto& p = complex.triangulation().point(vertex);
        vertices.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      }
      tet[k] = it->second;
    }
    if (tet_signed_volume(vertices[tet[0]], vertices[tet[1]], vertices[tet[2]], vertices[tet[3]]) < 0.0)
      std::swap(tet[2], tet[3]);
    tets.push_back(tet);
  }
  mesh.V.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (size_t v = 0; v < vertices.size(); ++v) mesh.V.row(static_cast<Eigen::Index>(v)) = vertices[v];
  mesh.T.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (size_t t = 0; t < tets.size(); ++t) mesh.T.row(static_cast<Eigen::Index>(t)) = tets[t];
  return mesh;
}

/// Mesh_3's criteria take a size field as a functor of (point, dimension, index).
struct SizeField {
  using FT = Kernel::FT;
  const std::function<double(const Vec3&)>* size;
  template <class Index>
  FT operator()(const Point& p, int /*dimension*/, const Index& /*index*/) const {
    return (*size)(Vec3(p.x(), p.y(), p.z()));
  }
};

/// One Mesh_3 run on the polyhedron, seeded: Mesh_3 draws from the domain's generator and, in
/// places, from CGAL's thread-local default generator, whose state would carry over from
/// earlier calls, so both are seeded.
template <class Size>
VolumeMesh mesh_once(const Polyhedron& polyhedron, const Size& size, double facet_distance,
                     const SimulationMeshParameters& p, std::uint64_t seed) {
  namespace params = CGAL::parameters;
  CGAL::get_default_random() = CGAL::Random(static_cast<unsigned int>(seed));
  CGAL::Random random(static_cast<unsigned int>(seed));
  const Domain domain(polyhedron, &random);
  const Criteria criteria(params::facet_angle = p.facet_angle_degrees, params::facet_size = size,
                          params::facet_distance = facet_distance,
                          params::cell_radius_edge_ratio = p.radius_edge_ratio, params::cell_size = size);
  using Optimiser = SimulationMeshParameters::Optimiser;
  const int iterations = p.optimiser_iterations;
  // time_limit = 0: no limit, so the result depends on the seed alone.
  const Complex complex = CGAL::make_mesh_3<Complex>(
      domain, criteria,
      p.optimiser == Optimiser::kOdt
          ? params::odt(params::time_limit = 0, params::max_iteration_number = iterations)
          : params::no_odt(),
      p.optimiser == Optimiser::kLloyd
          ? params::lloyd(params::time_limit = 0, params::max_iteration_number = iterations)
          : params::no_lloyd(),
      p.perturb_sliver_degrees > 0.0
          ? params::perturb(params::time_limit = 0, params::sliver_bound = p.perturb_sliver_degrees)
          : params::no_perturb(),
      p.exude_sliver_degrees > 0.0 ? params::exude(params::time_limit = 0, params::sliver_bound = p.exude_sliver_degrees)
                                   : params::no_exude());
  return from_complex(complex);
}

/// Mesh_3's vertex count falls as its size bounds grow, but noisily, and only down to a floor
/// that its random initial points and the facet-angle bound set (seen: 12 to 46 vertices for
/// eight japonica grains at bounds beyond the grain's size). The search scales the bounds by
/// 1.2 per try until the count crosses the range, then bisects (geometrically) the scales
/// either side of it. Above the range at 1.2^7 (the floor), or with the bracket closed to 1%
/// without landing, the next seed searches afresh from the scale reached. Until then its
/// tries are those of a plain 1.2 step (a mesh that lands keeps its vertices).
struct ScaleSearch {
  double scale = 1.0;
  double too_fine = 0.0, too_coarse = 0.0;  ///< scales that gave too many / too few vertices; 0: none yet
  std::uint64_t reseeds = 0;

  void next(bool too_many_vertices) {
    (too_many_vertices ? too_fine : too_coarse) = scale;
    const bool at_floor = too_many_vertices && scale > 3.5;
    const bool closed = too_fine > 0.0 && too_coarse > 0.0 && too_coarse / too_fine < 1.01;
    if (at_floor || closed) {
      too_fine = too_coarse = 0.0;
      ++reseeds;
    } else if (too_fine > 0.0 && too_coarse > 0.0) {
      scale = std::sqrt(too_fine * too_coarse);
    } else {
      scale = too_many_vertices ? scale * 1.2 : scale / 1.2;
    }
  }
};

/// Mesh_3 runs of one make_simulation_mesh; a coarse grain's run takes about 20 ms.
constexpr int kMeshAttempts = 24;

void require_valid_tets(const VolumeMesh& mesh) {
  if (mesh.T.rows() == 0) throw std::runtime_error("simulation mesh: Mesh_3 produced no tetrahedra");
  const TetQuality quality = measure_tet_quality(mesh);
  if (!(quality.min_volume > 0.0))
    throw std::runtime_error("simulation mesh: a tetrahedron has volume " + std::to_string(quality.min_volume));
}

}  // namespace

void validate(const SimulationMeshParameters& p) {
  check_mesh(p.min_vertices >= 4 && p.min_vertices <= p.max_vertices, "vertex range",
          "4 <= min_vertices <= max_vertices");
  check_mesh(p.edge_size > 0.0, "edge_size", "positive");
  check_mesh(p.facet_distance > 0.0, "facet_distance", "positive");
  check_mesh(p.facet_angle_degrees > 0.0 && p.facet_angle_degrees <= 30.0, "facet_angle_degrees",
          "in (0, 30] (Mesh_3 terminates for angles up to 30)");
  check_mesh(p.radius_edge_ratio >= 2.0, "radius_edge_ratio", ">= 2 (Mesh_3 terminates for ratios >= 2)");
  check_mesh(p.exude_sliver_degrees >= 0.0 && p.exude_sliver_degrees < 60.0, "exude_sliver_degrees", "in [0, 60)");
  check_mesh(p.perturb_sliver_degrees >= 0.0 && p.perturb_sliver_degrees < 60.0, "perturb_sliver_degrees", "in [0, 60)");
  check_mesh(p.optimiser_iterations >= 1 && p.optimiser_iterations <= 1000, "optimiser_iterations", "in [1, 1000]");
}

const char* optimiser_name(SimulationMeshParameters::Optimiser optimiser) {
  using Optimiser = SimulationMeshParameters::Optimiser;
  return optimiser == Optimiser::kOdt ? "odt" : optimiser == Optimiser::kLloyd ? "lloyd" : "none";
}

VolumeMesh make_simulation_mesh(const SurfaceMesh& surface, const SimulationMeshParameters& p, std::uint64_t seed) {
  validate(p);
  const Vec3 extent = bounding_box_extent(surface.V);
  const double size_scale = std::cbrt(extent.prod()), distance_scale = extent.minCoeff();
  const Polyhedron polyhedron = to_cgal(surface);
  const auto outside_range = [&p](const VolumeMesh& mesh) {
    const auto n = static_cast<int>(mesh.V.rows());
    return std::max({p.min_vertices - n, n - p.max_vertices, 0});
  };
  VolumeMesh best;
  ScaleSearch search;
  for (int attempt = 0; attempt < kMeshAttempts; ++attempt) {
    VolumeMesh mesh = mesh_once(polyhedron, search.scale * p.edge_size * size_scale,
                                search.scale * p.facet_distance * distance_scale, p, seed + search.reseeds);
    const bool too_many_vertices = mesh.V.rows() > p.max_vertices;
    if (attempt == 0 || outside_range(mesh) < outside_range(best)) best = std::move(mesh);
    if (outside_range(best) == 0) break;
    search.next(too_many_vertices);
  }
  require_valid_tets(best);
  return best;
}

VolumeMesh make_graded_mesh(const SurfaceMesh& surface, const std::function<double(const Vec3&)>& size,
                            double facet_distance, const SimulationMeshParameters& p, std::uint64_t seed) {
  validate(p);
  if (!(facet_distance > 0.0)) throw std::invalid_argument("graded mesh: facet_distance must be positive");
  const VolumeMesh mesh = mesh_once(to_cgal(surface), SizeField{&size}, facet_distance, p, seed);
  require_valid_tets(mesh);
  return mesh;
}

}  // namespace rice::grains
