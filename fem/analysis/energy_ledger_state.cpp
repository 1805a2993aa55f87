// EnergyLedger's state for checkpoints: a restarted run continues the energy balance.
#include "fem/analysis/energy_ledger.hpp"

#include "fem/core/error.hpp"

namespace bipot {

StateArrays EnergyLedger::save_state() const {
  const EnergyTotals& t = totals_;
  StateArrays out;
  out["totals"] = {t.external_work,        t.interference_work,   t.bulk_energy, t.interface_energy,
                   t.adhesion_dissipation, t.viscous_dissipation, t.contact_work};
  out["u"] = u_;
  out["external"] = external_;
  out["internal"] = internal_;
  out["path"] = {last_chord_};
  for (std::size_t k = 0; k < ifaces_.size(); ++k)
    out["interface." + std::to_string(k)] = ifaces_[k]->save_energy_account();
  return out;
}

void EnergyLedger::load_state(const StateArrays& state) {
  const auto get = [&](const std::string& name) -> const std::vector<double>& {
    const auto it = state.find(name);
    if (it == state.end()) throw Error("energy state: no array '" + name + "'");
    return it->second;
  };
  const std::vector<double>& t = get("totals");
  if (t.size() != 7) throw Error("energy state: 'totals' needs 7 values");
  totals_ = {t[0], t[1], t[2], t[3], t[4], t[5], t[6]};
  u_ = get("u");
  external_ = get("external");
  internal_ = get("internal");
  // Checkpoints written before the three-point rule have no "path": the rule starts again.
  const auto path = state.find("path");
  last_chord_ = path != state.end() && path->second.size() == 1 ? path->second[0] : 0.0;
  for (std::size_t k = 0; k < ifaces_.size(); ++k)
    ifaces_[k]->load_energy_account(get("interface." + std::to_string(k)));
}

} // namespace bipot
