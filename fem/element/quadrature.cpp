#include "fem/element/quadrature.hpp"

#include "fem/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace bipot {
namespace {

constexpr double pi = 3.141592653589793238462643383279502884;

void add(QuadratureRule& rule, double x, double y, double z, double w) {
  rule.points.push_back({x, y, z});
  rule.weights.push_back(w);
}

// Triangle orbit of the barycentric point (a, a, 1 - 2a): three points, weight w each.
void add_tri_orbit(QuadratureRule& rule, double a, double w) {
  const double b = 1 - 2 * a;
  add(rule, a, a, 0, w);
  add(rule, b, a, 0, w);
  add(rule, a, b, 0, w);
}

// Tetrahedron orbit of the barycentric point (a, a, a, 1 - 3a): four points, weight w each.
void add_tet_orbit(QuadratureRule& rule, double a, double w) {
  const double b = 1 - 3 * a;
  add(rule, a, a, a, w);
  add(rule, b, a, a, w);
  add(rule, a, b, a, w);
  add(rule, a, a, b, w);
}

// Gauss–Legendre with enough points for `degree` on [-1, 1].
QuadratureRule line_rule(int degree) {
  return gauss_legendre((degree + 2) / 2);
}

QuadratureRule tensor_rule(int dim, int degree) {
  const QuadratureRule g = line_rule(degree);
  const int n = g.size();
  QuadratureRule rule;
  rule.degree = g.degree;
  const int nz = dim == 3 ? n : 1, ny = dim >= 2 ? n : 1;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < n; ++i) {
        const double y = dim >= 2 ? g.points[j][0] : 0, z = dim == 3 ? g.points[k][0] : 0;
        const double w =
            g.weights[i] * (dim >= 2 ? g.weights[j] : 1) * (dim == 3 ? g.weights[k] : 1);
        add(rule, g.points[i][0], y, z, w);
      }
  return rule;
}

// Gauss–Legendre mapped to [0, 1] with enough points for `degree`.
QuadratureRule unit_line_rule(int degree) {
  QuadratureRule g = line_rule(degree);
  for (int i = 0; i < g.size(); ++i) {
    g.points[i][0] = 0.5 * (1 + g.points[i][0]);
    g.weights[i] *= 0.5;
  }
  return g;
}

// Collapsed (Duffy) product rules. A monomial of total degree p pulled back to the unit
// square / cube has degree p in u, p + 1 in v and p + 2 in w once the Jacobian (1 - v) or
// (1 - v)(1 - w)² is included, hence one and two more degrees in those directions.
QuadratureRule collapsed_triangle(int degree) {
  const QuadratureRule gu = unit_line_rule(degree), gv = unit_line_rule(degree + 1);
  QuadratureRule rule;
  rule.degree = std::min(gu.degree, gv.degree - 1);
  for (int j = 0; j < gv.size(); ++j)
    for (int i = 0; i < gu.size(); ++i) {
      const double u = gu.points[i][0], v = gv.points[j][0];
      add(rule, u * (1 - v), v, 0, gu.weights[i] * gv.weights[j] * (1 - v));
    }
  return rule;
}

QuadratureRule collapsed_tetrahedron(int degree) {
  const QuadratureRule gu = unit_line_rule(degree), gv = unit_line_rule(degree + 1),
                       gw = unit_line_rule(degree + 2);
  QuadratureRule rule;
  rule.degree = std::min({gu.degree, gv.degree - 1, gw.degree - 2});
  for (int k = 0; k < gw.size(); ++k)
    for (int j = 0; j < gv.size(); ++j)
      for (int i = 0; i < gu.size(); ++i) {
        const double u = gu.points[i][0], v = gv.points[j][0], w = gw.points[k][0];
        const double jac = (1 - v) * (1 - w) * (1 - w);
        add(rule, u * (1 - v) * (1 - w), v * (1 - w), w,
            gu.weights[i] * gv.weights[j] * gw.weights[k] * jac);
      }
  return rule;
}

QuadratureRule triangle_rule(int degree) {
  QuadratureRule rule;
  if (degree <= 1) {
    rule.degree = 1;
    add(rule, 1.0 / 3, 1.0 / 3, 0, 0.5);
  } else if (degree == 2) {
    rule.degree = 2;
    add_tri_orbit(rule, 1.0 / 6, 1.0 / 6);
  } else if (degree <= 4) {
    // Dunavant's 6-point degree-4 rule (two orbits), in closed form.
    rule.degree = 4;
    const double s10 = std::sqrt(10.0), r = std::sqrt(38 - 44 * std::sqrt(0.4));
    const double q = std::sqrt(213125 - 53320 * s10);
    add_tri_orbit(rule, (8 - s10 + r) / 18, 0.5 * (620 + q) / 3720);
    add_tri_orbit(rule, (8 - s10 - r) / 18, 0.5 * (620 - q) / 3720);
  } else if (degree == 5) {
    // Radon's 7-point degree-5 rule.
    rule.degree = 5;
    const double s15 = std::sqrt(15.0);
    add(rule, 1.0 / 3, 1.0 / 3, 0, 0.5 * 9.0 / 40);
    add_tri_orbit(rule, (6 - s15) / 21, 0.5 * (155 - s15) / 1200);
    add_tri_orbit(rule, (6 + s15) / 21, 0.5 * (155 + s15) / 1200);
  } else {
    return collapsed_triangle(degree);
  }
  return rule;
}

QuadratureRule tetrahedron_rule(int degree) {
  QuadratureRule rule;
  if (degree <= 1) {
    rule.degree = 1;
    add(rule, 0.25, 0.25, 0.25, 1.0 / 6);
  } else if (degree == 2) {
    rule.degree = 2;
    add_tet_orbit(rule, (5 - std::sqrt(5.0)) / 20, 1.0 / 24);
  } else if (degree == 3) {
    // Two orbits (a, a, a, 1 - 3a) with equal weights 1/48 per point (positive, interior).
    // With t = a - 1/4, exactness for the symmetric polynomials 1, Σλ², Σλ³ reads
    // mean(t²) = 1/80 and mean(t³) = -1/960; s = t1 + t2 solves s (3/80 - s²/2) = -1/480
    // and t1 t2 = (s² - 1/40) / 2. Values below solve these to 40 digits.
    rule.degree = 3;
    add_tet_orbit(rule, 0.32886164993020291040031936782602203, 1.0 / 48);
    add_tet_orbit(rule, 0.11295679451251102869514698889260387, 1.0 / 48);
  } else {
    return collapsed_tetrahedron(degree);
  }
  return rule;
}

} // namespace

QuadratureRule gauss_legendre(int n) {
  if (n < 1 || n > 32)
    throw Error("gauss_legendre: " + std::to_string(n) + " points requested (1..32)");
  QuadratureRule rule;
  rule.degree = 2 * n - 1;
  rule.points.resize(n, {0, 0, 0});
  rule.weights.resize(n);
  // P_n(x) and P_n'(x) by the three-term recurrence.
  auto legendre = [n](double x, double& p, double& dp) {
    double p0 = 1, p1 = x;
    for (int k = 1; k < n; ++k) {
      const double p2 = ((2 * k + 1) * x * p1 - k * p0) / (k + 1);
      p0 = p1;
      p1 = p2;
    }
    p = p1;
    dp = n * (x * p1 - p0) / (x * x - 1);
  };
  for (int i = 0; i < (n + 1) / 2; ++i) {
    // Newton from the classical asymptotic guess of the i-th largest root.
    double x = std::cos(pi * (i + 0.75) / (n + 0.5)), p = 0, dp = 1;
    for (int it = 0; it < 100; ++it) {
      legendre(x, p, dp);
      const double dx = p / dp;
      x -= dx;
      if (std::abs(dx) <= 1e-15) break;
    }
    legendre(x, p, dp);
    const double w = 2 / ((1 - x * x) * dp * dp);
    // Enforce exact symmetry: roots come in ± pairs, the middle one of odd n is 0.
    if (2 * i + 1 == n) x = 0;
    rule.points[i][0] = -x;
    rule.points[n - 1 - i][0] = x;
    rule.weights[i] = rule.weights[n - 1 - i] = w;
  }
  return rule;
}

QuadratureRule gauss_rule(CellType type, int degree) {
  if (degree < 0 || degree > 40)
    throw Error("gauss_rule: degree " + std::to_string(degree) + " out of range (0..40)");
  switch (type) {
  case CellType::Line2:
  case CellType::Line3:
    return line_rule(degree);
  case CellType::Quad4:
  case CellType::Quad8:
    return tensor_rule(2, degree);
  case CellType::Hex8:
    return tensor_rule(3, degree);
  case CellType::Tri3:
  case CellType::Tri6:
    return triangle_rule(degree);
  case CellType::Tet4:
    return tetrahedron_rule(degree);
  case CellType::Point1:
    break;
  }
  throw Error("gauss_rule: no quadrature for cell type " + to_string(type));
}

int stiffness_degree(CellType type) {
  switch (type) {
  case CellType::Line2:
  case CellType::Line3:
  case CellType::Tri3:
  case CellType::Tri6:
  case CellType::Tet4:
    return 2 * (cell_order(type) - 1);
  default:
    return 2 * cell_order(type);
  }
}

int stiffness_degree(CellType type, Kinematics kin) {
  return stiffness_degree(type) + (kin == Kinematics::Axisymmetric ? 1 : 0);
}

} // namespace bipot
