#pragma once
/// Von Mises (J2) plasticity with linear isotropic hardening, small strain:
///   f(σ, κ) = q(σ) − (σ_y + H κ) ≤ 0,   q = sqrt(3/2 s:s),  s = σ − tr(σ)/3 I,
/// associated flow Δεp = Δγ (3/2) s/q, κ = equivalent plastic strain (Δκ = Δγ).
/// Radial return: Δγ = f(σ_trial, κ_n) / (3G + H), σ = σ_trial − 3G Δγ s_trial/q_trial
/// (exact for linear hardening), with the consistent tangent of the discrete map
/// (Simo & Taylor 1985; Simo & Hughes 1998, Box 3.2; de Souza Neto et al. 2008, §7.3-7.4).

#include "fem/core/parameter_binding.hpp"
#include "materials/elasto_plastic.hpp"

namespace bipot {

class VonMises : public ElastoPlastic {
public:
  enum Branch { Elastic = 0, Radial = 1 };

  struct Parameters {
    double youngs_modulus = 0;    ///< E (kPa)
    double poissons_ratio = 0;    ///< ν
    double yield_stress = 0;      ///< σ_y (kPa)
    double hardening_modulus = 0; ///< H (kPa)
    double unit_weight = 0;       ///< γ (kN/m³)
  };
  static ParamSchemaOf<Parameters> schema();
  /// Validates `p` through schema(): throws InputError with the input file's messages.
  explicit VonMises(const Parameters& p) : VonMises(schema().checked(p)) {}
  explicit VonMises(Checked<Parameters> p);

  std::string name() const override { return "von_mises"; }
  Return return_stress(const Mat3& trial, double kappa) const override;
  double yield_function(const Mat3& stress, double kappa) const override;

private:
  double yield_stress_;
  double hardening_modulus_;
};

} // namespace bipot
