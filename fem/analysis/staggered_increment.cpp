// The β-staggered fallback of the stage driver (StaggeredIncrement).
#include "fem/analysis/detail/staggered_increment.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace bipot {

// Fallback for an increment the monolithic iteration cannot solve even at the smallest step:
// a debonding snap-back, where β = min(β_old, w/E) has no solution continuous with the last
// state (Newton cycles between states). Alternate a solve with β held fixed (a well-posed
// contact problem) and the update of β from the displacement. β only decreases along this
// sequence, which therefore converges, to the equilibrium after the jump; the monolithic
// iteration then confirms it with the true law. Leaves `u` at the last iterate.
bool StaggeredIncrement::solve(const IncrementRequest& request, IncrementLog& log) {
  const auto& interfaces = ctx_.interfaces;
  const IncrementRequest held{request.lambda, request.dtau};
  constexpr int max_updates = 200;
  constexpr double beta_tolerance = 1e-6; // the monolithic check with the true law decides
  std::vector<std::vector<double>> beta(interfaces.size());
  for (std::size_t k = 0; k < interfaces.size(); ++k)
    beta[k] = interfaces[k]->committed_adhesion();
  auto merge = [&log](const IncrementLog& sub) {
    log.iterations += sub.iterations;
    log.linear_iterations += sub.linear_iterations;
    log.uzawa_updates += sub.uzawa_updates;
    log.history = sub.history;
    log.contact = sub.contact;
    log.failure = sub.failure;
  };
  auto unfreeze = [&] {
    for (const auto& ia : interfaces)
      ia->unfreeze_adhesion();
  };
  for (int it = 0; it < max_updates; ++it) {
    for (std::size_t k = 0; k < interfaces.size(); ++k)
      interfaces[k]->freeze_adhesion(beta[k]);
    IncrementLog sub;
    const bool ok = monolithic_.solve(held, sub);
    merge(sub);
    ++log.staggered;
    if (!ok) {
      unfreeze();
      log.failure = "staggered fallback, with beta held: " + log.failure;
      return false;
    }
    double change = 0;
    for (std::size_t k = 0; k < interfaces.size(); ++k) {
      std::vector<double> next = interfaces[k]->adhesion_at(ctx_.u, request.dtau);
      for (std::size_t i = 0; i < next.size(); ++i)
        change = std::max(change, std::abs(next[i] - beta[k][i]));
      beta[k] = std::move(next);
    }
    if (change <= beta_tolerance) break;
  }
  unfreeze();
  IncrementLog final_check;
  const bool ok = monolithic_.solve(held, final_check);
  merge(final_check);
  if (!ok) log.failure = "staggered fallback, final check with the true law: " + log.failure;
  return ok;
}

} // namespace bipot
