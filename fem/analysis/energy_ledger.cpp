#include "fem/analysis/energy_ledger.hpp"

#include <algorithm>
#include <cmath>

namespace bipot {

double EnergyTotals::balance_error() const {
  return external_work + interference_work -
         (bulk_energy + interface_energy + adhesion_dissipation + viscous_dissipation +
          contact_work);
}

double EnergyTotals::work_put_in() const {
  return std::abs(external_work) + std::abs(interference_work);
}

double EnergyTotals::relative_error() const {
  const double put_in = work_put_in();
  return put_in > 0 ? balance_error() / put_in : 0.0;
}

EnergyLedger::EnergyLedger(const std::vector<std::unique_ptr<InterfaceEnforcement>>& ifaces)
    : ifaces_(ifaces) {
  for (const auto& ia : ifaces_)
    ia->start_energy_account();
}

void EnergyLedger::record(const std::vector<double>& u, const std::vector<double>& external,
                          const std::vector<double>& internal, bool jump) {
  if (jump) break_path();
  if (u_.empty()) {
    u_.assign(u.size(), 0.0);
    external_.assign(u.size(), 0.0);
    internal_.assign(u.size(), 0.0);
  }
  double chord = 0;
  for (std::size_t d = 0; d < u.size(); ++d) {
    const double du = u[d] - u_[d];
    totals_.external_work += 0.5 * (external_[d] + external[d]) * du;
    totals_.bulk_energy += 0.5 * (internal_[d] + internal[d]) * du;
    chord += du * du;
  }
  chord = std::sqrt(chord);
  u_ = u;
  external_ = external;
  internal_ = internal;
  // The rule's parameter is the chord length of u, which grows along any path, traced
  // branches included (the load factor turns back at limit points). Steps whose lengths
  // differ by more than max_step_ratio keep the trapezoid (docs/energy_quadrature.md).
  const bool comparable = last_chord_ > 0 && chord > 0 &&
                          chord <= ThreePointRule::max_step_ratio * last_chord_ &&
                          last_chord_ <= ThreePointRule::max_step_ratio * chord;
  const ThreePointRule rule =
      comparable ? ThreePointRule::quadratic(last_chord_, chord) : ThreePointRule::trapezoid();
  last_chord_ = chord;

  totals_.interface_energy = 0;
  // A kink anywhere (a pair starting to soften) is one in every pair's path: the rule's
  // corrections count only if no interface saw one.
  double correction = 0;
  bool kinked = false;
  for (const auto& ia : ifaces_) {
    InterfaceEnergy e;
    e.rule = rule;
    e.on_path = !jump;
    ia->record_energy(e);
    correction += e.external_work_correction;
    totals_.external_work += e.exact_work_correction;
    kinked = kinked || e.kinked;
    totals_.interference_work += e.interference_work;
    totals_.interface_energy += e.stored;
    totals_.adhesion_dissipation += e.adhesion_dissipation;
    totals_.viscous_dissipation += e.viscous_dissipation;
    totals_.contact_work += e.contact_work;
  }
  if (!kinked) totals_.external_work += correction;
  if (jump) break_path();
}

EnergyTotals EnergyLedger::trial(const std::vector<double>& u, const std::vector<double>& external,
                                 const std::vector<double>& internal, bool jump) {
  // record() and back: the interfaces update their accounts only through record_energy().
  const EnergyTotals totals = totals_;
  const double chord = last_chord_;
  const std::vector<double> u_old = u_, external_old = external_, internal_old = internal_;
  std::vector<std::vector<double>> accounts;
  for (const auto& ia : ifaces_)
    accounts.push_back(ia->save_energy_account());
  record(u, external, internal, jump);
  const EnergyTotals out = totals_;
  totals_ = totals;
  last_chord_ = chord;
  u_ = u_old;
  external_ = external_old;
  internal_ = internal_old;
  for (std::size_t k = 0; k < ifaces_.size(); ++k)
    ifaces_[k]->load_energy_account(accounts[k]);
  return out;
}

void EnergyLedger::reset_displacements() {
  std::fill(u_.begin(), u_.end(), 0.0);
  break_path();
}

} // namespace bipot
