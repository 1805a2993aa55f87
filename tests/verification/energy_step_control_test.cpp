// The energy step control's budget (fem/analysis/energy_step_control.hpp) on hand-made
// totals, each verdict against the budget worked out by hand, and the ledger's trial record
// (EnergyLedger::trial) against the trapezoidal rule.
#include "fem/analysis/energy_ledger.hpp"
#include "fem/analysis/energy_step_control.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace bipot {
namespace {

using Verdict = EnergyStepControl::Verdict;

// Work put in `w`, elastic energy `bulk`, adhesion dissipation `adhesion` (kJ).
EnergyTotals totals(double w, double bulk, double adhesion = 0) {
  EnergyTotals t;
  t.external_work = w;
  t.bulk_energy = bulk;
  t.adhesion_dissipation = adhesion;
  return t;
}

TEST(EnergyLedger, TrialGivesTheRecordAndLeavesTheLedgerAsItWas) {
  const std::vector<std::unique_ptr<InterfaceEnforcement>> none;
  EnergyLedger ledger(none);
  ledger.record({1, 2}, {3, 4}, {3, 4}); // ½(0 + 3)·1 + ½(0 + 4)·2 = 5.5, both works
  const EnergyTotals trial = ledger.trial({2, 2}, {5, 4}, {6, 4});
  // External: 5.5 + ½(3 + 5)·1 = 9.5; internal: 5.5 + ½(3 + 6)·1 = 10.
  EXPECT_DOUBLE_EQ(trial.external_work, 9.5);
  EXPECT_DOUBLE_EQ(trial.bulk_energy, 10.0);
  EXPECT_DOUBLE_EQ(trial.balance_error(), -0.5);
  EXPECT_DOUBLE_EQ(trial.relative_error(), -0.5 / 9.5);
  EXPECT_DOUBLE_EQ(ledger.totals().external_work, 5.5); // untouched
  ledger.record({2, 2}, {5, 4}, {6, 4});
  EXPECT_EQ(ledger.totals().external_work, trial.external_work);
  EXPECT_EQ(ledger.totals().bulk_energy, trial.bulk_energy);
}

// tolerance 1e-3 from a balanced run with 100 kJ put in: a step putting in 10 kJ more has a
// share of 1e-3 × 10 = 0.01 kJ, and the run-wide rule half the budget, 0.5e-3 × 110 = 0.055.
TEST(EnergyStepControl, AStepIsInsideItsShareOrTheRunsHalfBudget) {
  EnergyStepControl control;
  EXPECT_FALSE(control.active());
  const EnergyTotals start = totals(100, 100);
  control.begin_stage(1e-3, start);
  EXPECT_EQ(control.judge(start, totals(110, 109.991), true), Verdict::Accept); // 0.009
  EXPECT_EQ(control.judge(start, totals(110, 109.96), true), Verdict::Accept);  // 0.04 ≤ 0.055
  EXPECT_EQ(control.judge(start, totals(110, 109.94), true), Verdict::Halve);   // 0.06
  EXPECT_EQ(control.judge(start, totals(110, 109.94), false), Verdict::OverBudget);
  // May the next step be longer? 0.009 × 1.5³ = 0.030 fits in 0.055, × 2³ = 0.072 does not.
  EXPECT_TRUE(control.may_grow(start, totals(110, 109.991), 1.5));
  EXPECT_FALSE(control.may_grow(start, totals(110, 109.991), 2.0));
}

// The work put in falls from 100 to 90 kJ (a snap-back): only the step's share of what it
// dissipated counts, 1e-3 × ΔD.
TEST(EnergyStepControl, WhereTheWorkPutInFallsOnlyTheShareOfTheDissipationCounts) {
  EnergyStepControl control;
  const EnergyTotals start = totals(100, 100);
  control.begin_stage(1e-3, start);
  EXPECT_EQ(control.judge(start, totals(90, 79.96, 10), true), Verdict::Halve);  // 0.04 > 0.01
  EXPECT_EQ(control.judge(start, totals(90, 39.96, 50), true), Verdict::Accept); // 0.04 ≤ 0.05
}

TEST(EnergyStepControl, KeptOverTheBudgetItsOwnErrorIsExcused) {
  EnergyStepControl control;
  const EnergyTotals start = totals(100, 100);
  control.begin_stage(1e-3, start);
  const EnergyTotals jump = totals(110, 109.9); // 0.1 kJ, over at the smallest step
  const Verdict v = control.judge(start, jump, false);
  EXPECT_EQ(v, Verdict::OverBudget);
  control.accept(start, jump, v);
  EXPECT_NEAR(control.controlled_error(jump), 0.0, 1e-15);
  // The next step (10 kJ more) is held to the budget again, the excused 0.1 kJ left out:
  // its own 0.05 kJ fits in 0.5e-3 × 120 = 0.06, 0.07 does not.
  EXPECT_EQ(control.judge(jump, totals(120, 119.85), true), Verdict::Accept);
  EXPECT_EQ(control.judge(jump, totals(120, 119.83), true), Verdict::Halve);
}

// Inside its share, but the run's error from earlier steps (0.08 kJ, within 1e-3 × 100) is
// over 1e-3 × 70 once the work put in has fallen to 70: flagged, not excused.
TEST(EnergyStepControl, AnErrorCarriedPastAFallOfTheWorkIsFlagged) {
  EnergyStepControl control;
  control.begin_stage(1e-3, totals(0, 0));
  const EnergyTotals before = totals(100, 99.92);
  const EnergyTotals after = totals(70, 49.92, 20); // own error 0
  const Verdict v = control.judge(before, after, true);
  EXPECT_EQ(v, Verdict::OverBudget);
  control.accept(before, after, v);
  EXPECT_NEAR(control.controlled_error(after), 0.08 / 70, 1e-12);
}

// A stage starting after one without the control takes the error the run carries as given.
TEST(EnergyStepControl, TheErrorOfUncontrolledStagesIsTakenAsGiven) {
  EnergyStepControl control;
  const EnergyTotals carried = totals(100, 99.5);
  control.begin_stage(1e-3, carried);
  EXPECT_NEAR(control.controlled_error(carried), 0.0, 1e-15);
  EXPECT_EQ(control.judge(carried, totals(110, 109.491), true), Verdict::Accept);
}

} // namespace
} // namespace bipot
