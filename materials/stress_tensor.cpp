#include "materials/stress_tensor.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace bipot {

Mat3 stress_tensor(const Voigt& stress) {
  Mat3 s = Mat3::Zero();
  for (int k = 0; k < stress.size(); ++k) {
    s(voigt_row[k], voigt_col[k]) = stress(k);
    s(voigt_col[k], voigt_row[k]) = stress(k);
  }
  return s;
}

Voigt stress_voigt(const Mat3& stress, int n) {
  Voigt v(n);
  for (int k = 0; k < n; ++k)
    v(k) = stress(voigt_row[k], voigt_col[k]);
  return v;
}

Principal principal(const Mat3& tensor) {
  // The iterative solver, not computeDirect(): the closed-form cubic loses digits for nearly
  // equal eigenvalues, which are common here (triaxial states, the edges of Mohr–Coulomb).
  Eigen::SelfAdjointEigenSolver<Mat3> eig(tensor);
  Principal p;
  for (int a = 0; a < 3; ++a) { // Eigen sorts ascending
    p.values(a) = eig.eigenvalues()(2 - a);
    p.directions.col(a) = eig.eigenvectors().col(2 - a);
  }
  return p;
}

StressJacobian isotropic_jacobian(const Principal& trial, const Vec3& s, const Mat3& J) {
  const Vec3& lam = trial.values;
  const Mat3& Q = trial.directions;
  // Shear factors θ_ab; "equal" eigenvalues are those within round-off of the largest one.
  const double tie = 1e-12 * std::max(1.0, lam.cwiseAbs().maxCoeff());
  Mat3 theta = Mat3::Zero();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      if (a == b) continue;
      const double d = lam(a) - lam(b);
      theta(a, b) = std::abs(d) > tie ? (s(a) - s(b)) / d : J(a, a) - J(a, b);
    }
  return jacobian_from([&](const Mat3& B) {
    const Mat3 dA = Q.transpose() * B * Q; // the perturbation in the principal frame
    Mat3 dS = Mat3::Zero();
    dS.diagonal() = J * dA.diagonal();
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        if (a != b) dS(a, b) = theta(a, b) * dA(a, b);
    return Mat3(Q * dS * Q.transpose());
  });
}

} // namespace bipot
