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
  out["shift"] = shift_;
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    std::vector<double>& v = out["pairs." + std::to_string(k)];
    for (const PairState& p : pairs_[k]) {
      v.push_back(p.beta);
      for (const auto* x : {&p.jump, &p.traction, &p.r})
        v.insert(v.end(), x->data(), x->data() + x->size());
    }
  }
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
  if (get("shift").size() != shift_.size()) throw Error("energy state: 'shift' has another size");
  shift_ = get("shift");
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    const std::vector<double>& v = get("pairs." + std::to_string(k));
    std::size_t at = 0;
    for (PairState& p : pairs_[k]) {
      const auto n = static_cast<std::size_t>(p.jump.size());
      if (at + 1 + 3 * n > v.size()) throw Error("energy state: too few pair values");
      p.beta = v[at++];
      for (auto* x : {&p.jump, &p.traction, &p.r}) {
        for (std::size_t i = 0; i < n; ++i)
          (*x)(static_cast<Eigen::Index>(i)) = v[at++];
      }
    }
    if (at != v.size()) throw Error("energy state: too many pair values");
  }
}

} // namespace bipot
