#pragma once
/// The path-following state of one stage (`control:` arc_length or dissipation): which
/// control the next increment uses, the step length (arc length or dissipated energy) and
/// its adaptation, and the switches between the ramp and dissipation control.

#include "fem/assembly/condensed_interface_system.hpp"
#include "fem/assembly/interface_enforcement.hpp"
#include "fem/input/problem_spec.hpp"

#include <Eigen/Dense>

#include <memory>
#include <string>
#include <vector>

namespace bipot {

struct PathStep;

class PathControl {
public:
  /// `sys` is null when the model has no contact interface (then the stage must be a ramp:
  /// input checks refuse the rest).
  PathControl(const StageSpec& stage, const CondensedInterfaceSystem* sys,
              const std::vector<std::unique_ptr<InterfaceEnforcement>>& interfaces);
  ~PathControl();

  /// The next increment is traced (λ an unknown) rather than ramped.
  bool following() const { return mode_ != Mode::Ramp; }
  /// The constraint of the next traced increment, its length halved `level` times.
  PathStep& step(int level);
  /// The pseudo-time step of a traced increment (the viscosity's Δτ), as a fraction of the
  /// stage's duration: a planned increment's. Δλ is only known at the end and may be tiny or
  /// negative on a snap-back, where time still runs; with |Δλ_prev| the viscous β barely
  /// moved in small steps and the pile's traced path broke down at 7.6 mm.
  double pseudo_time_step() const { return planned_; }
  /// A converged traced step goes on along the path: for arc length, its interface
  /// displacement has a positive projection on the last step's (Crisfield's angle test: the
  /// constraint ‖x‖ = L also holds going back); a dissipation step cannot go back.
  bool forward(const PathStep& step) const;
  /// λ would pass 1: ramp to the end of the stage from here.
  void finish() { finished_ = true, mode_ = Mode::Ramp; }
  /// Every halving of a traced step failed other than for want of softening (a plastic bulk
  /// dissipates what the adhesion's constraint does not see, and Δλ runs away): the ramp
  /// carries the rest of the stage, its cut-backs and staggered fallback included. False if
  /// the stage already ramps to its end.
  bool abandon() {
    if (finished_) return false;
    finish();
    return true;
  }
  /// A ramp increment failed: true if dissipation control takes over (the stage asks for
  /// it, an interface has adhesion left, and an earlier increment gives a direction).
  bool switch_on_failure();
  /// A traced step found no pair softening within reach (IncrementLog::nothing_softens: the
  /// ramp failed for the bulk's sake, e.g. a plastic soil): back to the ramp, which until an
  /// increment converges has the solver's own iteration limit (ramp_iterations()) and cuts
  /// back instead of handing over again.
  void decline() { mode_ = Mode::Ramp, declined_ = true; }
  /// The Newton iterations a ramp increment gets (0: the contact solver's own limit). Where a
  /// failure would hand over to dissipation control, a ramp increment slower than one that
  /// makes a traced step shrink (slow_iterations) fails: the ramp that cannot follow a
  /// softening interface used up all 50 iterations before, twice on rccm_traced.yaml (100 of
  /// its 341 linear solves).
  int ramp_iterations() const { return can_switch() ? slow_iterations : 0; }
  /// Newton iterations from which a step counts as slow: the next traced step is shorter.
  static constexpr int slow_iterations = 8;
  /// The most Newton iterations of a traced step after which the next one may grow; a slower
  /// one where the path turns halves it (end_increment).
  static constexpr int quick_iterations = 3;
  /// A converged increment from u_begin to u of Δλ in `iterations`: its dissipation, the
  /// next step's length and the control of the next increment. `may_grow` false: the next
  /// step is no longer than this one (the stage's energy budget shortened it).
  void end_increment(const std::vector<double>& u, const std::vector<double>& u_begin,
                     double dlambda, int iterations, bool may_grow = true);
  bool traced_last() const { return traced_last_; }
  double last_dissipation() const { return dissipation_last_; }
  /// More traced increments than the stage allows.
  bool too_many(int steps) const { return steps > max_increments_; }

  /// What a failed traced increment reports, and its residual history for failure.log.
  std::string failure_message(std::size_t stage_index, int step, double lambda, int cutbacks,
                              const std::vector<double>& history, const std::string& why) const;

private:
  enum class Mode { Ramp, ArcLength, Dissipation };
  Eigen::VectorXd on_interface(const std::vector<double>& u) const;
  /// A failed ramp increment would hand over to dissipation control.
  bool can_switch() const;
  /// Σ A w(β): what adhesion loss can still dissipate (kJ), at the committed β.
  double adhesion_capacity() const;

  const StageSpec& stage_;
  const CondensedInterfaceSystem* sys_;
  const std::vector<std::unique_ptr<InterfaceEnforcement>>& interfaces_;
  Mode mode_ = Mode::Ramp;
  bool finished_ = false, traced_last_ = false, declined_ = false;
  int max_increments_;
  double planned_;
  double capacity_ = 0;             ///< adhesion energy left at the stage's start (kJ)
  double dissipation_step_ = 0;     ///< Δτ0 (kJ)
  double dissipation_ = 0;          ///< Δτ of the next traced step
  double length0_ = 0, length_ = 0; ///< arc length, first and next
  double dissipation_last_ = 0;     ///< of the last converged increment
  double dlambda_prev_ = 0;
  Eigen::VectorXd x_prev_; ///< the last increment on the interface DOFs
  std::unique_ptr<PathStep> step_;
};

} // namespace bipot
