#pragma once
/// Internal to fem/analysis: `generalized_newton`, the exact generalized Newton of one
/// increment on the bulk condensed onto the interface DOFs (exact_newton_increment.cpp).

#include "fem/analysis/detail/increment_context.hpp"
#include "fem/analysis/detail/increment_solver.hpp"
#include "fem/assembly/condensed_interface_system.hpp"
#include "fem/assembly/linear_bulk_residual.hpp"
#include "fem/linalg/reused_lu_solver.hpp"
#include "fem/linalg/schur_complement_solver.hpp"

#include <vector>

namespace bipot {

/// Each outer iteration condenses the bulk at u onto the interface DOFs I (the Schur
/// complement of K on I, SchurComplementSolver, factorised once per constrained set while the
/// bulk is linear), runs the generalized Newton iteration on the small dense system of I and
/// the interface multipliers (InterfaceNewton), and recovers the rest of the mesh by one back
/// substitution. A linear bulk needs one outer iteration, checked on the whole mesh; a
/// nonlinear one repeats it around each new bulk state until the assembled residual is met.
/// Handles path-following steps (IncrementRequest::path).
class ExactNewtonIncrement : public IncrementSolver {
public:
  /// `schur_ready` is the driver's: it clears it when it overwrites K (a new ρ assembles the
  /// unconstrained bulk). `bulk_product` gives a linear bulk's residual from products with K.
  ExactNewtonIncrement(IncrementContext& context, const CondensedInterfaceSystem& system,
                       LinearBulkResidual& bulk_product, bool& schur_ready)
      : ctx_(context), sys_(system), bulk_product_(bulk_product), schur_ready_(schur_ready) {
    schur_.set_factor_directory(factor_directory(ctx_.solver.options()));
  }
  bool solve(const IncrementRequest& request, IncrementLog& log) override;
  /// The dense Newton factors (at 936k DOFs 82 MiB in single precision); S and the bulk
  /// factors stay, as the next stage may solve on them.
  void release_workspace() override {
    newton_matrix_.reset();
    path_matrix_.reset();
  }

private:
  struct Increment; ///< the increment's data and its current outer iteration
  /// R = the bulk residual at u with the prescribed increments of outer iteration `outer`
  /// (and inc.R1, its change per unit load factor, for a path); K assembled with `refactor`.
  void assemble_bulk_residual(Increment& inc, int outer, bool refactor);
  /// The whole residual at u (bulk and interface forces) on the free DOFs: the reference of
  /// the increment and, for a nonlinear bulk, the test of the outer loop.
  double whole_residual(const Increment& inc, double dtau);
  /// Factorises K's Schur complement on I (false and log.failure if it fails).
  bool condense(Increment& inc, IncrementLog& log);
  /// du from the interface increment x; with a path, R and the loads at the Δλ found first.
  std::vector<double> expand(Increment& inc, const Eigen::VectorXd& z);
  /// A linear bulk: the whole residual R0 − K du + f_c(u) after the back substitution is the
  /// interface residual up to round-off; true if it is below 100 × `floor`.
  bool check_whole_mesh(double floor, IncrementLog& log);

  IncrementContext& ctx_;
  const CondensedInterfaceSystem& sys_;
  LinearBulkResidual& bulk_product_;
  bool& schur_ready_;
  SchurComplementSolver schur_;
  std::vector<Index> schur_constrained_; ///< constrained DOFs of the factorised matrix
  ReusedLuSolver newton_matrix_;         ///< the dense Newton steps, factors kept across iterations
  ReusedLuSolver path_matrix_;           ///< the bordered Newton matrices of path-following steps
};

} // namespace bipot
