// Light through a rice grain: the translucent rice model, the paper's CDRF plus a term for
// the light a thin grain lets through to its shaded side (issue 24 §2). The exitance at a
// point of mean curvature κ and thickness d (thickness.hpp), lit at angle θ, over the
// irradiance E of a surface facing the light:
//
//   M / E = A f_r(θ, σ0 max(κ, 0)) + τ(d, cos θ),                                    (T1)
//
// A f_r the paper's CDRF (cdrf.hpp, eqs. 6–8) and τ a table over (d, cos θ), read
// bilinearly, fitted by least squares to what the CDRF leaves out of the random-walk
// reference on real grain meshes (fit_translucency; `rice study translucency`). A table, not
// a closed form such as a diffusion slab's T(d): light reaches a point of a grain through
// its whole curved body, not a slab, and the table is what the reference says it is.
#pragma once

#include <vector>

namespace rice::shading {

class TranslucencyTable {
 public:
  /// `d_nodes` ≥ 2 nodes over d ∈ [0, d_max] [m], `c_nodes` ≥ 2 over cos θ ∈ [−1, 1];
  /// `values` d-major: node (i, j) at d_i = d_max i/(d_nodes − 1), cos θ_j = −1 + 2j/(c_nodes − 1),
  /// index i c_nodes + j. Throws std::invalid_argument for counts, sizes or d_max ≤ 0.
  TranslucencyTable(double d_max, int d_nodes, int c_nodes, std::vector<double> values);

  /// τ(d, cos θ), bilinear; d clamped to [0, d_max], cos θ to [−1, 1].
  double operator()(double thickness, double cos_theta) const;

  /// The four nodes τ(d, cos θ) reads and their weights (summing to 1).
  struct Stencil {
    int node[4];
    double weight[4];
  };
  Stencil stencil(double thickness, double cos_theta) const;

  /// (1 − t) a + t b node by node; a and b must share their grid.
  static TranslucencyTable blend(const TranslucencyTable& a, const TranslucencyTable& b, double t);

  double d_max() const { return d_max_; }
  int d_nodes() const { return nd_; }
  int c_nodes() const { return nc_; }
  const std::vector<double>& values() const { return values_; }

 private:
  double d_max_;
  int nd_, nc_;
  std::vector<double> values_;
};

/// One point of the reference: what the CDRF leaves out there, M/E − A f_r, with a weight
/// (a vertex's area).
struct TranslucencySample {
  double cos_theta = 0.0, thickness = 0.0, residual = 0.0, weight = 1.0;
};

/// The table on the given grid minimising Σ w (τ(d, cos θ) − residual)² / Σ w
/// + λ Σ (second differences of τ along d and along cos θ)², λ = `smoothing`: the penalty
/// fills nodes no sample reads and keeps τ from following the reference's noise.
/// Throws std::invalid_argument for no samples or a grid as the constructor does.
TranslucencyTable fit_translucency(const std::vector<TranslucencySample>& samples, double d_max, int d_nodes,
                                   int c_nodes, double smoothing);

}  // namespace rice::shading
