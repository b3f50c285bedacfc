// The translucent rice model's table and its least-squares fit (translucency.hpp).
#include "shading/translucency.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rice::shading {

TranslucencyTable::TranslucencyTable(double d_max, int d_nodes, int c_nodes, std::vector<double> values)
    : d_max_(d_max), nd_(d_nodes), nc_(c_nodes), values_(std::move(values)) {
  if (!(d_max > 0.0) || d_nodes < 2 || c_nodes < 2)
    throw std::invalid_argument("TranslucencyTable: needs d_max > 0 and at least 2 nodes on each axis");
  if (values_.size() != static_cast<std::size_t>(d_nodes) * c_nodes)
    throw std::invalid_argument("TranslucencyTable: " + std::to_string(values_.size()) + " values for a " +
                                std::to_string(d_nodes) + " x " + std::to_string(c_nodes) + " grid");
}

TranslucencyTable::Stencil TranslucencyTable::stencil(double thickness, double cos_theta) const {
  const double x = std::clamp(thickness / d_max_, 0.0, 1.0) * (nd_ - 1);
  const double y = (std::clamp(cos_theta, -1.0, 1.0) + 1.0) / 2.0 * (nc_ - 1);
  const int i = std::min(static_cast<int>(x), nd_ - 2), j = std::min(static_cast<int>(y), nc_ - 2);
  const double fx = x - i, fy = y - j;
  return {{i * nc_ + j, i * nc_ + j + 1, (i + 1) * nc_ + j, (i + 1) * nc_ + j + 1},
          {(1 - fx) * (1 - fy), (1 - fx) * fy, fx * (1 - fy), fx * fy}};
}

double TranslucencyTable::operator()(double thickness, double cos_theta) const {
  const Stencil s = stencil(thickness, cos_theta);
  double tau = 0.0;
  for (int k = 0; k < 4; ++k) tau += s.weight[k] * values_[s.node[k]];
  return tau;
}

TranslucencyTable TranslucencyTable::blend(const TranslucencyTable& a, const TranslucencyTable& b, double t) {
  if (a.nd_ != b.nd_ || a.nc_ != b.nc_ || a.d_max_ != b.d_max_)
    throw std::invalid_argument("TranslucencyTable::blend: the tables' grids differ");
  std::vector<double> values(a.values_.size());
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = (1.0 - t) * a.values_[k] + t * b.values_[k];
  return {a.d_max_, a.nd_, a.nc_, std::move(values)};
}

namespace {

// Adds λ (x_a − 2 x_b + x_c)² to the normal equations.
void add_second_difference(Eigen::MatrixXd& normal, int a, int b, int c, double lambda) {
  const int nodes[3] = {a, b, c};
  const double coefficients[3] = {1.0, -2.0, 1.0};
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) normal(nodes[p], nodes[q]) += lambda * coefficients[p] * coefficients[q];
}

}  // namespace

TranslucencyTable fit_translucency(const std::vector<TranslucencySample>& samples, double d_max, int d_nodes,
                                   int c_nodes, double smoothing) {
  if (samples.empty()) throw std::invalid_argument("fit_translucency: no samples");
  const TranslucencyTable grid(d_max, d_nodes, c_nodes, std::vector<double>(static_cast<std::size_t>(d_nodes) * c_nodes));
  const int n = d_nodes * c_nodes;
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  double total = 0.0;
  for (const TranslucencySample& s : samples) total += s.weight;
  if (!(total > 0.0)) throw std::invalid_argument("fit_translucency: the samples' weights sum to zero");
  for (const TranslucencySample& s : samples) {
    const TranslucencyTable::Stencil st = grid.stencil(s.thickness, s.cos_theta);
    const double w = s.weight / total;
    for (int p = 0; p < 4; ++p) {
      rhs(st.node[p]) += w * st.weight[p] * s.residual;
      for (int q = 0; q < 4; ++q) normal(st.node[p], st.node[q]) += w * st.weight[p] * st.weight[q];
    }
  }
  for (int i = 0; i < d_nodes; ++i)
    for (int j = 0; j + 2 < c_nodes; ++j)
      add_second_difference(normal, i * c_nodes + j, i * c_nodes + j + 1, i * c_nodes + j + 2, smoothing);
  for (int j = 0; j < c_nodes; ++j)
    for (int i = 0; i + 2 < d_nodes; ++i)
      add_second_difference(normal, i * c_nodes + j, (i + 1) * c_nodes + j, (i + 2) * c_nodes + j, smoothing);
  normal.diagonal().array() += 1e-12;  // nodes neither samples nor curvature pin: zero
  const Eigen::VectorXd x = normal.ldlt().solve(rhs);
  return {d_max, d_nodes, c_nodes, std::vector<double>(x.data(), x.data() + n)};
}

}  // namespace rice::shading
