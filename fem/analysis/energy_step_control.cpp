#include "fem/analysis/energy_step_control.hpp"

#include "fem/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace bipot {

namespace {

// The sum of the terms' magnitudes: the balance is a difference of these, so its round-off is
// a few ε of that sum whatever the work put in (a geostatic stage puts in almost none).
double round_off(const EnergyTotals& t) {
  return 1e-12 *
         (std::abs(t.external_work) + std::abs(t.interference_work) + std::abs(t.bulk_energy) +
          std::abs(t.interface_energy) + std::abs(t.adhesion_dissipation) +
          std::abs(t.viscous_dissipation) + std::abs(t.contact_work));
}

double dissipated(const EnergyTotals& t) {
  return t.adhesion_dissipation + t.viscous_dissipation + t.contact_work;
}

} // namespace

void EnergyStepControl::begin_stage(double tolerance, const EnergyTotals& totals) {
  // Coming from a stage without the control, the error the run carries is what the control
  // found, not what it made.
  if (!active()) excused_ = totals.balance_error();
  tolerance_ = tolerance;
}

bool EnergyStepControl::within_budget(const EnergyTotals& before, const EnergyTotals& after,
                                      double factor) const {
  const double own = after.balance_error() - before.balance_error();
  const double share = tolerance_ * (std::max(dissipated(after) - dissipated(before), 0.0) +
                                     std::max(after.work_put_in() - before.work_put_in(), 0.0));
  if (factor * std::abs(own) <= share + round_off(after)) return true;
  if (after.work_put_in() < before.work_put_in()) return false;
  const double run = before.balance_error() - excused_ + factor * own;
  return std::abs(run) <= headroom * tolerance_ * after.work_put_in() + round_off(after);
}

EnergyStepControl::Verdict EnergyStepControl::judge(const EnergyTotals& before,
                                                    const EnergyTotals& trial,
                                                    bool can_halve) const {
  if (!active()) return Verdict::Accept;
  if (!within_budget(before, trial, 1.0)) return can_halve ? Verdict::Halve : Verdict::OverBudget;
  // Within its budget, yet the run's balance is over the tolerance: the work put in fell
  // below what the error of earlier steps needs. No shorter step mends it.
  return controlled_error(trial) * trial.work_put_in() >
                 tolerance_ * trial.work_put_in() + round_off(trial)
             ? Verdict::OverBudget
             : Verdict::Accept;
}

void EnergyStepControl::accept(const EnergyTotals& before, const EnergyTotals& totals,
                               Verdict verdict) {
  // Kept over its budget at the smallest step: its error is excused, so that the steps after
  // it are held to the tolerance again.
  if (verdict == Verdict::OverBudget && !within_budget(before, totals, 1.0))
    excused_ += totals.balance_error() - before.balance_error();
}

bool EnergyStepControl::may_grow(const EnergyTotals& before, const EnergyTotals& after,
                                 double growth) const {
  // The error of a step grows with the cube of its length (see the class comment).
  return !active() || within_budget(before, after, growth * growth * growth);
}

double EnergyStepControl::controlled_error(const EnergyTotals& totals) const {
  const double put_in = totals.work_put_in();
  return put_in > 0 ? std::abs(totals.balance_error() - excused_) / put_in : 0.0;
}

void EnergyStepControl::load_state(const std::vector<double>& state) {
  if (state.size() != 2)
    throw Error("energy step control state: needs 2 values (tolerance, excused error), has " +
                std::to_string(state.size()));
  tolerance_ = state[0];
  excused_ = state[1];
}

} // namespace bipot
