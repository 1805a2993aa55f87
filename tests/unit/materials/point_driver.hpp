#pragma once
// Helpers for stress-point tests of materials: central finite differences of the stress
// (to check consistent tangents) and a mixed strain/stress control loop (Newton on the
// stress-controlled strain components with the material's own tangent).

#include "materials/material.hpp"

#include <Eigen/LU>

#include <vector>

namespace bipot::test {

/// Stress (excluding σ0) at `strain` from `state` (new state discarded).
inline Voigt stress_at(const Material& m, const Voigt& strain, const Voigt& sigma0,
                       const double* state) {
  Voigt s;
  VoigtMatrix D;
  std::vector<double> scratch(m.num_state_variables() + 1);
  m.update(strain, sigma0, state, s, D, scratch.data());
  return s;
}

/// dσ/dε by central differences with step h (engineering shear strains).
inline VoigtMatrix fd_tangent(const Material& m, const Voigt& strain, const Voigt& sigma0,
                              const double* state, double h) {
  const int n = static_cast<int>(strain.size());
  VoigtMatrix D(n, n);
  for (int j = 0; j < n; ++j) {
    Voigt ep = strain, em = strain;
    ep(j) += h;
    em(j) -= h;
    D.col(j) = (stress_at(m, ep, sigma0, state) - stress_at(m, em, sigma0, state)) / (2 * h);
  }
  return D;
}

/// Max-norm relative difference ‖A − B‖∞ / ‖B‖∞.
inline double relative_difference(const VoigtMatrix& A, const VoigtMatrix& B) {
  return (A - B).cwiseAbs().maxCoeff() / B.cwiseAbs().maxCoeff();
}

/// Finds the strain whose components with `controlled[i] == false` equal `strain(i)` and
/// whose other components give total stress σ0 + σ = `target(i)`, from the committed
/// `state`; returns the stress (excluding σ0) and writes the new state. Newton with the
/// consistent tangent; `strain` holds the initial guess on entry and the result on exit.
inline Voigt mixed_control(const Material& m, Voigt& strain, const std::vector<bool>& controlled,
                           const Voigt& target, const Voigt& sigma0, const double* state,
                           double* new_state, int max_iterations = 50) {
  const int n = static_cast<int>(strain.size());
  std::vector<int> free;
  for (int i = 0; i < n; ++i)
    if (controlled[i]) free.push_back(i);
  const int k = static_cast<int>(free.size());
  Voigt s;
  VoigtMatrix D;
  for (int it = 0; it < max_iterations; ++it) {
    m.update(strain, sigma0, state, s, D, new_state);
    Eigen::VectorXd r(k);
    Eigen::MatrixXd J(k, k);
    for (int a = 0; a < k; ++a) {
      r(a) = sigma0(free[a]) + s(free[a]) - target(free[a]);
      for (int b = 0; b < k; ++b)
        J(a, b) = D(free[a], free[b]);
    }
    if (k == 0 || r.cwiseAbs().maxCoeff() <= 1e-13 * (1.0 + s.cwiseAbs().maxCoeff())) break;
    const Eigen::VectorXd d = J.fullPivLu().solve(r);
    for (int a = 0; a < k; ++a)
      strain(free[a]) -= d(a);
  }
  m.update(strain, sigma0, state, s, D, new_state);
  return s;
}

} // namespace bipot::test
