// The strain-rate damping of the Neo-Hookean tets (xpbd/strain_rate_damping.hpp) as a term of
// the reference solver's step energy:
//
//   Ψ^E(x) = Σ_e (τ_e V_e / h) φ(F_e(x) − F_e(xⁿ)),   φ = ½ ε:𝒞:ε,  ε = sym(Fⁿᵀ ΔF),
//
// quadratic and convex in x, so its Hessian needs no projection. Call set_start(xⁿ) at the
// start of every step. Tets with τ = 0 are left out.
#pragma once

#include <vector>

#include "fem_reference/constraint_kernels.hpp"
#include "fem_reference/element_form.hpp"
#include "xpbd/strain_rate_damping.hpp"

namespace rice::fem {

class StrainRateDampingForm final : public ElementForm<4> {
 public:
  /// Keeps a reference to `tets`; h is the step.
  StrainRateDampingForm(const std::vector<xpbd::NeoHookeanTet>& tets, double h) : tets_(tets), h_(h) {
    for (size_t e = 0; e < tets.size(); ++e)
      if (tets[e].strain_rate_damping > 0.0) index_.push_back(static_cast<int>(e));
    F_start_.assign(index_.size(), Mat3::Identity());
  }

  void set_start(const Positions& x) {
    for (int e = 0; e < element_count(); ++e) F_start_[e] = deformation(e, gather(x, e));
  }

  std::string name() const override { return "strain-rate damping"; }
  int element_count() const override { return static_cast<int>(index_.size()); }
  Particles element_particles(int e) const override { return tet(e).particles; }

  double element_value(int e, const LocalVector& x) const override {
    const xpbd::NeoHookeanTet& t = tet(e);
    return scale(e) * xpbd::strain_rate_damping_value(F_start_[e], deformation(e, x) - F_start_[e], t.mu,
                                                      t.lambda_lame());
  }

  LocalVector element_gradient(int e, const LocalVector& x) const override {
    const xpbd::NeoHookeanTet& t = tet(e);
    const Mat3 P = xpbd::strain_rate_damping_dF(F_start_[e], deformation(e, x) - F_start_[e], t.mu, t.lambda_lame());
    return scale(e) * xpbd::gradient_from_dF(P, t.Dm_inv);
  }

  LocalMatrix element_hessian(int e, const LocalVector&, bool) const override {
    const xpbd::NeoHookeanTet& t = tet(e);
    return scale(e) * xpbd::hessian_from_d2F(xpbd::strain_rate_damping_d2F(F_start_[e], t.mu, t.lambda_lame()),
                                             t.Dm_inv);
  }

 private:
  const xpbd::NeoHookeanTet& tet(int e) const { return tets_[index_[e]]; }
  double scale(int e) const { return tet(e).strain_rate_damping * tet(e).rest_volume / h_; }  // τV/h
  Mat3 deformation(int e, const LocalVector& x) const { return xpbd::deformation_gradient(x, tet(e).Dm_inv); }

  const std::vector<xpbd::NeoHookeanTet>& tets_;
  double h_;
  std::vector<int> index_;
  std::vector<Mat3> F_start_;
};

}  // namespace rice::fem
