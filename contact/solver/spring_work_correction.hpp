#pragma once
/// The three-point rule's correction of the work done on a pair's adhesive springs over the
/// last increment (interface_energy.cpp, docs/energy_quadrature.md). The springs' work
/// −∫ a·dg is the part of the external work that the trapezoidal rule integrates with an
/// error while β falls; the rule needs the path to be smooth across the two last steps,
/// which it is not where some pair's β starts or stops falling or its contact branch changes
/// (a kink in its traction, and through the bodies' stiffness one in every pair's path): the
/// ledger keeps the trapezoid for every pair of the model if any pair is Kinked.

#include "fem/core/three_point_rule.hpp"

#include <Eigen/Core>

namespace bipot::contact {

/// What a pair did over one step, for the kink test: β fell or not, β reached 0, and its
/// contact branch (ContactStatus) at the step's end.
int spring_regime(double beta_old, double beta_new, int status);

/// The pair's last steps: the adhesive traction a and the jump g at the stencil's three
/// states (0: before the last step but one, 2: now), whether β fell over the last step, and
/// for how many steps, up to the last, the regime (spring_regime) has not changed.
struct SpringHistory {
  Eigen::VectorXd a[3], g[3];
  bool softening = false;
  int regime_steps = 0;
};

/// How a pair went over the stencil's two steps and the steps before them.
enum class SpringPath {
  Steady,    ///< β did not change, same contact branch: a linear spring, both rules exact
  Softening, ///< β fell over them all and is not 0, same branch: the rule applies
  Kinked     ///< the regime changed within them
};

/// Steps of one regime that a pair needs for the rule, counted back from the step it
/// integrates: the stencil's two and two before them. A kink leaves the path's higher
/// derivatives large for a while after it: with one step before (the least that sees a kink
/// at the stencil's first state) the traced pile at half density over-corrected the step two
/// after each onset, its worst error 3.4e-5 (trapezoid) → 4.8e-5; with two it stays 3.4e-5,
/// the end's falls 1.4e-5 → 9.8e-6, and the column is as before (docs/energy_quadrature.md).
constexpr int regime_steps_needed = 4;

SpringPath spring_path(const SpringHistory& h);

/// Per unit area: rule(−a·dg) − trapezoid(−a·dg) on a Softening pair, else 0.
double spring_work_correction(const ThreePointRule& rule, const SpringHistory& h);

} // namespace bipot::contact
