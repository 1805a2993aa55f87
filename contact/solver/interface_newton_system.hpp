#pragma once
/// The interface equations of the exact generalized Newton (`generalized_newton`), once the
/// bulk has been condensed onto the interface DOFs.
///
/// Unknowns: x, the displacement increments of the interface DOFs I (both copies of every
/// pair's nodes; node a alone against a rigid obstacle), and λ_i = A_i r_i (kN, local frame), the
/// irreversible interface force of every pair (Alart & Curnier 1991: the multipliers are unknowns
/// of the Newton step, not moved by an outer loop). With the bulk condensed (Schur complement S,
/// reduced load c):
///
///     F_x  = c − S x + f_c(x, λ)                    equilibrium of I
///     F_λi = λ_i − A_i Proj_{K_μ̄}(τ_i),  τ_i = λ_i/A_i − ρ_i [Δg_t + (g_n + μ̄‖Δg_t‖) n]
///
/// f_c puts +Q_i (λ_i + A_i a_i) on node b and its opposite on node a, a_i = −β²(C_n g_n n +
/// C_t g_t) the adhesive traction with β = β(jump) the implicit update. F_λ = 0 is the
/// bipotential fixed point of docs/formulation.md §4, hence the interface law itself. Its exact
/// generalized Jacobian, from the projection's and the β update's derivatives
/// (InterfaceResponseDerivatives), makes the iteration locally quadratic; in stick
/// ∂F_λ/∂λ = 0 (but for stick_regularisation, below) and the rows enforce the jump exactly
/// (no penalty), in separation λ = 0. A stuck component acting only on prescribed DOFs is
/// undetermined; its row also fixes its own step (see add()).

#include "contact/solver/interface_assembler.hpp"
#include "fem/assembly/condensed_interface_system.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <string>
#include <vector>

namespace bipot::contact {

/// The size of the dense condensed system generalized_newton builds, without building it:
/// dim × (distinct nodes of the pairs, obstacles having none) DOFs and dim × pairs
/// multipliers, over the interfaces given (those that do not share their nodes).
struct CondensedSize {
  Index dofs = 0, multipliers = 0;
  Index total() const { return dofs + multipliers; }
};
CondensedSize condensed_size(const std::vector<const Interface*>& interfaces, int dim);

/// The largest condensed system generalized_newton accepts: its LU costs (2/3) n³ per
/// factorisation and S (at most n² doubles) and the single-precision factors (n² floats)
/// hold up to 1.5 n² doubles' worth (1.7 GB at 12,000); past it semismooth_newton (sparse,
/// the whole mesh) is the better tool.
constexpr Index max_condensed_unknowns = 12000;
/// The message refusing a larger one ("" when it fits), prefixed by `where`.
std::string condensed_size_problem(const CondensedSize& size, const std::string& where);

class InterfaceNewtonSystem final : public CondensedInterfaceSystem {
public:
  /// ∂F_λ/∂λ of a stuck component in J (the law's own is 0). Two pairs on the same two nodes
  /// (a node on two interfaces, as the pile's toe corner is on the shaft's and the toe's), both
  /// stuck, tie the same jump: only the sum of their forces is determined and J is singular.
  /// A fresh LU then gave Newton steps of 1e24 kN that no line search could take back (the
  /// Coulomb pile: 332 linear solves and a cut-back; 75 with it). ε on the diagonal makes J
  /// regular and picks the split of least ‖Δλ‖; elsewhere it only moves a Newton step's
  /// F_λ by ε ‖Δλ‖, far below any tolerance (the block's and the piles' counts are unchanged).
  static constexpr double stick_regularisation = 1e-12;

  /// Over `interfaces` (not owned).
  InterfaceNewtonSystem(const std::vector<InterfaceAssembler*>& interfaces, const DofMap& dofs);

  const std::vector<Index>& dofs() const override { return dofs_; }
  Index num_multipliers() const override { return num_multipliers_; }

  /// λ = A r̂ from the interfaces' current multipliers.
  Eigen::VectorXd multipliers() const override;
  /// r̂ = λ / A on the interfaces, for their next evaluate().
  void set_multipliers(const Eigen::VectorXd& lambda) const override;

  /// For the interfaces' last evaluate(): adds f_c to F.head(num_dofs()) and sets
  /// F.tail(num_multipliers()) to F_λ; with J, adds their derivatives with respect to
  /// (x, λ). Rows of I-DOFs flagged in `constrained` (same order as dofs()) get no interface
  /// term: their equation prescribes the DOF (the reaction takes the interface force).
  void add(const std::vector<bool>& constrained, Eigen::VectorXd& F,
           Eigen::MatrixXd* J) const override;
  /// The same with J's interface terms as (row, column, value) entries appended to `J` (a
  /// few per pair; duplicates are to be summed): the sparse part of the Newton matrix, whose
  /// dense part is the condensed bulk alone.
  void add(const std::vector<bool>& constrained, Eigen::VectorXd& F,
           std::vector<Eigen::Triplet<double>>& J) const override;

  /// max_i ‖F_λi‖ (kN) of an F filled by add(): how far the multipliers are from the law.
  double multiplier_residual(const Eigen::VectorXd& F) const override;
  std::vector<ContactStatus> branches() const override;

  /// Σ_i A_i [E(β_i,committed) − E(β_i)], E = the law's adhesion_energy: the energy that
  /// adhesion loss has released since the last converged increment, at the interfaces' last
  /// evaluate() (kJ). With grad, adds its derivatives with respect to x (through β's
  /// dependence on the jump): the row a dissipation-controlled step borders J with.
  double released_adhesion_energy(Eigen::VectorXd* grad) const override;
  /// A pair whose friction force is on the cone to within round-off (ConeTie: typically at an
  /// increment's start after slip, Δg_t = 0) takes the slip branch if Fx, the force that
  /// would move its nodes with the multipliers held, drives its jump along its slip (against
  /// r_t), else stick.
  bool set_tie_hints(const Eigen::VectorXd& Fx,
                     const std::vector<bool>& constrained) const override;

private:
  /// add() with each Jacobian entry passed to jac(row, column, value) (null: F only).
  template <class AddEntry>
  void add_terms(const std::vector<bool>& constrained, Eigen::VectorXd& F, AddEntry* jac) const;

  struct PairSlots {
    InterfaceAssembler* iface;
    std::size_t pair;
    Index a, b;       ///< position in dofs() of node a's / node b's first component (b: -1
                      ///< against a rigid obstacle)
    Index multiplier; ///< position of λ_i in the unknowns
  };
  std::vector<InterfaceAssembler*> interfaces_;
  std::vector<Index> dofs_;
  std::vector<PairSlots> pairs_;
  Index num_multipliers_ = 0;
  int dim_;
};

} // namespace bipot::contact
