#include "fem/core/three_point_rule.hpp"

#include <cmath>
#include <initializer_list>

namespace bipot {

ThreePointRule ThreePointRule::quadratic(double h1, double h2) {
  // Nodes scaled to x0 = −h1/h2, x1 = 0, x2 = 1; Lagrange basis L_i and its derivative; the
  // integrand is a cubic in x, so two Gauss points on [0, 1] integrate it exactly. The weights
  // are dimensionless: the 1/h2 of the derivative cancels the h2 of the measure.
  const double x0 = -h1 / h2;
  const auto basis = [x0](double x, double L[3], double dL[3]) {
    L[0] = x * (x - 1) / (x0 * (x0 - 1));
    L[1] = (x - x0) * (x - 1) / x0;
    L[2] = (x - x0) * x / (1 - x0);
    dL[0] = (2 * x - 1) / (x0 * (x0 - 1));
    dL[1] = (2 * x - x0 - 1) / x0;
    dL[2] = (2 * x - x0) / (1 - x0);
  };
  ThreePointRule rule;
  rule.three_point = true;
  for (auto& row : rule.c)
    for (double& v : row)
      v = 0;
  const double offset = 0.5 / std::sqrt(3.0);
  for (const double x : {0.5 - offset, 0.5 + offset}) {
    double L[3], dL[3];
    basis(x, L, dL);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        rule.c[i][j] += 0.5 * L[i] * dL[j];
  }
  return rule;
}

double ThreePointRule::apply(const double f[3], const double u[3]) const {
  double sum = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      sum += c[i][j] * f[i] * u[j];
  return sum;
}

double ThreePointRule::correction(const double f[3], const double u[3]) const {
  return apply(f, u) - 0.5 * (f[1] + f[2]) * (u[2] - u[1]);
}

} // namespace bipot
