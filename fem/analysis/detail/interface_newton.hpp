#pragma once
/// Internal to fem/analysis: the generalized Newton iteration on the condensed interface
/// system of one bulk state (interface_newton.cpp), ExactNewtonIncrement's inner loop.

#include "fem/analysis/detail/convergence_test.hpp"
#include "fem/analysis/detail/increment_context.hpp"
#include "fem/analysis/detail/increment_solver.hpp"
#include "fem/assembly/condensed_interface_system.hpp"
#include "fem/linalg/condensed_newton_matrix.hpp"
#include "fem/linalg/reused_lu_solver.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <vector>

namespace bipot {

/// Newton on z = (x, λ_c[, Δλ]): x the increments of the interface DOFs I from u, λ_c = A r
/// the multipliers, Δλ the load factor's increment of a path-following step. Its residual is
///   F(z) = ( c − S x [+ Δλ c1] + f_c(x, λ_c),  F_λ(x, λ_c) [, g(z)] )
/// with S the Schur complement of the bulk on I, c the condensed bulk residual, c1 its
/// change per unit load factor, f_c and F_λ the interfaces' forces and law
/// (CondensedInterfaceSystem), g the path constraint (PathStep). J = [−S 0; 0 0] + the sparse
/// interface (and border) terms, solved inexactly by GMRES on earlier factors
/// (ReusedLuSolver), each step backtracked on ‖F‖ unless its only excess is the overshoot
/// of pairs going from stick to slip (see solve()).
class InterfaceNewton {
public:
  /// The condensed system of the bulk state `context.u`; S, c and c1 must outlive this.
  /// `path`: a path-following step (c1 used), else none.
  InterfaceNewton(IncrementContext& context, const CondensedInterfaceSystem& system,
                  const std::vector<bool>& constrained_I, const Eigen::MatrixXd& S,
                  bool symmetric_S, const Eigen::VectorXd& c, const Eigen::VectorXd& c1,
                  PathStep* path, double dtau);

  /// Iterates from z (in: the start; out: the last iterate) until the forces and the law
  /// pass `test` (and the path constraint its own tolerance), or fails after `iteration_limit`
  /// iterations, on a non-finite residual or a singular Jacobian (false, log.failure).
  /// Counts iterations, the history of the relative force residual (with a linear bulk) and
  /// the linear algebra in `log` and the context's summary.
  bool solve(Eigen::VectorXd& z, const ConvergenceTest& test, int iteration_limit,
             ReusedLuSolver& newton_solver, IncrementLog& log);

private:
  /// F at `at` (the interfaces evaluated there) and, with `jac`, J's sparse part.
  void residual(const Eigen::VectorXd& at, Eigen::VectorXd& out, CondensedNewtonMatrix* jac);
  /// The line search's merit: each residual in units of its own tolerance.
  double merit(const Eigen::VectorXd& r) const;
  /// merit(r) without the law rows of the pairs stuck in `before` and sliding in `after`.
  double merit_without_stick_to_slip(const Eigen::VectorXd& r,
                                     const std::vector<ContactStatus>& before,
                                     const std::vector<ContactStatus>& after) const;

  IncrementContext& ctx_;
  const CondensedInterfaceSystem& sys_;
  const std::vector<bool>& constrained_I_;
  const Eigen::VectorXd &c_, &c1_;
  PathStep* path_;
  double dtau_;
  Index nI_, n_, nz_;         ///< |I|, |I| + multipliers, unknowns (n + 1 with a path)
  CondensedNewtonMatrix J_;   ///< the Newton matrix of the current iterate
  std::vector<double> trial_; ///< u with I moved by x
  std::vector<Eigen::Triplet<double>> entries_; ///< J's sparse part
  Eigen::VectorXd grad_;                        ///< the path constraint's gradient
  double g_weight_ = 0;                         ///< the path constraint's weight in the merit
  bool lambda_held_ = false; ///< the constraint had no gradient at the last Jacobian: dΔλ = 0
  bool holding_ = true;      ///< every Jacobian so far had Δλ held
};

} // namespace bipot
