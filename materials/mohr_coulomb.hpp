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

#include "fem/core/parameter_binding.hpp"
#include "materials/multi_surface_plastic.hpp"

#include <optional>

namespace bipot {

namespace detail {
/// The problems of the rules below, if any (the messages `check` prints).
std::optional<std::string> dilatancy_problem(double dilatancy_angle, double friction_angle);
std::optional<std::string> no_strength_problem(const std::string& model, double cohesion,
                                               double friction_angle);
} // namespace detail

/// The elastic constants and strength shared by mohr_coulomb and drucker_prager: the first
/// members of their Parameters, in the order of their keys. Angles in degrees.
struct FrictionalParameters {
  double youngs_modulus = 0;  ///< E (kPa)
  double poissons_ratio = 0;  ///< ν
  double cohesion = 0;        ///< c (kPa)
  double friction_angle = 0;  ///< φ
  double dilatancy_angle = 0; ///< ψ
};

/// Adds cohesion (kPa, ≥ 0), friction_angle and dilatancy_angle (degrees, [0, 90)), bound to
/// P's members of those names, with the rules ψ ≤ φ and c > 0 when φ = 0; shared with
/// drucker_prager. The schema's name names the material in messages.
template <class P> void add_friction_keys(ParamSchemaOf<P>& s) {
  s.real("cohesion", &P::cohesion, "kPa", "cohesion c").non_negative();
  s.real("friction_angle", &P::friction_angle, "deg", "friction angle phi")
      .at_least(0.0)
      .less_than(90.0)
      .because("a friction angle of 90 degrees or more has no finite strength in compression");
  s.real("dilatancy_angle", &P::dilatancy_angle, "deg",
         "dilatancy angle psi (plastic potential); psi <= phi")
      .at_least(0.0)
      .less_than(90.0);
  s.rule("dilatancy_angle", "dilatancy_angle <= friction_angle",
         [](const P& p) { return detail::dilatancy_problem(p.dilatancy_angle, p.friction_angle); });
  s.rule("cohesion", "cohesion > 0 when friction_angle is 0", [model = s.name()](const P& p) {
    return detail::no_strength_problem(model, p.cohesion, p.friction_angle);
  });
}

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

  struct Parameters : FrictionalParameters {
    std::optional<double> tension_cutoff = std::nullopt; ///< σ_t (kPa); empty = none
    double unit_weight = 0;                              ///< γ (kN/m³)
  };
  static ParamSchemaOf<Parameters> schema();
  /// Validates `p` through schema(): throws InputError with the input file's messages.
  explicit MohrCoulomb(const Parameters& p) : MohrCoulomb(schema().checked(p)) {}
  explicit MohrCoulomb(Checked<Parameters> p);

  std::string name() const override { return "mohr_coulomb"; }
};

} // namespace bipot
