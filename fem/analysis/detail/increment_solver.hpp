#pragma once
/// Internal to fem/analysis: the nonlinear solver of one load increment, as the stage driver
/// (StaticAnalysis::Impl::run) sees it. The implementations, one per algorithm:
///   ExactNewtonIncrement          generalized_newton on the condensed interface system
///   AugmentedLagrangianIncrement  semismooth_newton / bipotential_uzawa on the whole matrix
///   StaggeredIncrement            the β-staggered fallback for a debonding jump
/// make_increment_solver() picks the first two by the contact solver option.

#include <memory>
#include <string>
#include <vector>

namespace bipot {

class CondensedInterfaceSystem;
class LinearBulkResidual;
struct IncrementContext;
struct PathStep;

/// How one increment went: counts for the step report, the residual history and why it
/// failed.
struct IncrementLog {
  int iterations = 0, linear_iterations = 0, uzawa_updates = 0, staggered = 0;
  std::vector<double> history; ///< relative force residual per iteration
  double contact = 0;          ///< last relative multiplier change
  std::string failure;
  /// A dissipation-controlled step met equilibrium and the law where no pair softens: the
  /// constraint cannot be met (PathControl::decline()).
  bool nothing_softens = false;
};

/// One increment to solve, from the state in the solver's IncrementContext.
struct IncrementRequest {
  IncrementRequest(double lambda, double dtau, PathStep* path = nullptr, int max_iterations = 0)
      : lambda(lambda), dtau(dtau), path(path), max_iterations(max_iterations) {}
  double lambda; ///< stage load factor at the increment's end (its start with `path`)
  double dtau;   ///< pseudo-time of the increment (s): viscous adhesion's Δτ
  /// Path-following (generalized_newton only): Δλ is solved for, bordered by the step's
  /// constraint; the converged Δλ and interface increment are written back into it.
  PathStep* path;
  /// > 0: the generalized Newton gives up after that many iterations rather than the contact
  /// solver's max_iterations (a ramp that may hand over to path-following sooner).
  int max_iterations;
};

class IncrementSolver {
public:
  virtual ~IncrementSolver() = default;
  /// Solves the increment. Leaves `u` (and the interfaces) at the last iterate; on failure
  /// (false, the reason in log.failure) the caller restores u.
  virtual bool solve(const IncrementRequest& request, IncrementLog& log) = 0;
  /// Frees what the next increment can rebuild (dense factors kept across increments): the
  /// stage driver calls it at a stage's end, before the output, whose arrays would otherwise
  /// add to those factors at the run's peak.
  virtual void release_workspace() {}
};

/// The increment solver of the contact solver option on `context`'s system: the exact
/// generalized Newton when the interfaces come with a condensed system (`generalized_newton`
/// and some interface acting on the system), else Newton on the whole matrix
/// (semismooth_newton, bipotential_uzawa, or no interface to enforce). `schur_ready` and
/// `bulk_product` are the driver's state the generalized Newton shares (see
/// ExactNewtonIncrement).
std::unique_ptr<IncrementSolver> make_increment_solver(IncrementContext& context,
                                                       const CondensedInterfaceSystem* condensed,
                                                       LinearBulkResidual& bulk_product,
                                                       bool& schur_ready);

} // namespace bipot
