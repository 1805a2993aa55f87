// The iterations of one load increment (StaticAnalysis::Impl): Newton with the contact
// solvers' multiplier updates, the line search, and the staggered fallback for jumps.
#include "fem/analysis/detail/static_analysis_impl.hpp"

namespace bipot {

using namespace analysis_detail;

// ‖R‖ at a trial displacement for the current multipliers (line search merit). Uses R as
// scratch; no matrix.
double StaticAnalysis::Impl::residual_norm(const std::vector<double>& trial, double dtau,
                                           const Constraints& constraints) {
  R.set_zero();
  solid.assemble(trial, constraints, nullptr, R);
  for (const auto& ia : interfaces) {
    ia->evaluate(trial, dtau);
    ia->add_to_system(constraints, nullptr, R);
  }
  R.finish_assembly();
  add_step_loads(constraints);
  return R.norm2();
}

// Newton (and, for bipotential_uzawa, Uzawa) iterations of one increment ending at stage
// load factor `lambda`. Leaves `u` at the last iterate; the caller restores it on failure.
bool StaticAnalysis::Impl::solve_increment(double lambda, double dtau, IncrementLog& log,
                                           int exact_iterations) {
  if (newton_system) return solve_increment_exact(lambda, dtau, log, nullptr, exact_iterations);
  const NonlinearSolverOptions& copt = model.contact_solver;
  const int max_iterations = has_contact ? copt.max_iterations : options.max_iterations;
  const double tolerance = has_contact ? copt.tolerance : options.residual_tolerance;
  F_step.copy(F_prev);
  F_step.scale(1.0 - lambda);
  F_step.axpy(lambda, F_cur);
  for (std::size_t k = 0; k < interfaces.size(); ++k) {
    interfaces[k]->set_gap_shift(gap_start[k] + lambda * (gap_target[k] - gap_start[k]));
    interfaces[k]->begin_increment(extrapolation);
  }
  move_obstacles(lambda);

  std::vector<bool> prescribed(u.size());
  for (const auto& kv : target)
    prescribed[kv.first] = true;
  Constraints constraints;
  double reference = 0.0, baseline = -1.0;
  bool first_pass = true;
  int inner = 0;
  for (;; ++log.iterations, ++inner) {
    constraints.clear();
    for (const auto& [d, v] : target)
      constraints.set(d, first_pass ? start[d] + lambda * (v - start[d]) - u[d] : 0.0);
    auto t0 = std::chrono::steady_clock::now();
    bool tangent_changed = false;
    for (const auto& ia : interfaces) {
      ia->evaluate(u, dtau);
      tangent_changed = tangent_changed || ia->tangent_changed();
    }
    // Prescribed increments are eliminated with the matrix's own diagonal: rebuild then.
    const bool need_matrix = !matrix_ready || !linear || tangent_changed ||
                             (has_contact && first_pass && !target.empty());
    R.set_zero();
    if (need_matrix) K->set_zero();
    solid.assemble(u, constraints, need_matrix ? K.get() : nullptr, R);
    for (const auto& ia : interfaces)
      ia->add_to_system(constraints, need_matrix ? K.get() : nullptr, R);
    R.finish_assembly();
    if (need_matrix) K->finish_assembly();
    add_step_loads(constraints);
    const double norm = free_norm(R, constraints);
    double change = 0, force_scale = 0, roundoff = 0;
    for (const auto& ia : interfaces) {
      change = std::max(change, ia->multiplier_change());
      force_scale = std::max(force_scale, ia->force_scale());
      roundoff = std::max(roundoff, ia->roundoff_force());
    }
    summary.assembly_seconds += seconds_since(t0);
    if (log.iterations == 0) {
      reference = std::max({norm, F_step.norm2(), force_scale, reaction_scale});
      if (reference == 0.0 && change == 0.0) return true; // nothing acts on the body
    }
    reference = std::max(reference, force_scale);
    log.history.push_back(norm / reference);
    log.contact = change / reference;

    // A tolerance below the interface forces' round-off (large ρ, tight tolerance) cannot be
    // met; the residual then stalls at that level, which counts as converged.
    const bool force_ok =
        !first_pass && norm <= std::max(tolerance * reference, roundoff_factor * roundoff);
    const bool contact_ok = change <= tolerance * reference;
    if (force_ok && contact_ok) return true;
    if (baseline < 0) baseline = norm;
    // When to move the multipliers (the corrector r̂ ← Proj(τ)): bipotential_uzawa once
    // equilibrium holds for the current ones; semismooth_newton as soon as the residual of
    // the current inner problem has dropped tenfold (inexact augmented Lagrangian), so
    // equilibrium and the contact law converge together.
    const bool inner_done = force_ok || (!copt.uzawa() && !first_pass && norm <= 0.1 * baseline);
    if (has_contact && inner_done && !contact_ok) {
      if (log.uzawa_updates >= copt.max_outer_iterations) {
        log.failure = "the Uzawa multipliers did not settle in " +
                      std::to_string(log.uzawa_updates) + " updates";
        return false;
      }
      for (const auto& ia : interfaces)
        ia->update_multipliers();
      ++log.uzawa_updates;
      // K was rebuilt but not factorised: the solver still holds the previous matrix, so
      // it must be set up again even if the next tangent equals the one last factorised.
      if (need_matrix) matrix_ready = false;
      inner = -1;
      baseline = -1; // the next residual, for the new multipliers, is the new baseline
      continue;
    }
    if (inner >= max_iterations) {
      log.failure = "no convergence in " + std::to_string(inner) + " iterations";
      return false;
    }
    if (!std::isfinite(norm)) {
      log.failure = "the residual is not finite";
      return false;
    }
    if (need_matrix) {
      t0 = std::chrono::steady_clock::now();
      // A failed factorisation (the direct solvers broadcast it: every rank throws) is a
      // failed increment, cut back like the others: a plastic tangent can be singular where
      // points sit at a yield surface's apex, which a smaller step may avoid.
      try {
        solver.setup(*K);
      } catch (const SolverError& e) {
        log.failure = e.what();
        return false;
      }
      summary.setup_seconds += seconds_since(t0);
      matrix_ready = true;
      for (const auto& ia : interfaces)
        ia->mark_tangent_assembled();
      ++summary.matrix_setups;
    }
    du.set_zero();
    t0 = std::chrono::steady_clock::now();
    LinearSolveStats stats;
    try {
      stats = solver.solve(R, du);
    } catch (const SolverError& e) {
      log.failure = e.what();
      return false;
    }
    summary.solve_seconds += seconds_since(t0);
    log.linear_iterations += stats.iterations;
    summary.linear_iterations += stats.iterations;
    ++summary.linear_solves;
    std::vector<double> du_all = du.gather_all();
    rigid.follow(du_all); // the rigid bodies' slaves move with their reference nodes
    double step = 1.0;
    // Backtracking on ‖R‖ at fixed multipliers: semi-smooth Newton steps can flip pairs
    // between stick and slip (or open and closed) back and forth; damping breaks the cycle.
    // Without contact, a plastic bulk: from the first step on, which carries the prescribed
    // increments and is the one that most often overshoots (points switching return branch);
    // on the 100k-DOF strip footing it removed all 4 cut-backs and 11 % of the iterations.
    const bool damp = copt.line_search && (has_contact ? !first_pass : !linear);
    if (damp) {
      t0 = std::chrono::steady_clock::now();
      // The merit is the free-DOF residual: constrained DOFs take their whole (prescribed)
      // step, so their rows are eliminated as in the iteration itself.
      Constraints fixed;
      for (const auto& kv : target)
        fixed.set(kv.first, 0.0);
      std::vector<double> trial(u.size());
      step = backtracking_step(norm, [&](double s) {
        for (std::size_t i = 0; i < u.size(); ++i)
          trial[i] = u[i] + (prescribed[i] ? 1.0 : s) * du_all[i];
        return residual_norm(trial, dtau, fixed);
      });
      summary.assembly_seconds += seconds_since(t0);
    }
    for (std::size_t i = 0; i < u.size(); ++i)
      u[i] += (prescribed[i] ? 1.0 : step) * du_all[i];
    first_pass = false;
  }
}

// Fallback for an increment the monolithic iteration cannot solve even at the smallest step:
// a debonding snap-back, where β = min(β_old, w/E) has no solution continuous with the last
// state (Newton cycles between states). Alternate a solve with β held fixed (a well-posed
// contact problem) and the update of β from the displacement. β only decreases along this
// sequence, which therefore converges, to the equilibrium after the jump; the monolithic
// iteration then confirms it with the true law. Leaves `u` at the last iterate.
bool StaticAnalysis::Impl::solve_increment_staggered(double lambda, double dtau,
                                                     IncrementLog& log) {
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
    const bool ok = solve_increment(lambda, dtau, sub);
    merge(sub);
    ++log.staggered;
    if (!ok) {
      unfreeze();
      log.failure = "staggered fallback, with beta held: " + log.failure;
      return false;
    }
    double change = 0;
    for (std::size_t k = 0; k < interfaces.size(); ++k) {
      std::vector<double> next = interfaces[k]->adhesion_at(u, dtau);
      for (std::size_t i = 0; i < next.size(); ++i)
        change = std::max(change, std::abs(next[i] - beta[k][i]));
      beta[k] = std::move(next);
    }
    if (change <= beta_tolerance) break;
  }
  unfreeze();
  IncrementLog final_check;
  const bool ok = solve_increment(lambda, dtau, final_check);
  merge(final_check);
  if (!ok) log.failure = "staggered fallback, final check with the true law: " + log.failure;
  return ok;
}

} // namespace bipot
