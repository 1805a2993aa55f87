#include "materials/elasto_plastic.hpp"

#include "materials/linear_elastic.hpp"

#include <Eigen/Cholesky>

#include <cmath>

namespace bipot {

ElastoPlastic::ElastoPlastic(double youngs_modulus, double poissons_ratio, double unit_weight)
    : youngs_modulus_(youngs_modulus), poissons_ratio_(poissons_ratio),
      shear_modulus_(youngs_modulus / (2 * (1 + poissons_ratio))),
      bulk_modulus_(youngs_modulus / (3 * (1 - 2 * poissons_ratio))), unit_weight_(unit_weight) {}

VoigtMatrix ElastoPlastic::elasticity_matrix(int n) const {
  return isotropic_elasticity(youngs_modulus_, poissons_ratio_, n);
}

void ElastoPlastic::update(const Voigt& strain, const Voigt& initial_stress,
                           const double* old_state, Voigt& stress, VoigtMatrix& tangent,
                           double* new_state) const {
  const int n = static_cast<int>(strain.size());
  double state[state_size] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  if (old_state) std::copy(old_state, old_state + state_size, state);
  const Voigt plastic_strain = Eigen::Map<const Eigen::VectorXd>(state + plastic_strain_slot, n);
  const VoigtMatrix D = elasticity_matrix(n);
  const Voigt trial = initial_stress + D * (strain - plastic_strain);
  const Return r = return_stress(stress_tensor(trial), state[hardening_slot]);
  if (r.branch == 0) {
    stress = trial - initial_stress;
    tangent = D;
    state[plastic_flag_slot] = 0.0;
  } else {
    const Voigt total = stress_voigt(r.stress, n);
    stress = total - initial_stress;
    tangent = r.jacobian.topLeftCorner(n, n) * D;
    const Voigt dep = D.llt().solve(trial - total); // Δεp = D⁻¹ (σ_trial − σ)
    double norm2 = 0.0;                             // Δεp:Δεp with tensor shears γ/2
    for (int i = 0; i < n; ++i) {
      state[plastic_strain_slot + i] += dep(i);
      norm2 += i < 3 ? dep(i) * dep(i) : 0.5 * dep(i) * dep(i);
    }
    state[equivalent_plastic_strain_slot] += std::sqrt(2.0 / 3.0 * norm2);
    state[hardening_slot] += r.hardening_increment;
    state[plastic_flag_slot] = 1.0;
  }
  if (new_state) std::copy(state, state + state_size, new_state);
}

std::string ElastoPlastic::output_field_name(int i) const {
  return i == 0 ? "equivalent_plastic_strain" : i == 1 ? "plastic" : std::string();
}

void ElastoPlastic::output(const double* state, double* values) const {
  values[0] = state[equivalent_plastic_strain_slot];
  values[1] = state[plastic_flag_slot];
}

} // namespace bipot
