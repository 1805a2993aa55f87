#include "fem/analysis/energy_ledger.hpp"

namespace bipot {

double EnergyTotals::balance_error() const {
  return external_work + interference_work -
         (bulk_energy + interface_energy + adhesion_dissipation + viscous_dissipation +
          contact_work);
}

EnergyLedger::EnergyLedger(const std::vector<std::unique_ptr<contact::InterfaceAssembler>>& ifaces)
    : ifaces_(ifaces), pairs_(ifaces.size()), shift_(ifaces.size(), 0.0),
      obstacle_(ifaces.size(), {0, 0, 0}) {
  for (std::size_t k = 0; k < ifaces.size(); ++k) {
    if (ifaces[k]->tied()) continue;
    const std::vector<double> beta = ifaces[k]->committed_adhesion();
    pairs_[k].resize(ifaces[k]->num_pairs());
    for (std::size_t i = 0; i < pairs_[k].size(); ++i) {
      PairState& p = pairs_[k][i];
      const int m = ifaces[k]->multipliers()[i].size();
      p.jump = p.traction = p.r = contact::LocalVector::Zero(m);
      // The unloaded jump: the pair's gap (no force acts on it yet).
      p.jump(0) = ifaces[k]->interface().initial_gap + ifaces[k]->interface().pairs[i].gap +
                  ifaces[k]->gap_shift();
      p.beta = beta[i];
    }
    shift_[k] = ifaces[k]->gap_shift();
    obstacle_[k] = ifaces[k]->obstacle_displacement();
  }
}

void EnergyLedger::record(const std::vector<double>& u, const std::vector<double>& external,
                          const std::vector<double>& internal) {
  if (u_.empty()) {
    u_.assign(u.size(), 0.0);
    external_.assign(u.size(), 0.0);
    internal_.assign(u.size(), 0.0);
  }
  for (std::size_t d = 0; d < u.size(); ++d) {
    const double du = u[d] - u_[d];
    totals_.external_work += 0.5 * (external_[d] + external[d]) * du;
    totals_.bulk_energy += 0.5 * (internal_[d] + internal[d]) * du;
  }
  u_ = u;
  external_ = external;
  internal_ = internal;

  totals_.interface_energy = 0;
  for (std::size_t k = 0; k < ifaces_.size(); ++k) {
    const contact::InterfaceAssembler& ia = *ifaces_[k];
    if (ia.tied()) continue;
    const double w = ia.law().adhesion_energy(1.0) - ia.law().adhesion_energy(0.0);
    const double dshift = ia.gap_shift() - shift_[k];
    shift_[k] = ia.gap_shift();
    // A moving obstacle is body 2 of its pairs: its displacement moves every jump.
    const int dim = static_cast<int>(ia.multipliers().empty() ? 0 : ia.multipliers()[0].size());
    Eigen::VectorXd d_obstacle = Eigen::VectorXd::Zero(dim);
    if (ia.interface().obstacle)
      for (int c = 0; c < dim; ++c)
        d_obstacle(c) = ia.obstacle_displacement()[c] - obstacle_[k][c];
    obstacle_[k] = ia.obstacle_displacement();
    for (std::size_t i = 0; i < ia.num_pairs(); ++i) {
      const double A = ia.interface().pairs[i].weight;
      const contact::PairResult& now = ia.results()[i];
      PairState& old = pairs_[k][i];
      const contact::LocalVector dg = now.jump - old.jump;
      // Work done on the interface, −t·dg (t compression positive, g opening positive), split
      // into its irreversible part r and the adhesive springs a = t − r.
      totals_.contact_work -= 0.5 * A * (old.r + now.r).dot(dg);
      const contact::LocalVector a = now.traction - now.r;
      totals_.interface_energy -= 0.5 * A * a.dot(now.jump);
      // β E = −a·g / β: the driving force of the β update at the end of the step (backward
      // Euler, as the law integrates it).
      const double dbeta = old.beta - now.beta;
      totals_.adhesion_dissipation += A * w * dbeta;
      if (dbeta != 0.0 && now.beta > 0)
        totals_.viscous_dissipation += A * (-a.dot(now.jump) / now.beta - w) * dbeta;
      // A prescribed interference moves the normal jump without moving the bodies.
      totals_.interference_work -= 0.5 * A * (old.traction(0) + now.traction(0)) * dshift;
      if (ia.interface().obstacle)
        totals_.interference_work -=
            0.5 * A * (old.traction + now.traction).dot(ia.frame(i).transpose() * d_obstacle);
      old = {now.jump, now.traction, now.r, now.beta};
    }
  }
}

void EnergyLedger::reset_displacements() {
  std::fill(u_.begin(), u_.end(), 0.0);
}

} // namespace bipot
