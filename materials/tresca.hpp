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

#include "fem/core/parameter_schema.hpp"
#include "materials/multi_surface_plastic.hpp"

namespace bipot {

class Tresca : public MultiSurfacePlastic {
public:
  enum Branch { Elastic = 0, Plane, EdgeLeft, EdgeRight };

  /// Keys: youngs_modulus, poissons_ratio, cohesion (shear strength c, kPa, > 0),
  /// hardening_modulus (H, kPa, ≥ 0, default 0), unit_weight.
  static ParamSchema schema();
  explicit Tresca(const ParameterSet& params);
  Tresca(double youngs_modulus, double poissons_ratio, double cohesion,
         double hardening_modulus = 0.0, double unit_weight = 0.0);

  std::string name() const override { return "tresca"; }
};

} // namespace bipot
