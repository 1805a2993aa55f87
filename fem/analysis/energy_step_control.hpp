#pragma once
/// Step control on the energy balance (stage `energy_tolerance`, docs/theory.md "Energy
/// balance"). An increment is judged on the totals the ledger would record
/// (EnergyLedger::trial) before anything of it is committed: its own balance error e (the
/// change of balance_error over the increment) must stay within the tolerance of what it put
/// in and dissipated,
///   |e| ≤ tolerance × (ΔD⁺ + ΔW⁺)  (+ round-off),
/// D = adhesion + viscous dissipation + contact work, W = external + interference work (its
/// increase: a geostatic stage can leave W negative, and the pull-out then adds to it while
/// |W| falls). An increment over
/// its share is redone in halves like a cut-back. Summed, the run's error stays within
/// tolerance × (D + the work put in while it grew), which bounds it by tolerance × W at every
/// step also on a snap-back, where W falls (the bodies give work back) but D never does: a
/// budget on W itself let the first traced steps spend errors that W, 5 times smaller at
/// the bottom of the column's snap-back, could not carry. The error is the trapezoidal
/// rule's on the softening springs: per step third order, against a dissipation of first
/// order, so a halving divides the ratio by about 4.
///
/// An increment still over its share at the smallest step allowed (a jump, whose energy goes
/// into a snap no quasi-static ledger sees) is accepted and flagged, never retried, and its
/// error `excused`; as is the error the run carries into the first stage it controls (stages
/// without the option, or before a restart). An increment within its share after which the
/// run's |balance_error − excused| is still over tolerance × W is flagged too.

#include "fem/analysis/energy_ledger.hpp"

namespace bipot {

class EnergyStepControl {
public:
  enum class Verdict {
    Accept,     ///< within the budget
    Halve,      ///< over its share: redo the increment in halves
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
  /// |balance_error − excused| / work put in (0 without work).
  double controlled_error(const EnergyTotals& totals) const;
  /// The error excused so far (kJ).
  double excused() const { return excused_; }

private:
  static double own_error(const EnergyTotals& before, const EnergyTotals& after);
  double own_allowance(const EnergyTotals& before, const EnergyTotals& after) const;

  /// The share of the budget the run's error may use before increments are held to their own
  /// share (below).
  static constexpr double headroom = 0.1;
  double tolerance_ = 0;
  double excused_ = 0;
};

} // namespace bipot
