#include "materials/mohr_coulomb.hpp"

#include "materials/linear_elastic.hpp"

#include <cmath>
#include <limits>

namespace bipot {

namespace {
constexpr double degree = M_PI / 180.0;

// The plane through principal components (a, b), a ≥ b: (1 + sin α) σa − (1 − sin α) σb.
Vec3 shear_plane(int a, int b, double sin_angle) {
  Vec3 v = Vec3::Zero();
  v(a) = 1 + sin_angle;
  v(b) = -(1 - sin_angle);
  return v;
}
} // namespace

namespace detail {
std::optional<std::string> dilatancy_problem(double dilatancy_angle, double friction_angle) {
  if (dilatancy_angle <= friction_angle) return std::nullopt;
  return "value " + format_value(dilatancy_angle) + " deg exceeds friction_angle " +
         format_value(friction_angle) +
         " deg: a dilatancy angle above the friction angle would dissipate negative work";
}

std::optional<std::string> no_strength_problem(const std::string& model, double cohesion,
                                               double friction_angle) {
  if (cohesion > 0 || friction_angle > 0) return std::nullopt;
  return "value 0 with friction_angle 0 leaves the " + model +
         " material no strength at all; give cohesion > 0 or friction_angle > 0";
}
} // namespace detail

ParamSchemaOf<MohrCoulomb::Parameters> MohrCoulomb::schema() {
  ParamSchemaOf<Parameters> s("mohr_coulomb",
                              "Mohr-Coulomb plasticity (non-associated, perfectly plastic) with "
                              "an optional tension cut-off");
  add_hooke_keys(s);
  add_friction_keys(s);
  s.real("tension_cutoff", &Parameters::tension_cutoff, "kPa",
         "tensile strength sigma_t: the major principal stress stays <= sigma_t (absent: no "
         "cut-off)")
      .non_negative();
  add_unit_weight_key(s);
  return s;
}

MohrCoulomb::MohrCoulomb(Checked<Parameters> p)
    : MultiSurfacePlastic(p->youngs_modulus, p->poissons_ratio, p->unit_weight) {
  const double friction_angle = p->friction_angle, dilatancy_angle = p->dilatancy_angle;
  const double cohesion = p->cohesion;
  const std::optional<double> tension_cutoff = p->tension_cutoff;
  const double sphi = std::sin(friction_angle * degree), spsi = std::sin(dilatancy_angle * degree);
  const double k = 2 * cohesion * std::cos(friction_angle * degree);
  // Surfaces 0-2: main plane (σ1, σ3), then (σ2, σ3) and (σ1, σ2); 3-5: cut-off on σ1..σ3.
  // No hardening: κ stays 0.
  std::vector<PrincipalSurface> surfaces;
  for (auto [a, b] : {std::pair{0, 2}, std::pair{1, 2}, std::pair{0, 1}})
    surfaces.push_back({shear_plane(a, b, sphi), shear_plane(a, b, spsi), k, 0.0, 0.0});
  std::vector<ActiveSet> sets = {
      {{0}, Plane}, {{0, 1}, EdgeLeft}, {{0, 2}, EdgeRight}, {{0, 1, 2}, Apex}};
  if (tension_cutoff) {
    for (int a = 0; a < 3; ++a)
      surfaces.push_back({Vec3::Unit(a), Vec3::Unit(a), *tension_cutoff, 0.0, 0.0});
    // Smaller sets first; the cut-off edge on the yield surface (four planes through one
    // point) is covered by three 3-plane subsets (ActiveSet).
    sets = {{{0}, Plane},
            {{3}, Tension},
            {{0, 1}, EdgeLeft},
            {{0, 2}, EdgeRight},
            {{0, 3}, PlaneTension},
            {{3, 4}, TensionEdge},
            {{0, 1, 2}, Apex},
            {{0, 3, 4}, PlaneTensionEdge},
            {{0, 1, 3}, PlaneTensionEdge},
            {{0, 1, 4}, PlaneTensionEdge},
            {{0, 2, 3}, EdgeRightTension},
            {{3, 4, 5}, TensionApex}};
  }
  const double apex = sphi > 0 ? cohesion * std::cos(friction_angle * degree) / sphi
                               : std::numeric_limits<double>::infinity();
  const double apex_stress = tension_cutoff ? std::min(apex, *tension_cutoff) : apex;
  set_surfaces(std::move(surfaces), std::move(sets), apex_stress,
               tension_cutoff && *tension_cutoff < apex ? TensionApex : Apex);
}

} // namespace bipot
