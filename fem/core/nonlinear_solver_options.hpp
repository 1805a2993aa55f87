#pragma once
/// What the analysis driver needs to know of the nonlinear solver chosen in the input
/// (`contact_solver:`): which iteration, its tolerance and limits. The contact module's
/// options (contact/solver/contact_solver_options.hpp) add the augmentation parameters.

#include <string>

namespace bipot {

struct NonlinearSolverOptions {
  std::string type = "generalized_newton";
  double tolerance = 1e-8;      ///< on the force residual and on the multiplier change
  int max_iterations = 50;      ///< Newton iterations (inner ones for Uzawa)
  int max_outer_iterations = 1; ///< Uzawa multiplier updates per increment
  int max_cutbacks = 6;         ///< halvings of a failing increment before the run stops
  bool line_search = true;      ///< backtracking on the residual norm

  bool uzawa() const { return type == "bipotential_uzawa"; }
  /// Exact generalized Newton on the condensed interface system (CondensedInterfaceSystem).
  bool exact_newton() const { return type == "generalized_newton"; }
};

} // namespace bipot
