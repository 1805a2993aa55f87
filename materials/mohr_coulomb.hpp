#pragma once
/// Mohr–Coulomb plasticity, perfectly plastic, non-associated, with an optional tension
/// cut-off. Tension positive, ordered principal stresses σ1 ≥ σ2 ≥ σ3:
///   f  = (σ1 − σ3) + (σ1 + σ3) sin φ − 2 c cos φ ≤ 0       (yield, the main plane)
///   g  = (σ1 − σ3) + (σ1 + σ3) sin ψ                      (plastic potential, ψ ≤ φ)
///   ft = σ1 − σt ≤ 0                                      (cut-off, associated, if given)
/// and the same planes with (σ2, σ3) and (σ1, σ2) for the edges. The implicit return in
/// principal stress space (MultiSurfacePlastic) picks, in this order: the main plane, the
/// cut-off plane, the left edge (σ1 = σ2, the triaxial-compression meridian), the right edge
/// (σ2 = σ3, triaxial extension), the main plane with the cut-off, the cut-off edge
/// (σ1 = σ2 = σt), the apex (σ = c cot φ I), and the cut-off corners; the consistent
/// tangent includes the rotation of the principal directions. With ψ = 0 the apex is a
/// vertex no flow reaches: a trial beyond it returns to the apex itself.
/// References: de Souza Neto, Perić & Owen (2008), Computational Methods for Plasticity,
/// §8.2 (Boxes 8.4–8.5); Clausen, Damkilde & Andersen (2006), IJNME 66, 1036–1059.

#include "fem/core/parameter_schema.hpp"
#include "materials/multi_surface_plastic.hpp"

#include <optional>

namespace bipot {

/// Adds cohesion (kPa, ≥ 0), friction_angle and dilatancy_angle (degrees, [0, 90)) with the
/// rules ψ ≤ φ and c > 0 when φ = 0; shared with drucker_prager. `model` names the material
/// in messages.
void add_friction_keys(ParamSchema& schema, const std::string& model);

class MohrCoulomb : public MultiSurfacePlastic {
public:
  enum Branch {
    Elastic = 0,
    Plane,            ///< main plane
    Tension,          ///< σ1 = σt
    EdgeLeft,         ///< σ1 = σ2 on the yield surface (compression meridian)
    EdgeRight,        ///< σ2 = σ3 on the yield surface (extension meridian)
    PlaneTension,     ///< main plane and σ1 = σt
    TensionEdge,      ///< σ1 = σ2 = σt
    Apex,             ///< σ1 = σ2 = σ3 = c cot φ
    PlaneTensionEdge, ///< σ1 = σ2 = σt on the yield surface
    EdgeRightTension, ///< σ2 = σ3 on the yield surface, σ1 = σt
    TensionApex       ///< σ1 = σ2 = σ3 = σt
  };

  /// Keys: youngs_modulus, poissons_ratio, cohesion (kPa), friction_angle,
  /// dilatancy_angle (degrees), tension_cutoff (kPa, optional), unit_weight.
  static ParamSchema schema();
  explicit MohrCoulomb(const ParameterSet& params);
  /// Angles in degrees; `tension_cutoff` empty = none.
  MohrCoulomb(double youngs_modulus, double poissons_ratio, double cohesion, double friction_angle,
              double dilatancy_angle, std::optional<double> tension_cutoff = std::nullopt,
              double unit_weight = 0.0);

  std::string name() const override { return "mohr_coulomb"; }
};

} // namespace bipot
