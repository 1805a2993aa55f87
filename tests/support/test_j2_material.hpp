#pragma once
/// A small von Mises (J2) material with linear isotropic hardening, for the analysis tests
/// only: it gives the FE tests of per-point state, cut-backs and Newton convergence a
/// material with internal variables that does not depend on materials/ (the registered
/// plastic materials are written and unit-tested there). Radial return and its consistent
/// tangent (Simo & Hughes 1998, box 3.2; de Souza Neto et al. 2008, eq. 7.120).
///
/// State per point: plastic strain (Voigt, engineering shears, nv values), then the
/// equivalent plastic strain ē. Yield: q − (σ_y + H ē) ≤ 0 with q = √(3/2 s:s).

#include "materials/material.hpp"

#include <cmath>

namespace bipot::test {

class TestJ2Material : public Material {
public:
  TestJ2Material(double E, double nu, double yield_stress, double hardening = 0.0)
      : G_(E / (2 * (1 + nu))), K_(E / (3 * (1 - 2 * nu))), sy_(yield_stress), H_(hardening) {}

  std::string name() const override { return "test_j2"; }
  int num_state_variables() const override { return 7; } // room for 6 Voigt + ē

  void update(const Voigt& strain, const Voigt&, const double* old_state, Voigt& stress,
              VoigtMatrix& tangent,
              double* new_state) const override {
    const int n = static_cast<int>(strain.size());
    const double zero[7] = {0, 0, 0, 0, 0, 0, 0};
    const double* old = old_state ? old_state : zero;
    // Elastic trial in tensor components: normal strains, tensor shears (γ/2).
    Voigt ee = Voigt::Zero(n);
    for (int i = 0; i < n; ++i)
      ee(i) = (strain(i) - old[i]) * (i < 3 ? 1.0 : 0.5);
    const double vol = (strain(0) - old[0]) + (strain(1) - old[1]) + (strain(2) - old[2]);
    Voigt s = Voigt::Zero(n); // deviatoric trial stress
    for (int i = 0; i < n; ++i)
      s(i) = 2 * G_ * (i < 3 ? ee(i) - vol / 3 : ee(i));
    double ss = 0;
    for (int i = 0; i < n; ++i)
      ss += (i < 3 ? 1.0 : 2.0) * s(i) * s(i);
    const double q = std::sqrt(1.5 * ss);
    const double f = q - (sy_ + H_ * old[6]);
    double dgamma = 0;
    if (f > 0) dgamma = f / (3 * G_ + H_);
    const double scale = q > 0 ? 1.0 - 3 * G_ * dgamma / q : 1.0;
    stress.resize(n);
    for (int i = 0; i < n; ++i)
      stress(i) = scale * s(i) + (i < 3 ? K_ * vol : 0.0);
    if (new_state) {
      for (int i = 0; i < 7; ++i)
        new_state[i] = old[i];
      for (int i = 0; i < n && dgamma > 0; ++i) // Δεp = Δγ (3/2) s / q, engineering shears
        new_state[i] += dgamma * 1.5 * s(i) / q * (i < 3 ? 1.0 : 2.0);
      new_state[6] = old[6] + dgamma;
    }
    tangent = VoigtMatrix::Zero(n, n);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        tangent(i, j) = K_ - 2 * G_ * scale / 3;
    for (int i = 0; i < n; ++i)
      tangent(i, i) += i < 3 ? 2 * G_ * scale : G_ * scale;
    if (dgamma > 0) {
      const double norm = std::sqrt(ss);
      const double c = 6 * G_ * G_ * (dgamma / q - 1 / (3 * G_ + H_));
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          tangent(i, j) += c * s(i) * s(j) / (norm * norm);
    }
  }

private:
  double G_, K_, sy_, H_;
};

} // namespace bipot::test
