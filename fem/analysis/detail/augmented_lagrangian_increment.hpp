#pragma once
/// Internal to fem/analysis: `semismooth_newton` and `bipotential_uzawa`, Newton on the whole
/// matrix with the augmented-Lagrangian multiplier updates (augmented_lagrangian_increment.cpp).
/// Also the increment solver of a model whose interfaces do not act on the system (a bulk-only
/// Newton, or interfaces tied by shared nodes).

#include "fem/analysis/detail/increment_context.hpp"
#include "fem/analysis/detail/increment_solver.hpp"

namespace bipot {

/// Newton on u with the interface multipliers r̂ held, the interfaces' corrector r̂ ← Proj(τ)
/// between: after equilibrium (bipotential_uzawa) or once the inner residual dropped tenfold
/// (semismooth_newton). Assembles K and sets up the sparse linear solver only when the
/// tangent changed. No path-following.
class AugmentedLagrangianIncrement : public IncrementSolver {
public:
  explicit AugmentedLagrangianIncrement(IncrementContext& context) : ctx_(context) {}
  bool solve(const IncrementRequest& request, IncrementLog& log) override;

private:
  IncrementContext& ctx_;
};

} // namespace bipot
