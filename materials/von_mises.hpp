#pragma once
/// Von Mises (J2) plasticity with linear isotropic hardening, small strain:
///   f(σ, κ) = q(σ) − (σ_y + H κ) ≤ 0,   q = sqrt(3/2 s:s),  s = σ − tr(σ)/3 I,
/// associated flow Δεp = Δγ (3/2) s/q, κ = equivalent plastic strain (Δκ = Δγ).
/// Radial return: Δγ = f(σ_trial, κ_n) / (3G + H), σ = σ_trial − 3G Δγ s_trial/q_trial
/// (exact for linear hardening), with the consistent tangent of the discrete map
/// (Simo & Taylor 1985; Simo & Hughes 1998, Box 3.2; de Souza Neto et al. 2008, §7.3-7.4).

#include "fem/core/parameter_schema.hpp"
#include "materials/elasto_plastic.hpp"

namespace bipot {

class VonMises : public ElastoPlastic {
public:
  enum Branch { Elastic = 0, Radial = 1 };

  /// Keys: youngs_modulus (kPa), poissons_ratio, yield_stress σ_y (kPa, > 0),
  /// hardening_modulus H (kPa, ≥ 0, default 0), unit_weight (kN/m³, default 0).
  static ParamSchema schema();
  explicit VonMises(const ParameterSet& params);
  VonMises(double youngs_modulus, double poissons_ratio, double yield_stress,
           double hardening_modulus = 0.0, double unit_weight = 0.0);

  std::string name() const override { return "von_mises"; }
  Return return_stress(const Mat3& trial, double kappa) const override;
  double yield_function(const Mat3& stress, double kappa) const override;

private:
  double yield_stress_;
  double hardening_modulus_;
};

} // namespace bipot
