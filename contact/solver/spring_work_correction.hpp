#pragma once
/// The three-point rule's correction of the work done on a pair's adhesive springs over the
/// last increment (interface_energy.cpp, docs/energy_quadrature.md). The springs' work
/// −∫ a·dg is the part of the external work that the trapezoidal rule integrates with an
/// error while β falls; the rule needs the path to be smooth across the two last steps,
/// which it is not where some pair's β starts or stops falling (a kink in its a(g), and
/// through the bodies' stiffness one in every pair's path): the ledger keeps the trapezoid
/// for every pair of the model if any pair is Kinked.

#include "fem/core/three_point_rule.hpp"

#include <Eigen/Core>

namespace bipot::contact {

/// The adhesive traction a and the jump g at the stencil's three states (0: before the last
/// step but one, 2: now), and β at those and one state earlier (beta[1..3] at a/g's 0..2).
struct SpringHistory {
  Eigen::VectorXd a[3], g[3];
  double beta[4] = {0, 0, 0, 0};
};

/// How a pair's springs went over the stencil's two steps and the step before them.
enum class SpringPath {
  Steady,    ///< β did not change: a linear spring, both rules exact
  Softening, ///< β fell over all three steps and is not 0: smooth, the rule applies
  Kinked     ///< β started or stopped falling, or reached 0, within them
};
/// The step before the stencil is included so that a kink at its first state (β starting to
/// fall there) is seen.
SpringPath spring_path(const SpringHistory& h);

/// Per unit area: rule(−a·dg) − trapezoid(−a·dg) on a Softening pair, else 0.
double spring_work_correction(const ThreePointRule& rule, const SpringHistory& h);

} // namespace bipot::contact
