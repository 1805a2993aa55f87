#pragma once
/// The interface equations of an exact generalized Newton once the bulk is condensed onto the
/// interface DOFs I (fem/analysis/exact_newton_increment.cpp): the unknowns are x, the
/// displacement increments of I, and the interfaces' multipliers λ; with S the bulk's Schur
/// complement on I and c the condensed load, the driver solves
///     F_x = c − S x + f_c(x, λ) = 0,   F_λ(x, λ) = 0
/// where f_c and F_λ (and their generalized derivatives) come from this class. The contact
/// module implements it (contact/solver/interface_newton_system.hpp: Alart–Curnier form of the
/// bipotential fixed point).

#include "fem/core/interface_point.hpp"
#include "fem/core/types.hpp"

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <vector>

namespace bipot {

class CondensedInterfaceSystem {
public:
  virtual ~CondensedInterfaceSystem() = default;

  /// Global DOFs of I, sorted: rows and columns of x.
  virtual const std::vector<Index>& dofs() const = 0;
  Index num_dofs() const { return static_cast<Index>(dofs().size()); }
  virtual Index num_multipliers() const = 0;
  Index size() const { return num_dofs() + num_multipliers(); }

  /// λ from the interfaces' current multipliers.
  virtual Eigen::VectorXd multipliers() const = 0;
  /// Gives λ to the interfaces, for their next evaluate().
  virtual void set_multipliers(const Eigen::VectorXd& lambda) const = 0;

  /// For the interfaces' last evaluate(): adds f_c to F.head(num_dofs()) and sets
  /// F.tail(num_multipliers()) to F_λ; with J, adds their derivatives with respect to
  /// (x, λ). Rows of I-DOFs flagged in `constrained` (same order as dofs()) get no interface
  /// term. Touches rows and columns below size() only (a bordered J passes as it is).
  virtual void add(const std::vector<bool>& constrained, Eigen::VectorXd& F,
                   Eigen::MatrixXd* J) const = 0;
  /// The same with J's interface terms as (row, column, value) entries appended to `J`
  /// (duplicates are to be summed): the sparse part of the Newton matrix, whose dense part is
  /// the condensed bulk alone (CondensedNewtonMatrix).
  virtual void add(const std::vector<bool>& constrained, Eigen::VectorXd& F,
                   std::vector<Eigen::Triplet<double>>& J) const = 0;
  /// max_i ‖F_λi‖ (kN) of an F filled by add(): how far the multipliers are from the law.
  virtual double multiplier_residual(const Eigen::VectorXd& F) const = 0;
  /// Each pair's branch of the law (stick, slip, open) at the interfaces' last evaluate(), in
  /// the order of the multipliers: pair k's law rows in F are num_dofs() + d k, ..., + d − 1,
  /// d = num_multipliers() / (number of pairs).
  virtual std::vector<ContactStatus> branches() const = 0;
  /// The energy adhesion loss has released since the last converged increment, at the last
  /// evaluate() (kJ); with grad, adds its derivatives with respect to x (the row a
  /// dissipation-controlled step borders J with).
  virtual double released_adhesion_energy(Eigen::VectorXd* grad) const = 0;
  /// Where a pair sits on a kink of its law to within round-off, as a friction force left
  /// exactly on the cone at an increment's start, every branch's derivative is an element of
  /// the generalized Jacobian and round-off picks one: tells the interfaces which to take
  /// from `Fx`, the interface DOFs' residual F.head(num_dofs()) at the start of a Newton
  /// iteration, whose direction indicates where the coming step goes (rows flagged in
  /// `constrained` left out). Returns whether a pair's branch changed (the caller evaluates
  /// again). By default there are no such kinks.
  virtual bool set_tie_hints(const Eigen::VectorXd& /*Fx*/,
                             const std::vector<bool>& /*constrained*/) const {
    return false;
  }
};

} // namespace bipot
