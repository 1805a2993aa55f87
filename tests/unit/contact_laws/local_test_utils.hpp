#pragma once
/// Small helpers shared by the contact-law tests: local vectors from lists and central
/// finite differences.

#include "contact/laws/coulomb_cone.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <initializer_list>

namespace bipot::contact::test {

inline LocalVector vec(std::initializer_list<double> values) {
  LocalVector v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double x : values)
    v(i++) = x;
  return v;
}

/// Central-difference Jacobian of f at x with step h (columns = components of x).
inline LocalMatrix fd_jacobian(const std::function<LocalVector(const LocalVector&)>& f,
                               const LocalVector& x, double h) {
  const LocalVector f0 = f(x);
  LocalMatrix J(f0.size(), x.size());
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    LocalVector xp = x, xm = x;
    xp(j) += h;
    xm(j) -= h;
    J.col(j) = (f(xp) - f(xm)) / (2.0 * h);
  }
  return J;
}

/// Central-difference derivative of a vector-valued function of one scalar.
inline LocalVector fd_derivative(const std::function<LocalVector(double)>& f, double x, double h) {
  return (f(x + h) - f(x - h)) / (2.0 * h);
}

/// Relative Frobenius error of an analytical Jacobian against a finite-difference one. The
/// floor keeps identically-zero Jacobians (open branch) from dividing by zero: both sides are
/// then exactly zero and the error is 0.
inline double relative_error(const LocalMatrix& exact, const LocalMatrix& fd) {
  const double scale = std::max(fd.norm(), 1e-30);
  return (exact - fd).norm() / scale;
}

} // namespace bipot::contact::test
