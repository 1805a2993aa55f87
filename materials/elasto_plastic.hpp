#pragma once
/// Common frame of the small-strain elasto-plastic materials (von_mises, tresca,
/// mohr_coulomb, drucker_prager): isotropic Hooke elasticity, additive split ε = εe + εp,
/// and an implicit (backward Euler) return of the total trial stress
///   σ_trial = σ0 + D (ε − εp_old)
/// onto the yield surface, done by the derived class in 3×3 tensor form. The yield surface
/// sees the total stress σ0 + σ, so geostatic stresses count; update() returns σ without σ0.
///
/// Internal variables (num_state_variables() = 9, the same in 2D and 3D):
///   [0, 6) plastic strain εp, Voigt order with engineering shears (2D uses the first 4);
///   6      equivalent plastic strain ε̄p = Σ sqrt(2/3 Δεp:Δεp) (tensor shears);
///   7      hardening variable κ (its meaning is the derived class's, see there);
///   8      1 if the last update was plastic, else 0.

#include "fem/core/material.hpp"
#include "materials/stress_tensor.hpp"

namespace bipot {

class ElastoPlastic : public Material {
public:
  static constexpr int plastic_strain_slot = 0;
  static constexpr int equivalent_plastic_strain_slot = 6;
  static constexpr int hardening_slot = 7;
  static constexpr int plastic_flag_slot = 8;
  static constexpr int state_size = 9;

  /// Result of a return mapping. `branch` 0 means elastic (the trial stress is admissible);
  /// the other codes are the derived class's (its Branch enum).
  struct Return {
    int branch = 0;
    Mat3 stress; ///< total stress after the return (kPa)
    double hardening_increment = 0.0;
    StressJacobian jacobian; ///< dσ/dσ_trial, consistent with the discrete return
  };

  int num_state_variables() const override { return state_size; }
  /// `old_state` may be null (virgin material: no plastic strain); `new_state` may be null.
  void update(const Voigt& strain, const Voigt& initial_stress, const double* old_state,
              Voigt& stress, VoigtMatrix& tangent, double* new_state) const override;

  /// equivalent_plastic_strain and plastic (1 where the last converged increment yielded).
  int num_output_fields() const override { return 2; }
  std::string output_field_name(int i) const override;
  void output(const double* state, double* values) const override;

  /// Returns the total trial stress `trial` (kPa) for hardening variable `kappa`; fills
  /// `out.stress` and `out.jacobian` only if the trial is not admissible (branch != 0).
  virtual Return return_stress(const Mat3& trial, double kappa) const = 0;

  /// Yield function at total stress `stress` and hardening variable `kappa`: ≤ 0 admissible,
  /// in kPa (the most critical of the material's surfaces).
  virtual double yield_function(const Mat3& stress, double kappa) const = 0;
  std::optional<double> initial_yield_value(const Voigt& stress) const override {
    return yield_function(stress_tensor(stress), 0.0);
  }

  /// The elasticity matrix for Voigt size 4 or 6 (engineering shear strains).
  VoigtMatrix elasticity_matrix(int voigt_size) const;
  double shear_modulus() const { return shear_modulus_; }
  double bulk_modulus() const { return bulk_modulus_; }
  double lame_lambda() const { return bulk_modulus_ - 2.0 * shear_modulus_ / 3.0; }
  double unit_weight() const override { return unit_weight_; }

protected:
  ElastoPlastic(double youngs_modulus, double poissons_ratio, double unit_weight);

private:
  double youngs_modulus_;
  double poissons_ratio_;
  double shear_modulus_;
  double bulk_modulus_;
  double unit_weight_;
};

} // namespace bipot
