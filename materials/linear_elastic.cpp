#include "materials/linear_elastic.hpp"

#include "fem/core/error.hpp"

namespace bipot {

void add_hooke_keys(ParamSchema& s) {
  s.real("youngs_modulus", "kPa", "Young's modulus E").positive();
  s.real("poissons_ratio", "", "Poisson's ratio nu").greater_than(-1.0).less_than(0.5);
}

void add_unit_weight_key(ParamSchema& s) {
  s.real("unit_weight", "kN/m^3", "weight per unit volume, used by gravity loads")
      .non_negative()
      .with_default(0.0);
}

ParamSchema LinearElastic::schema() {
  ParamSchema s("linear_elastic", "isotropic linear elasticity (Hooke's law)");
  add_hooke_keys(s);
  add_unit_weight_key(s);
  return s;
}

LinearElastic::LinearElastic(const ParameterSet& params)
    : LinearElastic(params.real("youngs_modulus"), params.real("poissons_ratio"),
                    params.real("unit_weight")) {}

LinearElastic::LinearElastic(double youngs_modulus, double poissons_ratio, double unit_weight)
    : youngs_modulus_(youngs_modulus), poissons_ratio_(poissons_ratio), unit_weight_(unit_weight) {
  if (!(youngs_modulus > 0) || !(poissons_ratio > -1 && poissons_ratio < 0.5))
    throw InputError("linear_elastic: need youngs_modulus > 0 and -1 < poissons_ratio < 0.5");
}

VoigtMatrix isotropic_elasticity(double E, double nu, int n) {
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double G = E / (2 * (1 + nu));
  VoigtMatrix D = VoigtMatrix::Zero(n, n);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      D(i, j) = lambda;
    D(i, i) += 2 * G;
  }
  for (int i = 3; i < n; ++i)
    D(i, i) = G; // engineering shear strains
  return D;
}

VoigtMatrix LinearElastic::elasticity_matrix(int n) const {
  return isotropic_elasticity(youngs_modulus_, poissons_ratio_, n);
}

void LinearElastic::update(const Voigt& strain, const Voigt&, const double*, Voigt& stress,
                           VoigtMatrix& tangent, double*) const {
  tangent = elasticity_matrix(static_cast<int>(strain.size()));
  stress = tangent * strain;
}

} // namespace bipot
