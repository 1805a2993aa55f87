// The choice of the increment solver (make_increment_solver).
#include "fem/analysis/detail/increment_solver.hpp"

#include "fem/analysis/detail/augmented_lagrangian_increment.hpp"
#include "fem/analysis/detail/exact_newton_increment.hpp"

namespace bipot {

std::unique_ptr<IncrementSolver> make_increment_solver(IncrementContext& context,
                                                       const CondensedInterfaceSystem* condensed,
                                                       LinearBulkResidual& bulk_product,
                                                       bool& schur_ready) {
  // The interface module builds a condensed system exactly for generalized_newton with an
  // interface that acts on the system; otherwise (tied or no interfaces) there is nothing to
  // condense and the whole-matrix Newton is the bulk's Newton.
  if (condensed)
    return std::make_unique<ExactNewtonIncrement>(context, *condensed, bulk_product, schur_ready);
  return std::make_unique<AugmentedLagrangianIncrement>(context);
}

} // namespace bipot
