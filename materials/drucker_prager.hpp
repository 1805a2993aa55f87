#pragma once
/// Drucker–Prager plasticity, perfectly plastic, non-associated. Tension positive,
/// p = tr σ / 3, s = σ − p I, J2 = s:s / 2:
///   f = sqrt(J2) + η p − ξ c ≤ 0,     g = sqrt(J2) + η̄ p,
/// with η, ξ (from φ) and η̄ (from ψ) matching Mohr–Coulomb at its compression meridian
/// (default), its extension meridian, or in plane strain (`match`).
///
/// The non-associated return is written as De Saxcé's bipotential projection, as for the
/// interface's Coulomb cone (contact/laws/coulomb_cone.hpp): the stress is the projection,
/// in the metric of the elasticity C⁻¹, onto the *yield* cone K of a trial shifted along
/// the hydrostatic axis by the plastic distortion,
///   σ = Proj_K^C( σ* + K_b (η − η̄) Δγ I ),   Δγ = √2 ‖dev Δεp‖ = (√J2(σ*) − √J2(σ)) / G,
/// where K_b is the bulk modulus (the analogue of μ‖Δg_t‖ in the interface law). The implicit
/// relation has a closed-form fixed point: on the cone's face Δγ = f(σ*) / (G + K_b η η̄);
/// when that overshoots the axis (√J2(σ*) < G Δγ) the stress is the apex p = ξ c / η.
/// Consistent tangent on the face as in de Souza Neto et al. (2008), §8.3.3; zero at the apex.
/// References: de Saxcé & Bousshine (1998), Int. J. Mech. Sci. 40, 387–398 (bipotential for
/// non-associated soils); de Souza Neto, Perić & Owen (2008), §8.3 (Box 8.9).

#include "fem/core/parameter_binding.hpp"
#include "materials/elasto_plastic.hpp"
#include "materials/mohr_coulomb.hpp"

namespace bipot {

class DruckerPrager : public ElastoPlastic {
public:
  enum Branch { Elastic = 0, Cone, Apex };
  enum class Match { Compression, Extension, PlaneStrain };

  /// Cone constants {η, ξ} of angle `angle_deg` for a match; η̄ is η of ψ.
  static std::pair<double, double> cone_constants(double angle_deg, Match match);

  struct Parameters : FrictionalParameters {
    Match match = Match::Compression; ///< which Mohr–Coulomb condition the cone reproduces
    double unit_weight = 0;           ///< γ (kN/m³)
  };
  static ParamSchemaOf<Parameters> schema();
  /// Validates `p` through schema(): throws InputError with the input file's messages.
  explicit DruckerPrager(const Parameters& p) : DruckerPrager(schema().checked(p)) {}
  explicit DruckerPrager(Checked<Parameters> p);

  std::string name() const override { return "drucker_prager"; }
  Return return_stress(const Mat3& trial, double kappa) const override;
  double yield_function(const Mat3& stress, double kappa) const override;

  /// The projection of `stress` onto the yield cone in the metric of C⁻¹ (associated
  /// return): the map the bipotential return applies to its shifted trial.
  Mat3 project_onto_cone(const Mat3& stress) const;

private:
  double eta_, xi_, eta_bar_, cohesion_;
};

} // namespace bipot
