#include "fem/element/quadrature.hpp"

#include "fem/core/error.hpp"
#include "test_cells.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace bipot {
namespace {

double factorial(int n) {
  return n <= 1 ? 1.0 : n * factorial(n - 1);
}

// ∫_{-1}^{1} x^k dx.
double line_moment(int k) {
  return k % 2 ? 0.0 : 2.0 / (k + 1);
}

// Exact integral of ξ^i η^j ζ^k over the reference cell of `type` (closed forms: products of
// line moments on [-1,1]^d; i! j! k! / (i + j + k + d)! on the unit simplex).
double exact_moment(CellType type, int i, int j, int k) {
  switch (type) {
  case CellType::Line2:
    return line_moment(i);
  case CellType::Quad4:
    return line_moment(i) * line_moment(j);
  case CellType::Hex8:
    return line_moment(i) * line_moment(j) * line_moment(k);
  case CellType::Tri3:
    return factorial(i) * factorial(j) / factorial(i + j + 2);
  case CellType::Tet4:
    return factorial(i) * factorial(j) * factorial(k) / factorial(i + j + k + 3);
  default:
    return NAN;
  }
}

// ∫ |ξ^i η^j ζ^k| over the reference cell: a positive scale for relative errors.
double abs_moment(CellType type, int i, int j, int k) {
  auto m = [](int n) { return 2.0 / (n + 1); };
  switch (type) {
  case CellType::Line2:
    return m(i);
  case CellType::Quad4:
    return m(i) * m(j);
  case CellType::Hex8:
    return m(i) * m(j) * m(k);
  default:
    return exact_moment(type, i, j, k);
  }
}

// Largest error over all monomials of total degree exactly p; with `relative`, each error is
// divided by ∫ |monomial| (high-degree moments on the simplices are small, ~1/p³).
double max_error_at_degree(CellType type, const QuadratureRule& rule, int p,
                           bool relative = false) {
  const int d = cell_dim(type);
  double worst = 0;
  for (int i = 0; i <= p; ++i)
    for (int j = 0; j <= (d >= 2 ? p - i : 0); ++j) {
      const int k = p - i - j;
      if ((d == 1 && (j != 0 || k != 0)) || (d == 2 && k != 0)) continue;
      double q = 0;
      for (int g = 0; g < rule.size(); ++g) {
        const auto& x = rule.points[g];
        q += rule.weights[g] * std::pow(x[0], i) * std::pow(x[1], j) * std::pow(x[2], k);
      }
      const double err = std::abs(q - exact_moment(type, i, j, k));
      worst = std::max(worst, relative ? err / abs_moment(type, i, j, k) : err);
    }
  return worst;
}

const CellType shapes[] = {CellType::Line2, CellType::Tri3, CellType::Quad4, CellType::Tet4,
                           CellType::Hex8};

TEST(Quadrature, GaussLegendreMatchesClosedForms) {
  const QuadratureRule g2 = gauss_legendre(2), g3 = gauss_legendre(3);
  // Roots of P2 and P3 and their weights in closed form; Newton converges to round-off.
  EXPECT_NEAR(g2.points[1][0], 1 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(g2.points[0][0], -1 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(g2.weights[0], 1.0, 1e-15);
  EXPECT_NEAR(g3.points[2][0], std::sqrt(0.6), 1e-15);
  EXPECT_EQ(g3.points[1][0], 0.0);
  EXPECT_NEAR(g3.weights[0], 5.0 / 9, 1e-15);
  EXPECT_NEAR(g3.weights[1], 8.0 / 9, 1e-15);
  EXPECT_THROW(gauss_legendre(0), Error);
}

TEST(Quadrature, ExactForMonomialsUpToRuleDegree) {
  for (CellType type : shapes)
    for (int degree = 0; degree <= 14; ++degree) {
      const QuadratureRule rule = gauss_rule(type, degree);
      ASSERT_GE(rule.degree, degree) << to_string(type);
      ASSERT_EQ(rule.points.size(), rule.weights.size());
      for (int p = 0; p <= rule.degree; ++p)
        // Positive weights summing to <= 8 times monomials bounded by 1: round-off ~1e-15.
        EXPECT_LT(max_error_at_degree(type, rule, p), 1e-13)
            << to_string(type) << " requested degree " << degree << ", monomial degree " << p;
    }
}

TEST(Quadrature, HighDegreeLineRules) {
  for (int degree : {20, 31, 40}) {
    const QuadratureRule rule = gauss_rule(CellType::Line3, degree);
    for (int p = 0; p <= rule.degree; ++p)
      // x^p with p <= 41 on [-1, 1]: weights sum to 2, round-off ~1e-15.
      EXPECT_LT(max_error_at_degree(CellType::Line2, rule, p), 1e-13) << degree << " " << p;
  }
}

TEST(Quadrature, NotExactOneDegreeHigher) {
  // The stated degree is sharp: some monomial of degree + 1 is integrated with a relative
  // error of about 1e-5 or more (smallest observed: 1.6e-5, triangle degree 9),
  // far above round-off (1e-15); 1e-8 separates the two cases safely.
  for (CellType type : shapes)
    for (int degree = 0; degree <= 10; ++degree) {
      const QuadratureRule rule = gauss_rule(type, degree);
      EXPECT_GT(max_error_at_degree(type, rule, rule.degree + 1, true), 1e-8)
          << to_string(type) << " requested degree " << degree;
    }
}

TEST(Quadrature, SimplexRulesHaveInteriorPointsAndPositiveWeights) {
  for (CellType type : {CellType::Tri3, CellType::Tet4})
    for (int degree = 0; degree <= 8; ++degree) {
      const QuadratureRule rule = gauss_rule(type, degree);
      for (int g = 0; g < rule.size(); ++g) {
        const auto& x = rule.points[g];
        EXPECT_GT(rule.weights[g], 0.0);
        EXPECT_GT(1 - x[0] - x[1] - x[2], 0.0);
        for (double c : x)
          EXPECT_GE(c, 0.0);
      }
    }
}

TEST(Quadrature, StiffnessDegrees) {
  // Full integration: 1 point for linear simplices, 2x2 / 3x3 / 2x2x2 Gauss for quads/hexes.
  EXPECT_EQ(gauss_rule(CellType::Tri3, stiffness_degree(CellType::Tri3)).size(), 1);
  EXPECT_EQ(gauss_rule(CellType::Tri6, stiffness_degree(CellType::Tri6)).size(), 3);
  EXPECT_EQ(gauss_rule(CellType::Quad4, stiffness_degree(CellType::Quad4)).size(), 4);
  EXPECT_EQ(gauss_rule(CellType::Quad8, stiffness_degree(CellType::Quad8)).size(), 9);
  EXPECT_EQ(gauss_rule(CellType::Tet4, stiffness_degree(CellType::Tet4)).size(), 1);
  EXPECT_EQ(gauss_rule(CellType::Hex8, stiffness_degree(CellType::Hex8)).size(), 8);
  for (CellType type : {CellType::Tri3, CellType::Tri6, CellType::Quad4, CellType::Quad8})
    EXPECT_EQ(stiffness_degree(type, Kinematics::Axisymmetric),
              stiffness_degree(type, Kinematics::PlaneStrain) + 1);
}

TEST(Quadrature, RejectsBadRequests) {
  EXPECT_THROW(gauss_rule(CellType::Point1, 1), Error);
  EXPECT_THROW(gauss_rule(CellType::Tri3, -1), Error);
  EXPECT_THROW(gauss_rule(CellType::Hex8, 41), Error);
}

} // namespace
} // namespace bipot
