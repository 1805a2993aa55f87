// InterfaceAssembler's share of the run's energy balance (fem/analysis/energy_ledger.hpp):
// each work term is the trapezoidal rule over the increment, exact for elastic springs at
// constant β, for friction at constant force and for unilateral contact; what is left is the
// trapezoidal rule's error on the adhesive springs while β changes within a step
// (docs/theory.md, "Energy balance").
#include "contact/solver/interface_assembler.hpp"

#include "contact/solver/adhesion_loss.hpp"

#include "fem/core/error.hpp"

namespace bipot::contact {

void InterfaceAssembler::start_energy_account() {
  accounted_.resize(iface_.pairs.size());
  for (std::size_t i = 0; i < accounted_.size(); ++i) {
    AccountedPair& p = accounted_[i];
    p.jump = p.traction = p.r = LocalVector::Zero(dim_);
    // The unloaded jump: the pair's gap (no force acts on it yet).
    p.jump(0) = iface_.initial_gap + iface_.pairs[i].gap + gap_shift_;
    p.beta = committed_[i].beta;
  }
  accounted_shift_ = gap_shift_;
  accounted_obstacle_ = obstacle_u_;
  account_recorded_ = false;
  law_change_work_ = 0;
}

void InterfaceAssembler::rebase_energy_account() {
  // A stage that puts another law in force changes the springs where the interface is: at
  // the recorded jumps, with β as set_law() left it. What that does to their energy is put in
  // by the change, not by a force: it is booked as interference work. The next step's
  // trapezoids then start from the new law's springs, so that the driving force the viscous
  // term integrates is the law's own at both ends, not the old law's at the start. Before
  // the first recorded step there is nothing to rebase (the account starts unloaded).
  if (!account_recorded_) return;
  for (std::size_t i = 0; i < accounted_.size(); ++i) {
    AccountedPair& p = accounted_[i];
    const double beta = committed_[i].beta;
    // A tied law's whole traction is its multiplier: no springs.
    const LocalVector a_new =
        law_->is_tied() ? LocalVector::Zero(dim_) : law_->adhesive_traction(beta, p.jump);
    const LocalVector a_old = p.traction - p.r;
    law_change_work_ -= 0.5 * iface_.pairs[i].weight * (a_new - a_old).dot(p.jump);
    p.traction = p.r + a_new;
    p.beta = beta;
  }
}

void InterfaceAssembler::record_energy(InterfaceEnergy& energy) {
  const double w = law_->adhesion_energy(1.0) - law_->adhesion_energy(0.0);
  energy.interference_work += law_change_work_;
  law_change_work_ = 0;
  account_recorded_ = true;
  const double dshift = gap_shift_ - accounted_shift_;
  accounted_shift_ = gap_shift_;
  // A moving obstacle is body 2 of its pairs: its displacement moves every jump.
  Eigen::VectorXd d_obstacle = Eigen::VectorXd::Zero(dim_);
  if (iface_.obstacle)
    for (int c = 0; c < dim_; ++c)
      d_obstacle(c) = obstacle_u_[c] - accounted_obstacle_[c];
  accounted_obstacle_ = obstacle_u_;
  for (std::size_t i = 0; i < accounted_.size(); ++i) {
    const double A = iface_.pairs[i].weight;
    const PairResult& now = results_[i];
    AccountedPair& old = accounted_[i];
    const LocalVector dg = now.jump - old.jump;
    // Work done on the interface, −t·dg (t compression positive, g opening positive), split
    // into its irreversible part r and the adhesive springs a = t − r.
    energy.contact_work -= 0.5 * A * (old.r + now.r).dot(dg);
    const LocalVector a = now.traction - now.r;
    energy.stored -= 0.5 * A * a.dot(now.jump);
    // β Ẽ = −a·g / β, the force that drives β down, at both ends of the step: the
    // dissipation is its trapezoid times the loss, second order like the work terms
    // (adhesion_loss.hpp).
    const LocalVector a_old = old.traction - old.r;
    const double drive_old = old.beta > 0 ? -a_old.dot(old.jump) / old.beta : 0.0;
    const double drive_now = now.beta > 0 ? -a.dot(now.jump) / now.beta : 0.0;
    const AdhesionLoss loss = adhesion_loss(w, old.beta, drive_old, now.beta, drive_now);
    energy.adhesion_dissipation += A * loss.adhesion;
    energy.viscous_dissipation += A * loss.viscous;
    // A prescribed interference moves the normal jump without moving the bodies.
    energy.interference_work -= 0.5 * A * (old.traction(0) + now.traction(0)) * dshift;
    if (iface_.obstacle)
      energy.interference_work -=
          0.5 * A * (old.traction + now.traction).dot(frame(i).transpose() * d_obstacle);
    old = {now.jump, now.traction, now.r, now.beta};
  }
}

std::vector<double> InterfaceAssembler::save_energy_account() const {
  std::vector<double> v = {accounted_shift_,       accounted_obstacle_[0],
                           accounted_obstacle_[1], accounted_obstacle_[2],
                           law_change_work_,       account_recorded_ ? 1.0 : 0.0};
  for (const AccountedPair& p : accounted_) {
    v.push_back(p.beta);
    for (const auto* x : {&p.jump, &p.traction, &p.r})
      v.insert(v.end(), x->data(), x->data() + x->size());
  }
  return v;
}

void InterfaceAssembler::load_energy_account(const std::vector<double>& v) {
  start_energy_account(); // sizes every pair's vectors
  const std::size_t n = static_cast<std::size_t>(dim_);
  const std::size_t head = 6;
  if (v.size() != head + accounted_.size() * (1 + 3 * n))
    throw Error("interface '" + iface_.name + "': the energy state has " +
                std::to_string(v.size()) + " values, its " + std::to_string(accounted_.size()) +
                " pairs need " + std::to_string(head + accounted_.size() * (1 + 3 * n)));
  accounted_shift_ = v[0];
  accounted_obstacle_ = {v[1], v[2], v[3]};
  law_change_work_ = v[4];
  account_recorded_ = v[5] != 0.0;
  std::size_t at = head;
  for (AccountedPair& p : accounted_) {
    p.beta = v[at++];
    for (auto* x : {&p.jump, &p.traction, &p.r})
      for (std::size_t i = 0; i < n; ++i)
        (*x)(static_cast<Eigen::Index>(i)) = v[at++];
  }
}

} // namespace bipot::contact
