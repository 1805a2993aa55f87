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

/// The Newton iteration runs on the small dense system of the interface DOFs I and the
/// interface multipliers (CondensedInterfaceSystem); the interface linear algebra is the
/// Schur complement of K on I (SchurComplementSolver, factorised once per constrained set
/// while the bulk is linear) and the dense Newton matrices (ReusedLuSolver); a nonlinear bulk
/// adds an outer loop over condensations. Handles path-following steps (IncrementRequest::
/// path).
class ExactNewtonIncrement : public IncrementSolver {
public:
  /// `schur_ready` is the driver's: it clears it when it overwrites K (a new ρ assembles the
  /// unconstrained bulk). `bulk_product` gives a linear bulk's residual from products with K.
  ExactNewtonIncrement(IncrementContext& context, const CondensedInterfaceSystem& system,
                       LinearBulkResidual& bulk_product, bool& schur_ready)
      : ctx_(context), sys_(system), bulk_product_(bulk_product), schur_ready_(schur_ready) {}
  bool solve(const IncrementRequest& request, IncrementLog& log) override;

private:
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
