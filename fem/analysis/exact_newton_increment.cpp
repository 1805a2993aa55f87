// One load increment with `generalized_newton` (StaticAnalysis::Impl): the bulk is condensed
// onto the interface DOFs I (SchurComplementSolver), the exact generalized Newton runs on the
// small dense system of I and the interface multipliers (CondensedInterfaceSystem),
// and one back substitution recovers the rest of the mesh.
//
// With a linear bulk, the full system of the increment, K du = R0 + f_c(u + du) (R0 the
// condensed bulk residual with the prescribed increments, f_c acting on I only), reduces
// exactly to S x = c + f_c(x) on I: the interior equations hold by construction. K is
// factorised once per constrained set, R0 assembled once per increment, and a Newton
// iteration costs O(|I|²) (GMRES on the factors of an earlier Newton matrix, ReusedLuSolver)
// or O(|I|³) when it refactorises, independent of the mesh interior. A nonlinear bulk repeats the
// condensation around each new bulk state (outer loop) until the assembled residual is met,
// each outer step backtracked on that whole residual.
#include "fem/analysis/detail/static_analysis_impl.hpp"

namespace bipot {

using namespace analysis_detail;

namespace {
// max_i ‖F_λi‖ (kN): how far the multipliers are from the interface law at the interfaces'
// last evaluate().
double law_residual(const CondensedInterfaceSystem& sys, const std::vector<bool>& constrained) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(sys.size());
  sys.add(constrained, F, nullptr);
  return sys.multiplier_residual(F);
}
} // namespace

bool StaticAnalysis::Impl::solve_increment_exact(double lambda, double dtau, IncrementLog& log,
                                                 PathStep* path, int max_iterations) {
  const NonlinearSolverOptions& copt = model.contact_solver;
  const int iteration_limit = max_iterations > 0 ? max_iterations : copt.max_iterations;
  const CondensedInterfaceSystem& sys = *newton_system;
  const Index nI = sys.num_dofs(), n = sys.size();
  F_step.copy(F_prev);
  F_step.scale(1.0 - lambda);
  F_step.axpy(lambda, F_cur);
  for (std::size_t k = 0; k < interfaces.size(); ++k) {
    interfaces[k]->set_gap_shift(gap_start[k] + lambda * (gap_target[k] - gap_start[k]));
    interfaces[k]->begin_increment(extrapolation);
  }
  move_obstacles(lambda);
  std::vector<Index> constrained_dofs;
  for (const auto& kv : target)
    constrained_dofs.push_back(kv.first);
  std::vector<bool> prescribed(u.size());
  for (const auto& kv : target)
    prescribed[kv.first] = true;
  std::vector<bool> constrained_I(nI);
  for (Index k = 0; k < nI; ++k)
    constrained_I[k] = target.count(sys.dofs()[k]) != 0;

  double reference = -1.0;
  Constraints constraints;
  for (int outer = 0;; ++outer) {
    // Bulk residual R0 = F − f_int(u), the prescribed increments eliminated (first pass).
    auto t0 = std::chrono::steady_clock::now();
    constraints.clear();
    for (const auto& [d, v] : target)
      constraints.set(d, outer == 0 ? start[d] + lambda * (v - start[d]) - u[d] : 0.0);
    const bool refactor = !schur_ready || !linear || constrained_dofs != schur_constrained;
    // A linear bulk (rigid bodies aside: their slaves' rows are transformed) gets its residual
    // from products with K, assembled with K at each refactorisation.
    const bool by_product = linear && rigid.empty();
    R.set_zero();
    if (refactor) K->set_zero();
    if (refactor && by_product)
      bulk_product.assemble(solid, u, constraints, *K, R);
    else if (by_product && bulk_product.ready())
      bulk_product.residual(solid, *K, u, constraints, R);
    else
      solid.assemble(u, constraints, refactor ? K.get() : nullptr, R);
    R.finish_assembly();
    if (refactor) K->finish_assembly();
    add_step_loads(constraints);
    // Path-following: R is affine in the load factor (prescribed values and loads are), so
    // R(λ + Δλ) = R + Δλ R1 with R1 the difference of the residuals at λ + 1 and λ.
    DistributedVector R1(dist);
    if (path) {
      const DistributedVector R_lambda = R;
      const DistributedVector F_lambda = F_step;
      Constraints ahead;
      for (const auto& [d, v] : target)
        ahead.set(d, start[d] + (lambda + 1.0) * (v - start[d]) - u[d]);
      F_step.axpy(1.0, F_cur);
      F_step.axpy(-1.0, F_prev);
      R.set_zero();
      if (by_product && bulk_product.ready())
        bulk_product.residual(solid, *K, u, ahead, R);
      else
        solid.assemble(u, ahead, nullptr, R);
      R.finish_assembly();
      add_step_loads(ahead);
      R1.copy(R);
      R1.axpy(-1.0, R_lambda);
      R.copy(R_lambda);
      F_step.copy(F_lambda);
    }
    // The whole residual with the interface forces at u: the reference of the increment and,
    // for a nonlinear bulk, the test of the outer loop.
    for (const auto& ia : interfaces)
      ia->evaluate(u, dtau);
    du.copy(R);
    for (const auto& ia : interfaces)
      ia->add_to_system(constraints, nullptr, du);
    du.finish_assembly();
    const double full_norm = free_norm(du, constraints);
    double force_scale = 0, roundoff = 0;
    for (const auto& ia : interfaces) {
      force_scale = std::max(force_scale, ia->force_scale());
      roundoff = std::max(roundoff, ia->roundoff_force());
    }
    summary.assembly_seconds += seconds_since(t0);
    if (reference < 0) {
      reference = std::max({full_norm, F_step.norm2(), force_scale, reaction_scale});
      if (reference == 0.0) return true; // nothing acts on the bodies
    }
    const double floor = std::max(copt.tolerance * reference, roundoff_factor * roundoff);
    // A nonlinear bulk: the history is that of the whole residual at each bulk state (Newton
    // on the bulk, quadratic with the consistent tangent); the inner iterations solve a
    // linearised problem exactly and their residuals say nothing about the increment.
    if (!linear) log.history.push_back(full_norm / reference);
    // The interface law at u: a damped outer step (below) leaves the multipliers between two
    // inner solutions, off the law, so the outer test and merit need it besides equilibrium.
    const double law = law_residual(sys, constrained_I);
    if (outer > 0) {
      if (full_norm <= floor && law <= copt.tolerance * reference) return true;
      if (outer >= copt.max_iterations) {
        log.failure = "the bulk (outer) iterations did not converge in " + std::to_string(outer) +
                      " condensations";
        return false;
      }
    }
    if (refactor) {
      t0 = std::chrono::steady_clock::now();
      try {
        // A linear (elastic) bulk has a symmetric K: LDLᵀ, half the factors. The whole-mesh
        // residual check after each increment would catch a K that is not.
        schur.factorize(*K, sys.dofs(), linear);
      } catch (const SolverError& e) {
        log.failure = e.what();
        return false;
      }
      summary.setup_seconds += seconds_since(t0);
      ++summary.matrix_setups;
      schur_ready = true;
      newton_matrix.reset(); // S changed: the old Newton matrix is no preconditioner
      schur_constrained = constrained_dofs;
    }
    t0 = std::chrono::steady_clock::now();
    const Eigen::VectorXd c1 = path ? schur.reduce(R1) : Eigen::VectorXd();
    const Eigen::VectorXd c = schur.reduce(R);
    summary.solve_seconds += seconds_since(t0);
    const Eigen::MatrixXd& S = schur.schur();

    // Newton on z = (x, λ_c[, Δλ]): x the increments of I's DOFs from u, λ_c = A r the
    // multipliers, Δλ the load factor's increment of a path-following step (one more row:
    // its constraint).
    const Index nz = path ? n + 1 : n;
    std::vector<double> trial = u;
    Eigen::VectorXd z(nz), F(nz), dz(nz), F_try(nz), grad;
    // J = [−S 0; 0 0] + the sparse interface (and border) terms: S is not copied per iteration.
    CondensedNewtonMatrix J(S, nz, schur.symmetric());
    std::vector<Eigen::Triplet<double>> entries;
    const Eigen::VectorXd lambda0 = sys.multipliers();
    z.head(nI).setZero();
    z.segment(nI, n - nI) = lambda0;
    if (path) {
      z.head(nI) = path->predictor_scale * path->x_prev;
      z(n) = path->predictor_scale * path->dlambda_prev;
    }
    // The merit of the line search measures each residual in units of its own tolerance: the
    // forces and the law to copt.tolerance × reference, the constraint to its looser
    // constraint_tolerance(). Weighted as a force relative to the reference instead (before),
    // the constraint, whose linearisation is poor where pairs cross β's kink, dominated the
    // merit and the line search cut steps that reduced the forces: on rccm_traced.yaml with
    // 100, 120 or 160 increments single traced steps took 14 to 20 iterations (5 now).
    const double g_weight =
        path ? copt.tolerance * reference / path->constraint_tolerance(copt.tolerance) : 0.0;
    auto residual = [&](const Eigen::VectorXd& at, Eigen::VectorXd& out,
                        CondensedNewtonMatrix* jac) {
      for (Index k = 0; k < nI; ++k)
        trial[sys.dofs()[k]] = u[sys.dofs()[k]] + at(k);
      sys.set_multipliers(at.segment(nI, n - nI));
      for (const auto& ia : interfaces)
        ia->evaluate(trial, dtau);
      out.head(nI) = c - J.dense_product(at.head(nI)); // shared by the ranks
      out.tail(nz - nI).setZero();
      entries.clear();
      // add() touches rows and columns below n only: a bordered J and F pass as they are.
      if (jac)
        sys.add(constrained_I, out, entries);
      else
        sys.add(constrained_I, out, nullptr);
      if (path) {
        out.head(nI) += at(n) * c1;
        out(n) = path->constraint(sys, at, jac ? &grad : nullptr);
        if (jac) {
          for (Index i = 0; i < nI; ++i)
            entries.emplace_back(i, n, c1(i));
          for (Index j = 0; j < nz; ++j)
            if (grad(j) != 0.0) entries.emplace_back(n, j, grad(j));
        }
      }
      if (jac) jac->set_sparse_part(entries);
    };
    auto merit = [&](const Eigen::VectorXd& r) {
      return path ? std::hypot(r.head(n).norm(), g_weight * r(n)) : r.norm();
    };
    ReusedLuSolver& newton_solver = path ? path_matrix : newton_matrix;
    // Single-precision factors: GMRES stays in double and meets the same tolerances, with
    // half the bytes streamed per preconditioner application (docs/theory.md). A nonlinear
    // bulk changes S, hence the factors, at every outer iteration: few solves per factors,
    // and double precision keeps its inner iteration counts (and cut-backs) as they were.
    newton_solver.set_single_precision_factors(linear);
    for (int it = 0;; ++it, ++log.iterations) {
      t0 = std::chrono::steady_clock::now();
      residual(z, F, &J);
      const double force = F.head(nI).norm(), change = sys.multiplier_residual(F);
      const bool constraint_met =
          !path || std::abs(F(n)) <= path->constraint_tolerance(copt.tolerance);
      summary.assembly_seconds += seconds_since(t0);
      if (linear) log.history.push_back(force / reference);
      log.contact = change / reference;
      if (force <= floor && change <= copt.tolerance * reference && constraint_met) break;
      if (!std::isfinite(force) || !std::isfinite(change)) {
        log.failure = "the interface residual is not finite";
        return false;
      }
      if (it >= iteration_limit) {
        log.failure = "no convergence in " + std::to_string(it) + " generalized Newton iterations";
        return false;
      }
      t0 = std::chrono::steady_clock::now();
      const int factorizations = newton_solver.factorizations();
      // Inexact Newton (Dembo, Eisenstat & Steihaug 1982): the step need only meet
      // ‖J dz + F‖ ≤ η ‖F‖. With η = min(1e-3, ‖F‖ / reference) the step's own error is at most
      // the square of the relative residual, so the convergence stays quadratic, while far
      // from the solution the GMRES on earlier factors stops much sooner (2.6× fewer GMRES
      // iterations on the pile at 77k DOFs). Path-following steps keep the tight solve (their
      // constraint row has a scale of its own).
      const double eta = path ? 0.0 : std::min(1e-3, F.norm() / reference);
      dz = newton_solver.solve(J, -F, eta);
      summary.solve_seconds += seconds_since(t0);
      ++summary.linear_solves;
      summary.matrix_setups += newton_solver.factorizations() - factorizations;
      summary.linear_iterations += newton_solver.last_iterations();
      log.linear_iterations += newton_solver.last_iterations();
      if (!dz.allFinite()) {
        log.failure = "the generalized Jacobian is singular";
        return false;
      }
      double step = 1.0;
      if (copt.line_search) {
        // Backtracking on ‖F‖ (forces and multiplier residuals are both in kN). A kink of the
        // projection can make the full step overshoot; the residual norm is cheap here.
        t0 = std::chrono::steady_clock::now();
        step = backtracking_step(merit(F), [&](double s) {
          residual(z + s * dz, F_try, nullptr);
          return merit(F_try);
        });
        summary.assembly_seconds += seconds_since(t0);
      }
      z += step * dz;
    }
    // The rest of the mesh: one back substitution; then u and the interface state at z.
    t0 = std::chrono::steady_clock::now();
    if (path) {
      // At the load factor found: the residual, the loads and the right-hand side that
      // expand() back-substitutes.
      path->dlambda = z(n);
      path->x = z.head(nI);
      R.axpy(z(n), R1);
      F_step.axpy(z(n), F_cur);
      F_step.axpy(-z(n), F_prev);
      schur.reduce(R);
    }
    schur.expand(z.head(nI), du);
    summary.solve_seconds += seconds_since(t0);
    std::vector<double> du_all = du.gather_all();
    rigid.follow(du_all); // the rigid bodies' slaves move with their reference nodes
    const Eigen::VectorXd lambda1 = z.segment(nI, n - nI);
    double step = 1.0;
    if (!linear && copt.line_search) {
      // Backtracking on the whole residual. With a plastic bulk the outer step is Newton on a
      // piecewise smooth residual: where points sit at a kink of their return (plane/edge,
      // edge/apex, elastic/plastic) and the apex's zero tangent makes K nearly singular
      // nearby, the full step can overshoot and the undamped iteration cycles (the
      // Mohr-Coulomb pile did, period 3). The prescribed DOFs always take their whole
      // increment; the multipliers move along with the displacements.
      t0 = std::chrono::steady_clock::now();
      Constraints fixed;
      for (const auto& kv : target)
        fixed.set(kv.first, 0.0);
      std::vector<double> trial(u.size());
      step = backtracking_step(std::hypot(full_norm, law), [&](double s) {
        for (std::size_t i = 0; i < u.size(); ++i)
          trial[i] = u[i] + (prescribed[i] ? 1.0 : s) * du_all[i];
        sys.set_multipliers(lambda0 + s * (lambda1 - lambda0));
        const double force = residual_norm(trial, dtau, fixed);
        return std::hypot(force, law_residual(sys, constrained_I));
      });
      summary.assembly_seconds += seconds_since(t0);
    }
    for (std::size_t i = 0; i < u.size(); ++i)
      u[i] += (prescribed[i] ? 1.0 : step) * du_all[i];
    sys.set_multipliers(lambda0 + step * (lambda1 - lambda0));
    for (const auto& ia : interfaces)
      ia->evaluate(u, dtau);
    if (!linear && path) {
      log.failure = "path-following needs a linear bulk (a bulk material is nonlinear)";
      return false;
    }
    if (!linear) continue; // re-assemble the bulk at the new state and test it
    // Linear bulk: the condensation is exact, so the whole residual R0 − K du + f_c(u) is the
    // interface residual up to round-off. Check it (a matrix-vector product) rather than trust it.
    t0 = std::chrono::steady_clock::now();
    DistributedVector Kdu(dist), full(dist);
    K->multiply(du, Kdu);
    full.copy(R);
    full.axpy(-1.0, Kdu);
    Constraints fixed;
    for (const auto& kv : target)
      fixed.set(kv.first, 0.0);
    for (const auto& ia : interfaces)
      ia->add_to_system(fixed, nullptr, full);
    full.finish_assembly();
    const double check = full.norm2();
    summary.assembly_seconds += seconds_since(t0);
    if (check > 100.0 * floor) {
      log.failure = "the condensed solution leaves a residual of " + std::to_string(check) +
                    " on the whole mesh (tolerance " + std::to_string(floor) + ")";
      return false;
    }
    return true;
  }
}

} // namespace bipot
