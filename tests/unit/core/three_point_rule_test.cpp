// ThreePointRule: the energy ledger's quadrature of ∫ F·du over the last step through three
// states. Checked against polynomial integrals it must reproduce exactly, the exact work of a
// linear spring (the linear bulk) and of a constant force (friction), and its order on a
// softening spring with a closed-form work.
#include "fem/core/three_point_rule.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace bipot {
namespace {

// F and u sampled at s1 − h1, s1, s1 + h2.
double rule_on(const ThreePointRule& rule, const std::function<double(double)>& F,
               const std::function<double(double)>& u, double s1, double h1, double h2) {
  const double f[3] = {F(s1 - h1), F(s1), F(s1 + h2)};
  const double x[3] = {u(s1 - h1), u(s1), u(s1 + h2)};
  return rule.apply(f, x);
}

// Quadratic F and u: F u' is a cubic, which the rule integrates exactly over [s1, s2] for any
// ratio of the steps. Reference: the antiderivative of (a0 + a1 s + a2 s²)(b1 + 2 b2 s).
TEST(ThreePointRule, IntegratesQuadraticPathsExactly) {
  const double a0 = 0.5, a1 = -1.0, a2 = 4.0, b0 = 1.0, b1 = 2.0, b2 = -3.0;
  const auto F = [&](double s) { return a0 + a1 * s + a2 * s * s; };
  const auto u = [&](double s) { return b0 + b1 * s + b2 * s * s; };
  const auto antiderivative = [&](double s) {
    // (a0 + a1 s + a2 s²)(b1 + 2 b2 s) = a0 b1 + (a1 b1 + 2 a0 b2) s + (a2 b1 + 2 a1 b2) s²
    //                                     + 2 a2 b2 s³
    return a0 * b1 * s + (a1 * b1 + 2 * a0 * b2) * s * s / 2 +
           (a2 * b1 + 2 * a1 * b2) * s * s * s / 3 + 2 * a2 * b2 * s * s * s * s / 4;
  };
  for (const double ratio : {0.4, 1.0, 2.5}) {
    const double s1 = 0.3, h2 = 0.2, h1 = h2 / ratio;
    const double exact = antiderivative(s1 + h2) - antiderivative(s1);
    const double got = rule_on(ThreePointRule::quadratic(h1, h2), F, u, s1, h1, h2);
    EXPECT_NEAR(got, exact, 1e-14 * std::abs(exact)) << "h2/h1 = " << ratio;
  }
}

// A linear bulk, F = k u + f0 along any path u(s): ½ k (u2² − u1²) + f0 (u2 − u1), as the
// interpolant of F is k times that of u plus f0; f0 alone is friction at a constant force.
TEST(ThreePointRule, IsExactForALinearSpringAndAConstantForce) {
  const auto u = [](double s) { return std::sin(3 * s) + 0.2 * s; };
  for (const double k : {0.0, 250.0}) {
    const double f0 = -7.0;
    const auto F = [&](double s) { return k * u(s) + f0; };
    const double s1 = 0.4, h1 = 0.15, h2 = 0.3;
    const double exact =
        0.5 * k * (u(s1 + h2) * u(s1 + h2) - u(s1) * u(s1)) + f0 * (u(s1 + h2) - u(s1));
    const double got = rule_on(ThreePointRule::quadratic(h1, h2), F, u, s1, h1, h2);
    EXPECT_NEAR(got, exact, 1e-13 * std::abs(exact)) << "k = " << k;
  }
}

TEST(ThreePointRule, TrapezoidIsTheDefault) {
  const double f[3] = {100.0, 2.0, 4.0}, u[3] = {-50.0, 1.0, 1.5};
  EXPECT_FALSE(ThreePointRule::trapezoid().three_point);
  EXPECT_DOUBLE_EQ(ThreePointRule::trapezoid().apply(f, u), 0.5 * (2.0 + 4.0) * 0.5);
  EXPECT_DOUBLE_EQ(ThreePointRule::trapezoid().correction(f, u), 0.0);
}

// The column's softening branch (tests/support/bonded_column.hpp): the interface stress
// t(g) = w²/(C g³) for g > g* = √(w/C), whose work from g1 to g2 is w²/(2C) (1/g1² − 1/g2²),
// along a path parametrised nonlinearly, g(s) = g_a + s + 2 s². One step's error: O(h⁴) for
// the rule (halving the step divides it by 16; ≥ 12 asked), O(h³) for the trapezoid (8).
TEST(ThreePointRule, OneStepErrorIsFourthOrderOnASofteningSpring) {
  const double C = 1.0e4, w = 1.0, g_a = 0.015; // 1.5 g*
  const auto g = [&](double s) { return g_a + s + 2 * s * s; };
  const auto t = [&](double s) { return w * w / (C * std::pow(g(s), 3)); };
  const auto exact = [&](double s1, double s2) {
    return w * w / (2 * C) * (1 / (g(s1) * g(s1)) - 1 / (g(s2) * g(s2)));
  };
  for (const double ratio : {1.0, 2.0}) {
    double error[2][2]; // [rule, trapezoid][h, h/2]
    for (int level = 0; level < 2; ++level) {
      const double s1 = 0.002, h2 = 0.002 / (1 << level), h1 = h2 / ratio;
      const double W = exact(s1, s1 + h2);
      error[0][level] = rule_on(ThreePointRule::quadratic(h1, h2), t, g, s1, h1, h2) - W;
      error[1][level] = rule_on(ThreePointRule::trapezoid(), t, g, s1, h1, h2) - W;
      EXPECT_LT(std::abs(error[0][level]), 0.5 * std::abs(error[1][level]));
    }
    const double rule_ratio = error[0][0] / error[0][1],
                 trapezoid_ratio = error[1][0] / error[1][1];
    std::printf("h2/h1 = %g: one-step error ratio at h and h/2: rule %.2f (%.3g -> %.3g), "
                "trapezoid %.2f\n",
                ratio, rule_ratio, error[0][0], error[0][1], trapezoid_ratio);
    EXPECT_GE(rule_ratio, 12.0);
    EXPECT_LT(trapezoid_ratio, 12.0); // the old rule fails the check above
  }
}

} // namespace
} // namespace bipot
