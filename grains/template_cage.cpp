// The template cage; see template_cage.hpp.
#include "grains/template_cage.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "grains/tet_quality.hpp"

namespace rice::grains {

void validate(const TemplateCageParameters& p) {
  if (p.stations < 1 || p.stations > 100)
    throw std::invalid_argument("template cage: stations must lie in [1, 100], got " + std::to_string(p.stations));
  if (!(p.tip_extension > 0.0 && p.tip_extension <= 10.0))
    throw std::invalid_argument("template cage: tip extension must lie in (0, 10], got " + std::to_string(p.tip_extension));
  if (!(p.margin >= 0.0 && p.margin <= 1.0))
    throw std::invalid_argument("template cage: margin must lie in [0, 1], got " + std::to_string(p.margin));
}

namespace {

/// The spindle's profile: stations x_j with scales k_j, and the tips' x.
struct Profile {
  std::vector<double> x, k;
  double tip_minus = 0.0, tip_plus = 0.0;
};

/// The stations' k: every inner station takes the largest q of the points between the first
/// and last station (so a point there lies inside whatever the segment), and each end station
/// what the points beyond it need under a pyramid to a tip `tip_extension` of their reach
/// further out: k_end ≥ q (x_tip − x_end)/(x_tip − x) for each. Then all grow by the margin.
Profile fit_profile(const Vertices& V, const Eigen::VectorXd& q, const TemplateCageParameters& p) {
  const double x_min = V.col(0).minCoeff(), x_max = V.col(0).maxCoeff();
  const int n = p.stations;
  Profile s;
  for (int j = 0; j < n; ++j) s.x.push_back(x_min + (j + 1.0) / (n + 1.0) * (x_max - x_min));
  double inner = 0.0;
  for (Eigen::Index i = 0; i < V.rows(); ++i)
    if (V(i, 0) >= s.x.front() && V(i, 0) <= s.x.back()) inner = std::max(inner, q[i]);
  s.k.assign(n, inner);
  s.tip_minus = s.x.front() - (1.0 + p.tip_extension) * (s.x.front() - x_min);
  s.tip_plus = s.x.back() + (1.0 + p.tip_extension) * (x_max - s.x.back());
  for (Eigen::Index i = 0; i < V.rows(); ++i) {
    const double x = V(i, 0);
    if (x < s.x.front())
      s.k.front() = std::max(s.k.front(), q[i] * (s.x.front() - s.tip_minus) / (x - s.tip_minus));
    if (x > s.x.back()) s.k.back() = std::max(s.k.back(), q[i] * (s.tip_plus - s.x.back()) / (s.tip_plus - x));
  }
  for (double& k : s.k) k *= 1.0 + p.margin;
  return s;
}

/// Adds tet (a, b, c, d), turned positive; a flat one is an error.
void add_tet(const Vertices& V, std::vector<std::array<int, 4>>& tets, std::array<int, 4> t) {
  const auto corner = [&](int k) -> Vec3 { return V.row(t[k]).transpose(); };
  const double volume = tet_signed_volume(corner(0), corner(1), corner(2), corner(3));
  if (!(std::abs(volume) > 0.0)) throw std::runtime_error("template cage: a flat tet");
  if (volume < 0.0) std::swap(t[2], t[3]);
  tets.push_back(t);
}

}  // namespace

VolumeMesh make_template_cage(const Vertices& V, const TemplateCageParameters& parameters) {
  validate(parameters);
  if (V.rows() < 4) throw std::invalid_argument("template cage: fewer than 4 points to enclose");
  // Diamond semi-diagonals: √2 times the largest |y| and |z|.
  const double a = std::sqrt(2.0) * V.col(1).cwiseAbs().maxCoeff();
  const double b = std::sqrt(2.0) * V.col(2).cwiseAbs().maxCoeff();
  if (!(a > 0.0 && b > 0.0)) throw std::invalid_argument("template cage: the points lie in a plane through the x axis");
  const Eigen::VectorXd q = V.col(1).cwiseAbs() / a + V.col(2).cwiseAbs() / b;
  const Profile s = fit_profile(V, q, parameters);

  const int n = parameters.stations;
  VolumeMesh cage;
  cage.V.resize(4 * n + 2, 3);
  // Diamond j: 4j + (0: +y, 1: +z, 2: −y, 3: −z), going round; tips last.
  for (int j = 0; j < n; ++j) {
    cage.V.row(4 * j + 0) << s.x[j], s.k[j] * a, 0.0;
    cage.V.row(4 * j + 1) << s.x[j], 0.0, s.k[j] * b;
    cage.V.row(4 * j + 2) << s.x[j], -s.k[j] * a, 0.0;
    cage.V.row(4 * j + 3) << s.x[j], 0.0, -s.k[j] * b;
  }
  const int tip_minus = 4 * n, tip_plus = 4 * n + 1;
  cage.V.row(tip_minus) << s.tip_minus, 0.0, 0.0;
  cage.V.row(tip_plus) << s.tip_plus, 0.0, 0.0;

  std::vector<std::array<int, 4>> tets;
  for (int j = 0; j + 1 < n; ++j) {
    // Kuhn's six tets around the diagonal d0 → d2' of the hexahedron (d0 d1 d2 d3)(d0' … d3');
    // every diamond is cut along d0–d2 from both sides, so neighbours share their faces.
    const int d = 4 * j, u = 4 * (j + 1);
    for (const std::array<int, 4>& t : {std::array<int, 4>{d, d + 1, d + 2, u + 2}, {d, d + 1, u + 1, u + 2},
                                        {d, d + 3, d + 2, u + 2}, {d, d + 3, u + 3, u + 2},
                                        {d, u, u + 1, u + 2}, {d, u, u + 3, u + 2}})
      add_tet(cage.V, tets, t);
  }
  for (const auto& [tip, d] : {std::pair{tip_minus, 0}, std::pair{tip_plus, 4 * (n - 1)}}) {
    add_tet(cage.V, tets, {tip, d, d + 1, d + 2});
    add_tet(cage.V, tets, {tip, d, d + 2, d + 3});
  }
  cage.T.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (size_t t = 0; t < tets.size(); ++t)
    for (int k = 0; k < 4; ++k) cage.T(static_cast<Eigen::Index>(t), k) = tets[t][k];
  return cage;
}

}  // namespace rice::grains
