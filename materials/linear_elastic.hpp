#pragma once
/// Isotropic linear elasticity (Hooke): σ = λ tr(ε) I + 2 G ε, with
/// λ = E ν / ((1+ν)(1−2ν)) and G = E / (2(1+ν)). In 2D (plane strain and axisymmetric) the
/// out-of-plane / hoop component is kept as the third Voigt entry, so the same 4×4 matrix
/// serves both kinematics (plane strain simply has ε_zz = 0).

#include "fem/core/material.hpp"
#include "fem/core/parameter_binding.hpp"

namespace bipot {

/// Hooke's matrix for Voigt size 4 (2D) or 6 (3D), engineering shear strains: λ on the
/// normal block, 2G added on its diagonal, G on the shear diagonal.
VoigtMatrix isotropic_elasticity(double youngs_modulus, double poissons_ratio, int voigt_size);

/// Adds youngs_modulus (kPa, > 0) and poissons_ratio ((-1, 0.5)), bound to P's members of
/// those names: shared by every isotropic material's schema so the keys read the same
/// everywhere.
template <class P> void add_hooke_keys(ParamSchemaOf<P>& s) {
  s.real("youngs_modulus", &P::youngs_modulus, "kPa", "Young's modulus E").positive();
  s.real("poissons_ratio", &P::poissons_ratio, "", "Poisson's ratio nu")
      .greater_than(-1.0)
      .less_than(0.5);
}
/// Adds unit_weight (kN/m³, ≥ 0, default 0), bound to P::unit_weight.
template <class P> void add_unit_weight_key(ParamSchemaOf<P>& s) {
  s.real("unit_weight", &P::unit_weight, "kN/m^3", "weight per unit volume, used by gravity loads")
      .non_negative()
      .defaulted();
}

class LinearElastic : public Material {
public:
  struct Parameters {
    double youngs_modulus = 0; ///< E (kPa)
    double poissons_ratio = 0; ///< ν
    double unit_weight = 0;    ///< γ (kN/m³)
  };
  static ParamSchemaOf<Parameters> schema();

  /// Validates `p` through schema(): throws InputError with the input file's messages.
  explicit LinearElastic(const Parameters& p) : LinearElastic(schema().checked(p)) {}
  explicit LinearElastic(Checked<Parameters> p);

  std::string name() const override { return "linear_elastic"; }
  /// Hooke's law on the strain alone: the initial stress does not change the response.
  void update(const Voigt& strain, const Voigt& initial_stress, const double* old_state,
              Voigt& stress, VoigtMatrix& tangent, double* new_state) const override;
  double unit_weight() const override { return unit_weight_; }
  bool is_linear() const override { return true; }

  /// The elasticity matrix for 2D (4×4) or 3D (6×6) Voigt strains.
  VoigtMatrix elasticity_matrix(int voigt_size) const;

private:
  double youngs_modulus_;
  double poissons_ratio_;
  double unit_weight_;
};

} // namespace bipot
