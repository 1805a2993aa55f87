#pragma once
/// Step control on the energy balance (stage `energy_tolerance`, docs/theory.md "Energy
/// balance"): after every increment the run's |balance_error| should stay within
/// tolerance × P, P = |external work| + |interference work| (the work put in, energy.csv's
/// relative_error). An increment is judged on the totals the ledger would record
/// (EnergyLedger::trial) before anything of it is committed, and redone in halves like a
/// cut-back if its own balance error e (the change of balance_error over it) is outside its
/// budget. It is inside when either
///   - |e| ≤ tolerance × (ΔD⁺ + ΔP⁺) (+ round-off): its own share of what it dissipated
///     (D = adhesion + viscous dissipation + contact work) and put in. Summed over the steps
///     this bounds the run's error by tolerance × D, and P ≥ D: it holds on a snap-back too,
///     where P falls (the bodies give work back) but D never does;
///   - or P does not fall over the step and the run's error stays within headroom ×
///     tolerance × P: room for P to fall later, after an error made while it rose. Without
///     that rule the pile's traced path would be held to the share everywhere; without the
///     share, the column's first traced steps spent errors that P, 6 times smaller at the
///     bottom of its snap-back, could not carry.
/// The error is the ledger's quadrature's on the softening springs: per step third order in
/// its length (the trapezoid; fourth where the three-point rule applies, which the growth
/// test leaves aside, erring on the cautious side), against a share of first order, so a
/// halving divides their ratio by about 4 (or 8).
///
/// An increment still outside its budget at the smallest step allowed (a jump, whose energy
/// goes into a snap no quasi-static ledger sees) is accepted and flagged, never retried, and
/// its error `excused` from then on; as is the error the run carries into the first stage it
/// controls (stages without the option). An increment inside its budget after which the run's
/// error is still over tolerance × P is flagged too. A checkpoint saves the excused error and
/// the tolerance in force (save_state), so that a restarted run judges its increments as the
/// uninterrupted run did.

#include "fem/analysis/energy_ledger.hpp"

#include <vector>

namespace bipot {

class EnergyStepControl {
public:
  enum class Verdict {
    Accept,     ///< within the budget
    Halve,      ///< over its budget: redo the increment in halves
    OverBudget, ///< over, and a shorter step is not allowed or would not help: keep and flag
  };

  /// A stage starts with its tolerance (0: off) and the run's totals so far.
  void begin_stage(double tolerance, const EnergyTotals& totals);
  bool active() const { return tolerance_ > 0; }
  /// The increment from `before` that would bring the run to `trial`; `can_halve`: a smaller
  /// step is still allowed (the cut-back level is below max_cutbacks).
  Verdict judge(const EnergyTotals& before, const EnergyTotals& trial, bool can_halve) const;
  /// The increment judged `verdict` was kept, bringing the run from `before` to `totals`.
  void accept(const EnergyTotals& before, const EnergyTotals& totals, Verdict verdict);
  /// The kept increment from `before` to `after` leaves room for a next one `growth` times as
  /// long (true when the control is off): else the step should not grow.
  bool may_grow(const EnergyTotals& before, const EnergyTotals& after, double growth) const;
  /// |balance_error − excused| / work put in (0 without work).
  double controlled_error(const EnergyTotals& totals) const;

  /// What the control carries from increment to increment and into the next stage, for
  /// checkpoints: the tolerance in force and the excused error.
  std::vector<double> save_state() const { return {tolerance_, excused_}; }
  /// Restores save_state()'s values; throws bipot::Error if there are not two.
  void load_state(const std::vector<double>& state);

private:
  /// The increment's error, `factor` times over, inside its budget (class comment).
  bool within_budget(const EnergyTotals& before, const EnergyTotals& after, double factor) const;

  static constexpr double headroom = 0.5;
  double tolerance_ = 0;
  double excused_ = 0;
};

} // namespace bipot
