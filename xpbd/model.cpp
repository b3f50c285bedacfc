// Builders that turn a tet mesh and material numbers into the shared model; see model.hpp.
#include "xpbd/model.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "xpbd/tet_stencil.hpp"

namespace rice::xpbd {
namespace {

std::array<int, 4> tet_indices(const Tets& T, int t) { return {T(t, 0), T(t, 1), T(t, 2), T(t, 3)}; }

void require_positive_volumes(const Eigen::VectorXd& volumes, const char* who) {
  for (int t = 0; t < volumes.size(); ++t)
    if (!(volumes[t] > 0.0))
      throw std::invalid_argument(std::string(who) + ": tetrahedron " + std::to_string(t) +
                                  " has non-positive rest volume " + std::to_string(volumes[t]));
}

double beta_for(double compliance, double rayleigh_time) {
  if (rayleigh_time < 0.0) throw std::invalid_argument("Rayleigh time must be >= 0");
  return compliance > 0.0 ? rayleigh_time / compliance : 0.0;
}

}  // namespace

LameParameters lame_from_young_poisson(double young, double poisson) {
  if (!(young > 0.0) || !(poisson > -1.0 && poisson < 0.5))
    throw std::invalid_argument("lame_from_young_poisson: need E > 0 and -1 < nu < 0.5, got E=" +
                                std::to_string(young) + " nu=" + std::to_string(poisson));
  return {young / (2.0 * (1.0 + poisson)),
          young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson))};
}

Particles make_particles(const TetMesh& mesh, double density) {
  if (!(density > 0.0)) throw std::invalid_argument("make_particles: density must be > 0");
  const Eigen::VectorXd masses = lumped_masses(mesh.V, mesh.T, density);
  Particles p;
  p.x = mesh.V;
  p.v = Positions::Zero(mesh.V.rows(), 3);
  p.w.resize(masses.size());
  for (int i = 0; i < masses.size(); ++i) {
    if (!(masses[i] > 0.0))
      throw std::invalid_argument("make_particles: vertex " + std::to_string(i) +
                                  " belongs to no tetrahedron (zero mass)");
    p.w[i] = 1.0 / masses[i];
  }
  return p;
}

void add_neo_hookean_tets(Model& model, const TetMesh& mesh, LameParameters material,
                          double rayleigh_time, double strain_rate_time, TetMaterial tet_material) {
  if (!(material.mu > 0.0) || !(material.lambda + material.mu > 0.0))
    throw std::invalid_argument("add_neo_hookean_tets: need mu > 0 and lambda + mu > 0");
  if (tet_material == TetMaterial::kCorotated && !(material.lambda > 0.0))
    throw std::invalid_argument("add_neo_hookean_tets: the corotated material needs lambda > 0 (Poisson's ratio > 0)");
  if (!(strain_rate_time >= 0.0))
    throw std::invalid_argument("add_neo_hookean_tets: strain-rate damping time must be >= 0");
  if (strain_rate_time > 0.0 && !(3.0 * material.lambda + 2.0 * material.mu > 0.0))
    throw std::invalid_argument("add_neo_hookean_tets: strain-rate damping needs 3 lambda + 2 mu > 0");
  const Eigen::VectorXd volumes = tet_volumes(mesh.V, mesh.T);
  require_positive_volumes(volumes, "add_neo_hookean_tets");
  for (int t = 0; t < mesh.T.rows(); ++t) {
    NeoHookeanTet tet;
    tet.particles = tet_indices(mesh.T, t);
    tet.Dm_inv = edge_matrix(tet_positions(mesh.V, mesh.T, t)).inverse();
    tet.rest_volume = volumes[t];
    tet.mu = material.mu;
    tet.lambda = material.lambda + material.mu;  // so that small strains see Lamé (μ, λ)
    tet.material = tet_material;  // before β: the compliances depend on it
    tet.beta_deviatoric = beta_for(tet.compliance_deviatoric(), rayleigh_time);
    tet.beta_hydrostatic = beta_for(tet.compliance_hydrostatic(), rayleigh_time);
    tet.strain_rate_damping = strain_rate_time;
    model.neo_hookean.push_back(tet);
  }
}

void add_edge_springs(Model& model, const TetMesh& mesh, double young, double rayleigh_time) {
  if (!(young > 0.0)) throw std::invalid_argument("add_edge_springs: Young's modulus must be > 0");
  const Eigen::VectorXd volumes = tet_volumes(mesh.V, mesh.T);
  require_positive_volumes(volumes, "add_edge_springs");
  // Unique edges (smaller index first, sorted) with the volume attributed to each: a sixth of
  // every tet that has it.
  std::map<std::pair<int, int>, double> edge_volume;
  for (int t = 0; t < mesh.T.rows(); ++t)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        edge_volume[std::minmax(mesh.T(t, a), mesh.T(t, b))] += volumes[t] / 6.0;
  for (const auto& [edge, volume] : edge_volume) {
    const double length = (mesh.V.row(edge.first) - mesh.V.row(edge.second)).norm();
    const double compliance = length * length / (young * volume);
    model.distances.push_back(
        {{edge.first, edge.second}, length, compliance, beta_for(compliance, rayleigh_time)});
  }
}

void add_tet_volumes(Model& model, const TetMesh& mesh, double bulk_modulus, double rayleigh_time) {
  if (!(bulk_modulus > 0.0)) throw std::invalid_argument("add_tet_volumes: bulk modulus must be > 0");
  const Eigen::VectorXd volumes = tet_volumes(mesh.V, mesh.T);
  require_positive_volumes(volumes, "add_tet_volumes");
  for (int t = 0; t < mesh.T.rows(); ++t) {
    const double compliance = 1.0 / (bulk_modulus * volumes[t]);
    model.volumes.push_back(
        {tet_indices(mesh.T, t), volumes[t], compliance, beta_for(compliance, rayleigh_time)});
  }
}

void pin_particles(Model& model, const std::vector<int>& indices) {
  for (const int i : indices) {
    if (i < 0 || i >= model.particles.size())
      throw std::out_of_range("pin_particles: particle " + std::to_string(i) + " does not exist");
    model.particles.w[i] = 0.0;
    model.particles.v.row(i).setZero();
  }
}

}  // namespace rice::xpbd
