#pragma once
/// Internal to fem/analysis: `semismooth_newton` and `bipotential_uzawa`, Newton on the whole
/// matrix with the augmented-Lagrangian multiplier updates (augmented_lagrangian_increment.cpp).
/// Also the increment solver of a model whose interfaces do not act on the system (a bulk-only
/// Newton, or interfaces tied by shared nodes).

#include "fem/analysis/detail/increment_context.hpp"
#include "fem/analysis/detail/increment_solver.hpp"

#include <vector>

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
  /// R (and K, when the tangent changed or the first pass eliminates the prescribed
  /// increments) at u for `constraints`; returns whether K was rebuilt.
  bool assemble(const Constraints& constraints, double dtau, bool first_pass);
  /// The interfaces' corrector r̂ ← Proj(τ); false (and log.failure) once the contact
  /// solver's limit on updates is reached.
  bool update_multipliers(IncrementLog& log, bool matrix_rebuilt);
  /// du = K⁻¹ R, setting the solver up first if K was rebuilt; false (and log.failure) if the
  /// factorisation or the solve fails.
  bool newton_step(IncrementLog& log, bool matrix_rebuilt);
  /// u += s du on the free DOFs (the prescribed ones take the whole step), s from the
  /// backtracking line search on ‖R‖ when `damp`, else 1. True when it took the full step
  /// after assembling the system there (for the held constraints; `rebuilt_ahead`: whether K
  /// was rebuilt), which the next iteration then uses as it is.
  bool move(const std::vector<bool>& prescribed, double norm, double dtau, bool damp,
            bool& rebuilt_ahead);

  IncrementContext& ctx_;
};

} // namespace bipot
