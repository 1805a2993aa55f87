// One load increment with `semismooth_newton` or `bipotential_uzawa`
// (AugmentedLagrangianIncrement): Newton on the whole matrix with the contact solvers'
// multiplier updates, and the line search.
#include "fem/analysis/detail/augmented_lagrangian_increment.hpp"

#include "fem/analysis/detail/convergence_test.hpp"
#include "fem/analysis/detail/line_search.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace bipot {

using namespace analysis_detail;

bool AugmentedLagrangianIncrement::assemble(const Constraints& constraints, double dtau,
                                            bool first_pass) {
  const auto t0 = std::chrono::steady_clock::now();
  bool tangent_changed = false;
  for (const auto& ia : ctx_.interfaces) {
    ia->evaluate(ctx_.u, dtau);
    tangent_changed = tangent_changed || ia->tangent_changed();
  }
  // Prescribed increments are eliminated with the matrix's own diagonal: rebuild then.
  const bool rebuild = !ctx_.matrix_ready || !ctx_.linear || tangent_changed ||
                       (ctx_.has_contact && first_pass && !ctx_.target.empty());
  SparseMatrix* K = rebuild ? &ctx_.K : nullptr;
  ctx_.R.set_zero();
  if (K) K->set_zero();
  ctx_.solid.assemble(ctx_.u, constraints, K, ctx_.R);
  for (const auto& ia : ctx_.interfaces)
    ia->add_to_system(constraints, K, ctx_.R);
  ctx_.R.finish_assembly();
  if (K) K->finish_assembly();
  ctx_.add_step_loads(constraints);
  ctx_.summary.assembly_seconds += seconds_since(t0);
  return rebuild;
}

bool AugmentedLagrangianIncrement::update_multipliers(IncrementLog& log, bool matrix_rebuilt) {
  if (log.uzawa_updates >= ctx_.contact_solver.max_outer_iterations) {
    log.failure =
        "the Uzawa multipliers did not settle in " + std::to_string(log.uzawa_updates) + " updates";
    return false;
  }
  for (const auto& ia : ctx_.interfaces)
    ia->update_multipliers();
  ++log.uzawa_updates;
  // K was rebuilt but not factorised: the solver still holds the previous matrix, so it must
  // be set up again even if the next tangent equals the one last factorised.
  if (matrix_rebuilt) ctx_.matrix_ready = false;
  return true;
}

bool AugmentedLagrangianIncrement::newton_step(IncrementLog& log, bool matrix_rebuilt) {
  RunSummary& summary = ctx_.summary;
  if (matrix_rebuilt) {
    const auto t0 = std::chrono::steady_clock::now();
    // A failed factorisation (the direct solvers broadcast it: every rank throws) is a
    // failed increment, cut back like the others: a plastic tangent can be singular where
    // points sit at a yield surface's apex, which a smaller step may avoid.
    try {
      ctx_.solver.setup(ctx_.K);
    } catch (const SolverError& e) {
      log.failure = e.what();
      return false;
    }
    summary.setup_seconds += seconds_since(t0);
    ctx_.matrix_ready = true;
    for (const auto& ia : ctx_.interfaces)
      ia->mark_tangent_assembled();
    ++summary.matrix_setups;
  }
  ctx_.du.set_zero();
  const auto t0 = std::chrono::steady_clock::now();
  LinearSolveStats stats;
  try {
    stats = ctx_.solver.solve(ctx_.R, ctx_.du);
  } catch (const SolverError& e) {
    log.failure = e.what();
    return false;
  }
  summary.solve_seconds += seconds_since(t0);
  log.linear_iterations += stats.iterations;
  summary.linear_iterations += stats.iterations;
  ++summary.linear_solves;
  return true;
}

bool AugmentedLagrangianIncrement::move(const std::vector<bool>& prescribed, double norm,
                                        double dtau, bool damp, bool& rebuilt_ahead) {
  std::vector<double>& u = ctx_.u;
  std::vector<double> du_all = ctx_.du.gather_all();
  ctx_.rigid.follow(du_all); // the rigid bodies' slaves move with their reference nodes
  double step = 1.0;
  if (damp) {
    // The merit is the free-DOF residual: constrained DOFs take their whole (prescribed)
    // step, so their rows are eliminated as in the iteration itself.
    const Constraints fixed = ctx_.held();
    double at_full = -1.0;
    if (!ctx_.linear) {
      // A nonlinear bulk: the full step is tried by assembling the next iteration's system
      // there (K with R): most full steps are taken, and that iteration then starts from it
      // instead of running every material point's return again at the same state (the
      // 100k-DOF footing: assembly 38.4 -> 31.9 s, the same 140 iterations). A linear bulk
      // with contact rebuilds K only when an interface's tangent changed, which a rejected
      // trial would leave in K: not there. (Tried on generalized_newton's outer loop as well,
      // with K and a path's R1: the Mohr-Coulomb pile's assembly went from 39 to 44 s, so it
      // is not done there.)
      const std::vector<double> u_now = u;
      for (std::size_t i = 0; i < u.size(); ++i)
        u[i] += du_all[i];
      rebuilt_ahead = assemble(fixed, dtau, false);
      at_full = ctx_.R.norm2();
      if (at_full < (1.0 - 1e-4) * norm) return true; // backtracking_step's test at the full step
      u = u_now;
    }
    const auto t0 = std::chrono::steady_clock::now();
    std::vector<double> trial(u.size());
    step = backtracking_step(
        norm,
        [&](double s) {
          for (std::size_t i = 0; i < u.size(); ++i)
            trial[i] = u[i] + (prescribed[i] ? 1.0 : s) * du_all[i];
          return ctx_.residual_norm(trial, dtau, fixed);
        },
        at_full); // if no trial did better, the full step, assembled again next
    ctx_.summary.assembly_seconds += seconds_since(t0);
  }
  for (std::size_t i = 0; i < u.size(); ++i)
    u[i] += (prescribed[i] ? 1.0 : step) * du_all[i];
  return false;
}

// Newton (and, for bipotential_uzawa, Uzawa) iterations of one increment ending at stage
// load factor `lambda`. Leaves `u` at the last iterate; the caller restores it on failure.
bool AugmentedLagrangianIncrement::solve(const IncrementRequest& request, IncrementLog& log) {
  if (request.path) {
    log.failure = "path-following needs contact_solver.type: generalized_newton";
    return false;
  }
  const double lambda = request.lambda, dtau = request.dtau;
  const NonlinearSolverOptions& copt = ctx_.contact_solver;
  const bool has_contact = ctx_.has_contact;
  const int max_iterations = has_contact ? copt.max_iterations : ctx_.options.max_iterations;
  ctx_.begin_increment(lambda);

  const std::vector<bool> prescribed = ctx_.prescribed();
  Constraints constraints;
  ConvergenceTest test(has_contact ? copt.tolerance : ctx_.options.residual_tolerance);
  double baseline = -1.0;
  bool first_pass = true;
  // The last line search assembled the system at u (its full step, taken), K rebuilt or not.
  bool assembled_ahead = false, rebuilt_ahead = false;
  for (int inner = 0;; ++log.iterations, ++inner) {
    constraints.clear();
    for (const auto& [d, v] : ctx_.target) {
      const double s = ctx_.start.at(d);
      constraints.set(d, first_pass ? s + lambda * (v - s) - ctx_.u[d] : 0.0);
    }
    const bool rebuilt = assembled_ahead ? rebuilt_ahead : assemble(constraints, dtau, first_pass);
    assembled_ahead = false;
    const double norm = ctx_.free_norm(ctx_.R, constraints);
    double change = 0;
    for (const auto& ia : ctx_.interfaces)
      change = std::max(change, ia->multiplier_change());
    const double force_scale = ctx_.interface_force_scale();
    if (!test.has_reference()) {
      test.set_reference(norm, ctx_.F_step.norm2(), force_scale, ctx_.reaction_scale);
      if (test.reference() == 0.0 && change == 0.0) return true; // nothing acts on the body
    }
    test.raise_reference(force_scale);
    test.set_roundoff(ctx_.interface_roundoff());
    log.history.push_back(test.relative(norm));
    log.contact = test.relative(change);

    const bool force_ok = !first_pass && test.forces_met(norm);
    const bool contact_ok = test.law_met(change);
    if (force_ok && contact_ok) return true;
    if (baseline < 0) baseline = norm;
    // When to move the multipliers (the corrector r̂ ← Proj(τ)): bipotential_uzawa once
    // equilibrium holds for the current ones; semismooth_newton as soon as the residual of
    // the current inner problem has dropped tenfold (inexact augmented Lagrangian), so
    // equilibrium and the contact law converge together.
    const bool inner_done = force_ok || (!copt.uzawa() && !first_pass && norm <= 0.1 * baseline);
    if (has_contact && inner_done && !contact_ok) {
      if (!update_multipliers(log, rebuilt)) return false;
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
    if (!newton_step(log, rebuilt)) return false;
    // Backtracking on ‖R‖ at fixed multipliers: semi-smooth Newton steps can flip pairs
    // between stick and slip (or open and closed) back and forth; damping breaks the cycle.
    // Without contact, a plastic bulk: from the first step on, which carries the prescribed
    // increments and is the one that most often overshoots (points switching return branch);
    // on the 100k-DOF strip footing it removed all 4 cut-backs and 11 % of the iterations.
    assembled_ahead =
        move(prescribed, norm, dtau, copt.line_search && (has_contact ? !first_pass : !ctx_.linear),
             rebuilt_ahead);
    first_pass = false;
  }
}

} // namespace bipot
