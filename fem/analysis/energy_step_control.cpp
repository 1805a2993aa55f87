#include "fem/analysis/energy_step_control.hpp"

#include <algorithm>
#include <cmath>

namespace bipot {

namespace {

// The sum of the terms' magnitudes: the balance is a difference of these, so its round-off is
// a few ε of that sum whatever the work put in (a geostatic stage puts in almost none).
double magnitude(const EnergyTotals& t) {
  return std::abs(t.external_work) + std::abs(t.interference_work) + std::abs(t.bulk_energy) +
         std::abs(t.interface_energy) + std::abs(t.adhesion_dissipation) +
         std::abs(t.viscous_dissipation) + std::abs(t.contact_work);
}

double dissipated(const EnergyTotals& t) {
  return t.adhesion_dissipation + t.viscous_dissipation + t.contact_work;
}

double round_off(const EnergyTotals& t) {
  return 1e-12 * magnitude(t);
}

} // namespace

void EnergyStepControl::begin_stage(double tolerance, const EnergyTotals& totals) {
  // Coming from a stage without the control (or from a restart, which does not save the
  // excused error), the error the run carries is what the control found, not what it made.
  if (!active()) excused_ = totals.balance_error();
  tolerance_ = tolerance;
}

double EnergyStepControl::own_error(const EnergyTotals& before, const EnergyTotals& after) {
  return std::abs(after.balance_error() - before.balance_error());
}

double EnergyStepControl::own_allowance(const EnergyTotals& before,
                                        const EnergyTotals& after) const {
  const auto work = [](const EnergyTotals& t) { return t.external_work + t.interference_work; };
  return tolerance_ * (std::max(dissipated(after) - dissipated(before), 0.0) +
                       std::max(work(after) - work(before), 0.0)) +
         round_off(after);
}

EnergyStepControl::Verdict EnergyStepControl::judge(const EnergyTotals& before,
                                                    const EnergyTotals& trial,
                                                    bool can_halve) const {
  if (!active()) return Verdict::Accept;
  // Within its own share, or the run's balance within a tenth of the budget: room for the
  // work put in to fall tenfold on a later snap-back (5 times on the column's).
  const bool in_share = own_error(before, trial) <= own_allowance(before, trial);
  if (!in_share && std::abs(trial.balance_error() - excused_) >
                       headroom * tolerance_ * trial.work_put_in() + round_off(trial))
    return can_halve ? Verdict::Halve : Verdict::OverBudget;
  // Within its own share, yet the run's balance is over: the work put in fell (a snap-back
  // gives work back) below what the error of earlier steps needs. No shorter step mends it.
  return controlled_error(trial) > tolerance_ + round_off(trial) / trial.work_put_in()
             ? Verdict::OverBudget
             : Verdict::Accept;
}

void EnergyStepControl::accept(const EnergyTotals& before, const EnergyTotals& totals,
                               Verdict verdict) {
  // An increment over its own share at the smallest step: its error is excused, so that the
  // steps after it are held to the tolerance again.
  if (verdict == Verdict::OverBudget && own_error(before, totals) > own_allowance(before, totals) &&
      std::abs(totals.balance_error() - excused_) >
          headroom * tolerance_ * totals.work_put_in() + round_off(totals))
    excused_ += totals.balance_error() - before.balance_error();
}

double EnergyStepControl::controlled_error(const EnergyTotals& totals) const {
  const double put_in = totals.work_put_in();
  return put_in > 0 ? std::abs(totals.balance_error() - excused_) / put_in : 0.0;
}

} // namespace bipot
