#pragma once
/// Tresca plasticity with linear isotropic hardening of the shear strength (undrained clay,
/// metals). Ordered principal stresses σ1 ≥ σ2 ≥ σ3:
///   f = (σ1 − σ3) − 2 (c + H κ) ≤ 0,   associated flow,
/// i.e. Mohr–Coulomb with φ = ψ = 0, and it shares that principal-space return
/// (MultiSurfacePlastic): plane, left edge (σ1 = σ2) and right edge (σ2 = σ3). The hardening
/// variable grows by Δκ = 2 Σ Δλ_i over the active planes, so that the plastic work is
/// σ:Δεp = (c + H κ) Δκ, and κ equals the plastic shear strain γp = ε1p − ε3p on a plane
/// return: in simple shear τ = c + H γp.
/// Reference: de Souza Neto, Perić & Owen (2008), §8.1.

#include "fem/core/parameter_binding.hpp"
#include "materials/multi_surface_plastic.hpp"

namespace bipot {

class Tresca : public MultiSurfacePlastic {
public:
  enum Branch { Elastic = 0, Plane, EdgeLeft, EdgeRight };

  struct Parameters {
    double youngs_modulus = 0;    ///< E (kPa)
    double poissons_ratio = 0;    ///< ν
    double cohesion = 0;          ///< shear strength c (kPa)
    double hardening_modulus = 0; ///< H (kPa)
    double unit_weight = 0;       ///< γ (kN/m³)
  };
  static ParamSchemaOf<Parameters> schema();
  /// Validates `p` through schema(): throws InputError with the input file's messages.
  explicit Tresca(const Parameters& p) : Tresca(schema().checked(p)) {}
  explicit Tresca(Checked<Parameters> p);

  std::string name() const override { return "tresca"; }
};

} // namespace bipot
