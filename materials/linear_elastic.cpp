#include "materials/linear_elastic.hpp"

namespace bipot {

ParamSchemaOf<LinearElastic::Parameters> LinearElastic::schema() {
  ParamSchemaOf<Parameters> s("linear_elastic", "isotropic linear elasticity (Hooke's law)");
  add_hooke_keys(s);
  add_unit_weight_key(s);
  return s;
}

LinearElastic::LinearElastic(Checked<Parameters> p)
    : youngs_modulus_(p->youngs_modulus), poissons_ratio_(p->poissons_ratio),
      unit_weight_(p->unit_weight) {}

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
