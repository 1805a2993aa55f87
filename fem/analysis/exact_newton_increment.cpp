// One load increment with `generalized_newton` (ExactNewtonIncrement): the bulk is condensed
// onto the interface DOFs I (SchurComplementSolver), the exact generalized Newton runs on the
// small dense system of I and the interface multipliers (InterfaceNewton), and one back
// substitution recovers the rest of the mesh.
//
// With a linear bulk, the full system of the increment, K du = R0 + f_c(u + du) (R0 the
// condensed bulk residual with the prescribed increments, f_c acting on I only), reduces
// exactly to S x = c + f_c(x) on I: the interior equations hold by construction. K is
// factorised once per constrained set, R0 assembled once per increment, and a Newton
// iteration costs O(|I|²) (GMRES on the factors of an earlier Newton matrix, ReusedLuSolver)
// or O(|I|³) when it refactorises, independent of the mesh interior. A nonlinear bulk repeats the
// condensation around each new bulk state (outer loop) until the assembled residual is met,
// each outer step backtracked on that whole residual.
#include "fem/analysis/detail/exact_newton_increment.hpp"

#include "fem/analysis/detail/convergence_test.hpp"
#include "fem/analysis/detail/interface_newton.hpp"
#include "fem/analysis/detail/line_search.hpp"
#include "fem/analysis/detail/path_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

namespace bipot {

using namespace analysis_detail;

namespace {
// A whole residual below this × the reference is round-off (1000 ε): the outer line search
// cannot judge a step by it.
constexpr double roundoff_merit = 1e3 * std::numeric_limits<double>::epsilon();

// max_i ‖F_λi‖ (kN): how far the multipliers are from the interface law at the interfaces'
// last evaluate().
double law_residual(const CondensedInterfaceSystem& sys, const std::vector<bool>& constrained) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(sys.size());
  sys.add(constrained, F, nullptr);
  return sys.multiplier_residual(F);
}
} // namespace

struct ExactNewtonIncrement::Increment {
  Increment(const IncrementRequest& request, const IncrementContext& ctx,
            const CondensedInterfaceSystem& sys)
      : lambda(request.lambda), dtau(request.dtau), path(request.path),
        iteration_limit(request.max_iterations > 0 ? request.max_iterations
                                                   : ctx.contact_solver.max_iterations),
        prescribed(ctx.prescribed()), constrained_I(sys.num_dofs()),
        test(ctx.contact_solver.tolerance),
        R1(request.path ? std::make_unique<DistributedVector>(ctx.dist) : nullptr) {
    for (const auto& kv : ctx.target)
      constrained_dofs.push_back(kv.first);
    for (Index k = 0; k < sys.num_dofs(); ++k)
      constrained_I[k] = ctx.target.count(sys.dofs()[k]) != 0;
  }
  double lambda, dtau;
  /// A path's Δλ over the outer iterations so far (a nonlinear bulk; 0 before the first).
  double dlambda = 0;
  PathStep* path;
  int iteration_limit; ///< of the Newton iterations on the interface
  std::vector<Index> constrained_dofs;
  std::vector<bool> prescribed;    ///< over all DOFs
  std::vector<bool> constrained_I; ///< over I
  ConvergenceTest test;
  Constraints constraints; ///< the prescribed increments of the current outer iteration
  /// A path's residual change per unit load factor (only with a path: a whole-mesh vector,
  /// 7.5 MB at 1M DOFs, alive while the bulk is factorised).
  std::unique_ptr<DistributedVector> R1;
};

void ExactNewtonIncrement::assemble_bulk_residual(Increment& inc, int outer, bool refactor) {
  const std::vector<double>& u = ctx_.u;
  SparseMatrix& K = ctx_.K;
  DistributedVector &R = ctx_.R, &F_step = ctx_.F_step;
  // R0 = F − f_int(u), the prescribed increments eliminated (first pass). A path's outer
  // iterations have moved the load factor by inc.dlambda.
  const double lambda = inc.lambda + inc.dlambda;
  inc.constraints.clear();
  for (const auto& [d, v] : ctx_.target)
    inc.constraints.set(d, outer == 0 ? ctx_.start.at(d) + lambda * (v - ctx_.start.at(d)) - u[d]
                                      : 0.0);
  // A linear bulk (rigid bodies aside: their slaves' rows are transformed) gets its residual
  // from products with K, assembled with K at each refactorisation.
  const bool by_product = ctx_.linear && ctx_.rigid.empty();
  // A path's prescribed values one load factor further on (R1 below).
  Constraints ahead;
  if (inc.path)
    for (const auto& [d, v] : ctx_.target)
      ahead.set(d, ctx_.start.at(d) + (lambda + 1.0) * (v - ctx_.start.at(d)) - u[d]);
  // Assembled by the materials (a nonlinear bulk, rigid bodies): a path's residual one load
  // factor further on comes from the same local systems (into inc.R1 until below), not from a
  // second assembly that evaluates every material point again.
  const bool ahead_in_pass = inc.path && !(by_product && (refactor || bulk_product_.ready()));
  R.set_zero();
  if (ahead_in_pass) inc.R1->set_zero();
  if (refactor) K.set_zero();
  if (refactor && by_product)
    bulk_product_.assemble(ctx_.solid, u, inc.constraints, K, R);
  else if (by_product && bulk_product_.ready())
    bulk_product_.residual(ctx_.solid, K, u, inc.constraints, R);
  else
    ctx_.solid.assemble(u, inc.constraints, refactor ? &K : nullptr, R, nullptr,
                        ahead_in_pass ? &ahead : nullptr, ahead_in_pass ? inc.R1.get() : nullptr);
  R.finish_assembly();
  if (ahead_in_pass) inc.R1->finish_assembly();
  if (refactor) K.finish_assembly();
  ctx_.add_step_loads(inc.constraints);
  if (!inc.path) return;
  // Path-following: R is affine in the load factor (prescribed values and loads are), so
  // R(λ + Δλ) = R + Δλ R1 with R1 the difference of the residuals at λ + 1 and λ. With a
  // nonlinear bulk it is so to first order: assemble() lifts the prescribed values through
  // the tangent at u (Constraints::condense), so R1 is ∂R/∂λ at u, the border of Newton's
  // linearisation.
  const DistributedVector R_lambda = R;
  const DistributedVector F_lambda = F_step;
  F_step.axpy(1.0, ctx_.F_cur);
  F_step.axpy(-1.0, ctx_.F_prev);
  if (ahead_in_pass) {
    R.copy(*inc.R1);
  } else {
    R.set_zero();
    bulk_product_.residual(ctx_.solid, K, u, ahead, R);
    R.finish_assembly();
  }
  ctx_.add_step_loads(ahead);
  inc.R1->copy(R);
  inc.R1->axpy(-1.0, R_lambda);
  R.copy(R_lambda);
  F_step.copy(F_lambda);
}

double ExactNewtonIncrement::whole_residual(const Increment& inc, double dtau) {
  for (const auto& ia : ctx_.interfaces)
    ia->evaluate(ctx_.u, dtau);
  DistributedVector& whole = ctx_.du; // scratch until the back substitution
  whole.copy(ctx_.R);
  for (const auto& ia : ctx_.interfaces)
    ia->add_to_system(inc.constraints, nullptr, whole);
  whole.finish_assembly();
  return ctx_.free_norm(whole, inc.constraints);
}

bool ExactNewtonIncrement::condense(Increment& inc, IncrementLog& log) {
  const auto t0 = std::chrono::steady_clock::now();
  // S changes: the old Newton matrix is no preconditioner. Its factors go before MUMPS
  // factorises, the run's peak out of core (at 307k DOFs: 492 -> 474 MB).
  newton_matrix_.reset();
  if (!ctx_.linear) path_matrix_.reset();
  try {
    // A linear (elastic) bulk has a symmetric K: LDLᵀ, half the factors. The whole-mesh
    // residual check after each increment would catch a K that is not.
    schur_.factorize(ctx_.K, sys_.dofs(), ctx_.linear);
  } catch (const SolverError& e) {
    log.failure = e.what();
    return false;
  }
  ctx_.summary.setup_seconds += seconds_since(t0);
  ++ctx_.summary.matrix_setups;
  schur_ready_ = true;
  schur_constrained_ = inc.constrained_dofs;
  return true;
}

std::vector<double> ExactNewtonIncrement::expand(Increment& inc, const Eigen::VectorXd& z) {
  const Index nI = sys_.num_dofs(), n = sys_.size();
  const auto t0 = std::chrono::steady_clock::now();
  if (inc.path) {
    // At the load factor found: the residual, the loads and the right-hand side that
    // expand() back-substitutes.
    inc.path->dlambda = z(n);
    inc.path->x = z.head(nI);
    ctx_.R.axpy(z(n), *inc.R1);
    ctx_.F_step.axpy(z(n), ctx_.F_cur);
    ctx_.F_step.axpy(-z(n), ctx_.F_prev);
    schur_.reduce(ctx_.R);
  }
  schur_.expand(z.head(nI), ctx_.du);
  ctx_.summary.solve_seconds += seconds_since(t0);
  std::vector<double> du_all = ctx_.du.gather_all();
  ctx_.rigid.follow(du_all); // the rigid bodies' slaves move with their reference nodes
  return du_all;
}

bool ExactNewtonIncrement::check_whole_mesh(double floor, IncrementLog& log) {
  const auto t0 = std::chrono::steady_clock::now();
  DistributedVector Kdu(ctx_.dist), full(ctx_.dist);
  ctx_.K.multiply(ctx_.du, Kdu);
  full.copy(ctx_.R);
  full.axpy(-1.0, Kdu);
  const Constraints fixed = ctx_.held();
  for (const auto& ia : ctx_.interfaces)
    ia->add_to_system(fixed, nullptr, full);
  full.finish_assembly();
  const double check = full.norm2();
  ctx_.summary.assembly_seconds += seconds_since(t0);
  if (check > 100.0 * floor) {
    log.failure = "the condensed solution leaves a residual of " + std::to_string(check) +
                  " on the whole mesh (tolerance " + std::to_string(floor) + ")";
    return false;
  }
  return true;
}

bool ExactNewtonIncrement::solve(const IncrementRequest& request, IncrementLog& log) {
  const NonlinearSolverOptions& copt = ctx_.contact_solver;
  const bool linear = ctx_.linear;
  PathStep* const path = request.path;
  std::vector<double>& u = ctx_.u;
  const Index nI = sys_.num_dofs(), n = sys_.size();
  ctx_.begin_increment(request.lambda);
  Increment inc(request, ctx_, sys_);
  ConvergenceTest& test = inc.test;
  // A path step on a nonlinear bulk: its outer iterations move x and λ on from where the
  // earlier ones left them; the constraint counts the whole increment (PathStep::x_offset).
  const bool path_outer = path && !linear;
  Eigen::VectorXd x_start;
  if (path) path->x_offset.resize(0);
  if (path_outer) {
    x_start = on_interface_dofs(sys_, u);
    path->x_offset.setZero(nI);
  }
  for (int outer = 0;; ++outer) {
    auto t0 = std::chrono::steady_clock::now();
    const bool refactor = !schur_ready_ || !linear || inc.constrained_dofs != schur_constrained_;
    assemble_bulk_residual(inc, outer, refactor);
    const double full_norm = whole_residual(inc, inc.dtau);
    ctx_.summary.assembly_seconds += seconds_since(t0);
    if (!test.has_reference()) {
      test.set_reference(full_norm, ctx_.F_step.norm2(), ctx_.interface_force_scale(),
                         ctx_.reaction_scale);
      if (test.reference() == 0.0) return true; // nothing acts on the bodies
    }
    test.set_roundoff(ctx_.interface_roundoff());
    const double floor = test.force_floor();
    // A nonlinear bulk: the history is that of the whole residual at each bulk state (Newton
    // on the bulk, quadratic with the consistent tangent); the inner iterations solve a
    // linearised problem exactly and their residuals say nothing about the increment.
    if (!linear) log.history.push_back(test.relative(full_norm));
    // The interface law at u: a damped outer step (below) leaves the multipliers between two
    // inner solutions, off the law, so the outer test and merit need it besides equilibrium.
    const double law = law_residual(sys_, inc.constrained_I);
    if (outer > 0) {
      const bool path_met =
          !path_outer || std::abs(path->constraint(sys_, Eigen::VectorXd::Zero(n + 1), nullptr)) <=
                             path->constraint_tolerance(copt.tolerance);
      if (test.forces_met(full_norm) && test.law_met(law) && path_met) return true;
      if (outer >= copt.max_iterations) {
        log.failure = "the bulk (outer) iterations did not converge in " + std::to_string(outer) +
                      " condensations";
        return false;
      }
    }
    if (refactor && !condense(inc, log)) return false;
    t0 = std::chrono::steady_clock::now();
    const Eigen::VectorXd c1 = path ? schur_.reduce(*inc.R1) : Eigen::VectorXd();
    const Eigen::VectorXd c = schur_.reduce(ctx_.R);
    ctx_.summary.solve_seconds += seconds_since(t0);

    // Newton on z = (x, λ_c[, Δλ]) from x = 0 and the multipliers' predictor, or a path's
    // predictor along its previous step.
    InterfaceNewton newton(ctx_, sys_, inc.constrained_I, schur_.schur(), schur_.symmetric(), c, c1,
                           path, inc.dtau);
    const Eigen::VectorXd lambda0 = sys_.multipliers();
    Eigen::VectorXd z(path ? n + 1 : n);
    z.head(nI).setZero();
    z.segment(nI, n - nI) = lambda0;
    if (path && outer == 0) {
      z.head(nI) = path->predictor_scale * path->x_prev;
      z(n) = path->predictor_scale * path->dlambda_prev;
    } else if (path) {
      z(n) = 0.0; // later outer iterations correct from the current state
    }
    ReusedLuSolver& newton_solver = path ? path_matrix_ : newton_matrix_;
    if (!newton.solve(z, test, inc.iteration_limit, newton_solver, log)) return false;

    // The rest of the mesh: one back substitution; then u and the interface state at z.
    const std::vector<double> du_all = expand(inc, z);
    const Eigen::VectorXd lambda1 = z.segment(nI, n - nI);
    double step = 1.0;
    if (!linear && copt.line_search) {
      // Backtracking on the whole residual. With a plastic bulk the outer step is Newton on a
      // piecewise smooth residual: where points sit at a kink of their return (plane/edge,
      // edge/apex, elastic/plastic) and the apex's zero tangent makes K nearly singular
      // nearby, the full step can overshoot and the undamped iteration cycles (the
      // Mohr-Coulomb pile did, period 3). The prescribed DOFs always take their whole
      // increment; the multipliers move along with the displacements. On a path the
      // prescribed DOFs and the loads follow the load factor, which the step scales.
      // Not where the merit at the start is within round-off of zero: no trial can show a
      // decrease there. A path's first outer step starts in equilibrium (to round-off on an
      // elastic bulk) and is driven by the constraint, which the merit leaves out;
      // backtracking on that noise cut the column's arc-length steps to 1/128 and cost one of
      // them 7 Newton iterations instead of 0 (path_following_test, TracedSnapBack; which
      // steps it hit was round-off's choice: none on the machine the test was written on).
      const double merit0 = std::hypot(full_norm, law);
      if (merit0 > roundoff_merit * test.reference()) {
        t0 = std::chrono::steady_clock::now();
        const Constraints fixed = ctx_.held();
        std::vector<double> trial(u.size());
        step = backtracking_step(merit0, [&](double s) {
          for (std::size_t i = 0; i < u.size(); ++i)
            trial[i] = u[i] + (inc.prescribed[i] && !path ? 1.0 : s) * du_all[i];
          if (path) ctx_.set_step_loads(inc.lambda + inc.dlambda + s * z(n));
          sys_.set_multipliers(lambda0 + s * (lambda1 - lambda0));
          const double force = ctx_.residual_norm(trial, inc.dtau, fixed);
          return std::hypot(force, law_residual(sys_, inc.constrained_I));
        });
        ctx_.summary.assembly_seconds += seconds_since(t0);
      }
    }
    for (std::size_t i = 0; i < u.size(); ++i)
      u[i] += (inc.prescribed[i] && !path ? 1.0 : step) * du_all[i];
    sys_.set_multipliers(lambda0 + step * (lambda1 - lambda0));
    for (const auto& ia : ctx_.interfaces)
      ia->evaluate(u, inc.dtau);
    if (path_outer) {
      // The whole increment so far: what the path reports, and the offset of the next outer
      // iteration's constraint.
      inc.dlambda += step * z(n);
      ctx_.set_step_loads(inc.lambda + inc.dlambda);
      path->x_offset = on_interface_dofs(sys_, u) - x_start;
      path->x = path->x_offset;
      path->dlambda = inc.dlambda;
    }
    if (!linear) continue; // re-assemble the bulk at the new state and test it
    // Linear bulk: the condensation is exact; check it (a matrix-vector product) rather than
    // trust it.
    return check_whole_mesh(floor, log);
  }
}

} // namespace bipot
