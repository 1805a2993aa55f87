#pragma once
/// Unilateral contact with Coulomb friction, no adhesion.

#include "contact/laws/interface_law.hpp"
#include "fem/core/parameter_binding.hpp"

namespace bipot::contact {

/// Coulomb–Signorini law: RCCM with β ≡ 0 (docs/formulation.md §3). With jump g = (g_n, g_t) and
/// traction t = r (body 1 on body 2, compression positive):
/// - Signorini: g_n ≥ 0, p = r_n ≥ 0, p g_n = 0;
/// - Coulomb: ‖r_t‖ ≤ μ p; Δg_t = 0 if ‖r_t‖ < μ p, else r_t = −μ p Δg_t/‖Δg_t‖.
/// μ = 0 is frictionless Signorini contact. Solved through the same bipotential projection
/// (De Saxcé & Feng 1998) as RCCM, of which it is the β0 = 0 case.
class CoulombSignorini : public InterfaceLaw {
public:
  struct Parameters {
    double friction_coefficient = 0; ///< μ (≥ 0; 0 = frictionless)
  };
  static ParamSchemaOf<Parameters> schema();

  CoulombSignorini() : CoulombSignorini(Parameters{}) {}
  /// Validates `p` through schema(): throws InputError unless friction_coefficient ≥ 0.
  explicit CoulombSignorini(const Parameters& p) : CoulombSignorini(schema().checked(p)) {}
  explicit CoulombSignorini(Checked<Parameters> p) : mu_(p->friction_coefficient) {}

  std::string name() const override { return "coulomb_signorini"; }
  /// μ, whatever β (β ≡ 0 for this law).
  double friction_coefficient(double) const override { return mu_; }

private:
  double mu_;
};

} // namespace bipot::contact
