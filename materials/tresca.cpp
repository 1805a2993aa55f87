#include "materials/tresca.hpp"

#include "materials/linear_elastic.hpp"

#include <limits>

namespace bipot {

ParamSchemaOf<Tresca::Parameters> Tresca::schema() {
  using P = Parameters;
  ParamSchemaOf<P> s("tresca", "Tresca plasticity with linear isotropic hardening of the shear "
                               "strength");
  add_hooke_keys(s);
  s.real("cohesion", &P::cohesion, "kPa",
         "shear strength c (undrained: s_u): sigma_1 - sigma_3 <= 2 c")
      .positive();
  s.real("hardening_modulus", &P::hardening_modulus, "kPa",
         "linear hardening H of the shear strength c + H * gamma_p (plastic shear strain)")
      .non_negative()
      .defaulted();
  add_unit_weight_key(s);
  return s;
}

Tresca::Tresca(Checked<Parameters> p)
    : MultiSurfacePlastic(p->youngs_modulus, p->poissons_ratio, p->unit_weight) {
  const double cohesion = p->cohesion, hardening_modulus = p->hardening_modulus;
  std::vector<PrincipalSurface> surfaces;
  for (auto [a, b] : {std::pair{0, 2}, std::pair{1, 2}, std::pair{0, 1}}) {
    const Vec3 n = Vec3::Unit(a) - Vec3::Unit(b);
    surfaces.push_back({n, n, 2 * cohesion, 2 * hardening_modulus, 2.0});
  }
  // No apex: the prism is open along the hydrostatic axis.
  set_surfaces(std::move(surfaces), {{{0}, Plane}, {{0, 1}, EdgeLeft}, {{0, 2}, EdgeRight}},
               std::numeric_limits<double>::infinity(), -1);
}

} // namespace bipot
