#pragma once
/// Internal to fem/analysis: the β-staggered fallback for an increment the monolithic
/// iteration cannot solve even at its smallest step (staggered_increment.cpp).

#include "fem/analysis/detail/increment_context.hpp"
#include "fem/analysis/detail/increment_solver.hpp"

namespace bipot {

/// Alternates the increment solver `monolithic` with every interface's adhesion β held and
/// the update of β from the displacement, then confirms the result with the true law. Only
/// for interfaces whose β can change (InterfaceEnforcement::adhesion_can_change).
class StaggeredIncrement : public IncrementSolver {
public:
  StaggeredIncrement(IncrementContext& context, IncrementSolver& monolithic)
      : ctx_(context), monolithic_(monolithic) {}
  /// `request.path` and `request.max_iterations` are not used: β-held solves take the
  /// contact solver's own limit.
  bool solve(const IncrementRequest& request, IncrementLog& log) override;

private:
  IncrementContext& ctx_;
  IncrementSolver& monolithic_;
};

} // namespace bipot
