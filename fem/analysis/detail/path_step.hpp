#pragma once
/// Internal to fem/analysis: one path-following increment, as the stage driver's PathControl
/// sets it up and the generalized Newton (ExactNewtonIncrement) solves it.

#include "fem/assembly/condensed_interface_system.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <vector>

namespace bipot {

/// The entries of `u` on the interface DOFs I of `sys`, in its order.
Eigen::VectorXd on_interface_dofs(const CondensedInterfaceSystem& sys,
                                  const std::vector<double>& u);

/// One path-following increment (stage `control:` arc_length or dissipation): the load
/// factor's increment Δλ joins the unknowns of the generalized Newton step, bordered by one
/// constraint g(x, λ_c, Δλ) = 0 (fem/analysis/path_constraint.cpp, docs/theory.md):
///   arc_length:  ‖x‖ = L                                (Crisfield, cylindrical)
///   dissipation: Σ A w (β_committed − β(x)) = Δτ          (Gutiérrez 2004)
/// x the increment of the interface DOFs, β the adhesion the law gives at the trial jumps.
struct PathStep {
  enum class Kind { ArcLength, Dissipation } kind = Kind::ArcLength;
  Eigen::VectorXd x_prev;              ///< the previous increment on I (direction and predictor)
  double dlambda_prev = 0, length = 0; ///< Δλ_prev; arc_length: L (m)
  /// A nonlinear bulk's outer iterations: how far I moved in the earlier ones of this
  /// increment (x counts from the current bulk state); empty: none.
  Eigen::VectorXd x_offset;
  double dissipation = 0;     ///< Δτ (kJ)
  double predictor_scale = 1; ///< z0 = scale × (x_prev, Δλ_prev)
  // Out: the converged increment.
  Eigen::VectorXd x;
  double dlambda = 0;

  /// g and, with grad (size n + 1), its gradient with respect to (x, λ_c, Δλ), at z after
  /// the interfaces were evaluated there.
  double constraint(const CondensedInterfaceSystem& sys, const Eigen::VectorXd& z,
                    Eigen::VectorXd* grad) const;
  /// The constraint's own scale (L or Δτ).
  double scale() const { return kind == Kind::ArcLength ? length : dissipation; }
  /// |g| ≤ constraint_tolerance(tolerance) is met: √tolerance × scale(). The constraint only
  /// picks which equilibrium of the path the step ends on, and the step's length is itself a
  /// choice (adapted by factors of 0.6 to 1.5): the step's equilibrium and the interface law
  /// are what the solver tolerance is for. Held to the tolerance itself, a converged
  /// equilibrium often took one more Newton iteration for the constraint alone, and the
  /// constraint's kinks (each pair's β = min(β_old, w/E)) made it the slowest residual.
  double constraint_tolerance(double tolerance) const { return std::sqrt(tolerance) * scale(); }
};

} // namespace bipot
