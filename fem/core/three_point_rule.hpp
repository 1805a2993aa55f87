#pragma once
/// A higher-order quadrature of a path integral ∫ F·du over the last step of a path known
/// only at its three latest states (docs/energy_quadrature.md). F and u are interpolated
/// quadratically in a path parameter s through s0 < s1 < s2 and F̃·ũ' (a cubic) is integrated
/// exactly over [s1, s2]: W = Σ_ij c_ij F_i·u_j. On a smooth path its error is O(h⁴) a step
/// (the trapezoid's O(h³)); it is exact where F is an affine function of u (a linear bulk,
/// an elastic spring) and where F is constant (friction at a constant force). Only the ratio
/// of the two step lengths enters.

namespace bipot {

struct ThreePointRule {
  /// c[i][j]: weight of F_i·u_j (i, j = 0, 1, 2 for s0, s1, s2). Each row sums to
  /// zero (a constant u does no work).
  double c[3][3] = {{0, 0, 0}, {0, -0.5, 0.5}, {0, -0.5, 0.5}};
  /// False: c is the trapezoidal rule ½ (F1 + F2)·(u2 − u1), the path is not known to be
  /// smooth over both steps.
  bool three_point = false;

  /// The largest ratio of two consecutive step lengths (either way) the rule is used for: the
  /// interpolation's error constant grows with it, and a step much longer than the one before
  /// is one the shorter one does not resolve; on the traced column a limit of 2.5 (which
  /// keeps the step controls' growth by 1.5 or 2 and their halvings) gives 1.3e-2 at 12
  /// increments where none gives 3.9e-2 and the trapezoid 1.9e-2 (docs/energy_quadrature.md).
  static constexpr double max_step_ratio = 2.5;

  /// The trapezoidal rule (the default).
  static ThreePointRule trapezoid() { return {}; }
  /// The quadratic rule for steps of lengths h1 = s1 − s0 and h2 = s2 − s1 (both > 0).
  static ThreePointRule quadratic(double h1, double h2);

  /// Σ_ij c_ij f_i u_j for scalars (one component of F·u).
  double apply(const double f[3], const double u[3]) const;
  /// The same minus the trapezoid's: what the rule adds to the trapezoidal rule.
  double correction(const double f[3], const double u[3]) const;
};

} // namespace bipot
