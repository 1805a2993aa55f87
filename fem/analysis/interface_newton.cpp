// The generalized Newton iteration on the condensed interface system (InterfaceNewton).
#include "fem/analysis/detail/interface_newton.hpp"

#include "fem/analysis/detail/line_search.hpp"
#include "fem/analysis/detail/path_step.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace bipot {

using namespace analysis_detail;

InterfaceNewton::InterfaceNewton(IncrementContext& context, const CondensedInterfaceSystem& system,
                                 const std::vector<bool>& constrained_I, const Eigen::MatrixXd& S,
                                 bool symmetric_S, const Eigen::VectorXd& c,
                                 const Eigen::VectorXd& c1, PathStep* path, double dtau)
    : ctx_(context), sys_(system), constrained_I_(constrained_I), c_(c), c1_(c1), path_(path),
      dtau_(dtau), nI_(system.num_dofs()), n_(system.size()), nz_(path ? n_ + 1 : n_),
      J_(S, nz_, symmetric_S), trial_(context.u) {}

void InterfaceNewton::residual(const Eigen::VectorXd& at, Eigen::VectorXd& out,
                               CondensedNewtonMatrix* jac) {
  const std::vector<double>& u = ctx_.u;
  for (Index k = 0; k < nI_; ++k)
    trial_[sys_.dofs()[k]] = u[sys_.dofs()[k]] + at(k);
  sys_.set_multipliers(at.segment(nI_, n_ - nI_));
  for (const auto& ia : ctx_.interfaces)
    ia->evaluate(trial_, dtau_);
  out.head(nI_) = c_ - J_.dense_product(at.head(nI_)); // shared by the ranks
  out.tail(nz_ - nI_).setZero();
  entries_.clear();
  // add() touches rows and columns below n only: a bordered J and F pass as they are.
  if (jac)
    sys_.add(constrained_I_, out, entries_);
  else
    sys_.add(constrained_I_, out, nullptr);
  if (path_) {
    out.head(nI_) += at(n_) * c1_;
    out(n_) = path_->constraint(sys_, at, jac ? &grad_ : nullptr);
    if (jac) {
      for (Index i = 0; i < nI_; ++i)
        entries_.emplace_back(i, n_, c1_(i));
      // A dissipation constraint with no gradient (no pair softens at this iterate) borders
      // J with a zero row. From the predictor on (e.g. that of a step whose ramp failed for
      // the bulk's sake) such Newton steps hold Δλ (row dΔλ = 0): where they land pairs soften
      // and the constraint acts, or equilibrium is met with none softening (nothing_softens).
      // Once the constraint has acted, a zero row fails the step as singular, as it did before
      // holding: holding there sent the energy-controlled column off its path (to the
      // staggered fallback) where the halved step stays on it.
      const bool no_gradient =
          path_->kind == PathStep::Kind::Dissipation && grad_.cwiseAbs().maxCoeff() == 0.0;
      lambda_held_ = holding_ && no_gradient;
      holding_ = lambda_held_;
      if (lambda_held_) entries_.emplace_back(n_, n_, 1.0);
      for (Index j = 0; j < nz_; ++j)
        if (grad_(j) != 0.0) entries_.emplace_back(n_, j, grad_(j));
    }
  }
  if (jac) jac->set_sparse_part(entries_);
}

double InterfaceNewton::merit(const Eigen::VectorXd& r) const {
  return path_ ? std::hypot(r.head(n_).norm(), g_weight_ * r(n_)) : r.norm();
}

double InterfaceNewton::merit_without_stick_to_slip(const Eigen::VectorXd& r,
                                                    const std::vector<ContactStatus>& before,
                                                    const std::vector<ContactStatus>& after) const {
  Eigen::VectorXd rest = r;
  const Index d = before.empty() ? 0 : (n_ - nI_) / static_cast<Index>(before.size());
  for (std::size_t k = 0; k < before.size(); ++k)
    if (before[k] == ContactStatus::Stick && after[k] == ContactStatus::Slip)
      rest.segment(nI_ + d * static_cast<Index>(k), d).setZero();
  return merit(rest);
}

bool InterfaceNewton::solve(Eigen::VectorXd& z, const ConvergenceTest& test, int iteration_limit,
                            ReusedLuSolver& newton_solver, IncrementLog& log) {
  const NonlinearSolverOptions& copt = ctx_.contact_solver;
  RunSummary& summary = ctx_.summary;
  Eigen::VectorXd F(nz_), dz(nz_), F_try(nz_);
  // The merit of the line search measures each residual in units of its own tolerance: the
  // forces and the law to copt.tolerance × reference, the constraint to its looser
  // constraint_tolerance(). Weighted as a force relative to the reference instead (before),
  // the constraint, whose linearisation is poor where pairs cross β's kink, dominated the
  // merit and the line search cut steps that reduced the forces: on rccm_traced.yaml with
  // 100, 120 or 160 increments single traced steps took 14 to 20 iterations (5 now).
  g_weight_ =
      path_ ? copt.tolerance * test.reference() / path_->constraint_tolerance(copt.tolerance) : 0.0;
  // Single-precision factors: GMRES stays in double and meets the same tolerances, with
  // half the bytes streamed per preconditioner application (docs/theory.md). A nonlinear
  // bulk changes S, hence the factors, at every outer iteration: few solves per factors,
  // and double precision keeps its inner iteration counts (and cut-backs) as they were.
  newton_solver.set_single_precision_factors(ctx_.linear);
  std::vector<ContactStatus> branches; // at z
  bool overshoot_taken = false;        // the last step was a full one across stick → slip
  for (int it = 0;; ++it, ++log.iterations) {
    auto t0 = std::chrono::steady_clock::now();
    residual(z, F, &J_);
    // Pairs on a kink to within round-off (friction exactly on the cone at the increment's
    // start): the branch the coming step needs, from the direction of the residual.
    if (it == 0 && sys_.set_tie_hints(F.head(nI_), constrained_I_)) residual(z, F, &J_);
    branches = sys_.branches();
    const double force = F.head(nI_).norm(), change = sys_.multiplier_residual(F);
    const bool constraint_met =
        !path_ || std::abs(F(n_)) <= path_->constraint_tolerance(copt.tolerance);
    summary.assembly_seconds += seconds_since(t0);
    if (ctx_.linear) log.history.push_back(test.relative(force));
    log.contact = test.relative(change);
    if (test.forces_met(force) && test.law_met(change)) {
      if (constraint_met) return true;
      if (lambda_held_) {
        log.failure = "no interface softens within the step: its dissipation cannot be met";
        log.nothing_softens = true;
        return false;
      }
    }
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
    // iterations on the pile at 77k DOFs). Near the end η is also held to 0.1 floor / ‖F‖:
    // the step's own error (η ‖F‖) then stays below the tolerance, so a step that would
    // converge is not spoiled by the inexact solve. Without that cap an iteration was added
    // on stick → slip steps of the frictional block (10k DOFs: 7, 4, 2 → 6, 4, 1 on steps 8
    // to 10) and the Coulomb pile took 182 linear solves instead of 75. Path-following steps
    // keep the tight solve (their constraint row has a scale of its own).
    const double eta =
        path_ ? 0.0
              : std::min({1e-3, test.relative(F.norm()), 0.1 * test.force_floor() / F.norm()});
    Eigen::VectorXd rhs = -F;
    if (path_ && lambda_held_) rhs(n_) = 0.0;
    dz = newton_solver.solve(J_, rhs, eta);
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
      const double merit0 = merit(F);
      // Except across stick → slip: a stuck pair's linearisation has no friction limit, so
      // the full step carries its force outside the cone by the whole excess, and F_λ there
      // measures that excess, which the slip branch's linearisation at the next iterate
      // removes (exactly for a 2D Coulomb pair), not a failure of the step. When the residual
      // of every other row meets the Armijo decrease, the full step is taken (not twice in a
      // row, against cycling between branches). Backtracked instead (before), the stick →
      // slip steps of the frictional block took halved steps one after another: 30k DOFs,
      // steps 8 and 9 of 15, 8 and 6 iterations against GetFEM's 7 and 5 (6 and 4 now); the
      // piles' linear solves are unchanged (docs/performance_solver_engine.md).
      residual(z + dz, F_try, nullptr);
      const double armijo = (1.0 - 1e-4) * merit0; // backtracking_step's test at the full step
      const double merit_full = merit(F_try);
      const bool decrease = merit_full < armijo;
      const bool overshoot_only =
          !decrease && !overshoot_taken &&
          merit_without_stick_to_slip(F_try, branches, sys_.branches()) < armijo;
      if (!decrease && !overshoot_only)
        step = backtracking_step(
            merit0,
            [&](double s) {
              residual(z + s * dz, F_try, nullptr);
              return merit(F_try);
            },
            merit_full);
      overshoot_taken = overshoot_only;
      summary.assembly_seconds += seconds_since(t0);
    }
    z += step * dz;
  }
}

} // namespace bipot
