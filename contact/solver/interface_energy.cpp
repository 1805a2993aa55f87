// InterfaceAssembler's share of the run's energy balance (fem/analysis/energy_ledger.hpp):
// each work term is the trapezoidal rule over the increment, exact for elastic springs at
// constant β, for friction at constant force and for unilateral contact. While β falls, the
// springs' share of the external work is integrated exactly where the law can
// (InterfaceLaw::spring_work, exact_work_correction), else by the ledger's three-point rule
// where the pair's path is smooth (external_work_correction); what is left is that rule's
// error, and the trapezoid's at kinks (docs/energy_quadrature.md).
#include "contact/solver/interface_assembler.hpp"

#include "contact/solver/adhesion_loss.hpp"
#include "contact/solver/spring_work_correction.hpp"

#include "fem/core/error.hpp"

#include <algorithm>
#include <optional>

namespace bipot::contact {

void InterfaceAssembler::start_energy_account() {
  accounted_.resize(iface_.pairs.size());
  for (std::size_t i = 0; i < accounted_.size(); ++i) {
    AccountedPair& p = accounted_[i];
    p.jump = p.traction = p.r = LocalVector::Zero(dim_);
    // The unloaded jump: the pair's gap (no force acts on it yet).
    p.jump(0) = iface_.initial_gap + iface_.pairs[i].gap + gap_shift_;
    p.beta = committed_[i].beta;
    p.prev_jump = p.jump;
    p.prev_adhesive = LocalVector::Zero(dim_);
    p.regime = -1;
    p.regime_steps = 0;
  }
  smooth_states_ = 1;
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
  smooth_states_ = 1; // other springs from here: the three-point stencil starts again
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
  // A prescribed interference moves the jumps without the bodies: the springs' work is then
  // not all external, and the trapezoid stays for the stencil's steps.
  const bool moved = dshift != 0.0 || d_obstacle.squaredNorm() != 0.0;
  const bool three_point = energy.rule.three_point && !moved && smooth_states_ >= 3;
  // A law that integrates its springs' work exactly along the pair's path (InterfaceLaw::
  // spring_work: rate-independent adhesion) needs neither the rule nor a smooth stretch: its
  // kinks are in the integral. Not across a jump, nor where the interference moved the jumps.
  const bool exact_ok = energy.on_path && !moved && !law_->is_tied();
  smooth_states_ = moved ? 1 : std::min(smooth_states_ + 1, 3);
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
    const std::optional<double> exact =
        exact_ok ? law_->spring_work(old.beta, old.jump, now.jump) : std::nullopt;
    if (exact) energy.exact_work_correction += A * (*exact + 0.5 * (a_old + a).dot(dg));
    energy.adhesion_dissipation += A * loss.adhesion;
    energy.viscous_dissipation += A * loss.viscous;
    // A prescribed interference moves the normal jump without moving the bodies.
    energy.interference_work -= 0.5 * A * (old.traction(0) + now.traction(0)) * dshift;
    if (iface_.obstacle)
      energy.interference_work -=
          0.5 * A * (old.traction + now.traction).dot(frame(i).transpose() * d_obstacle);
    const int regime = spring_regime(old.beta, now.beta, static_cast<int>(now.status));
    old.regime_steps = regime == old.regime ? std::min(old.regime_steps + 1, 1 << 20) : 1;
    old.regime = regime;
    if (three_point) {
      SpringHistory h;
      h.a[0] = old.prev_adhesive;
      h.a[1] = a_old;
      h.a[2] = a;
      h.g[0] = old.prev_jump;
      h.g[1] = old.jump;
      h.g[2] = now.jump;
      h.softening = now.beta < old.beta;
      h.regime_steps = old.regime_steps;
      energy.kinked = energy.kinked || spring_path(h) == SpringPath::Kinked;
      if (!exact) energy.external_work_correction += A * spring_work_correction(energy.rule, h);
    }
    old.prev_jump = old.jump;
    old.prev_adhesive = a_old;
    old.jump = now.jump;
    old.traction = now.traction;
    old.r = now.r;
    old.beta = now.beta;
  }
}

std::vector<double> InterfaceAssembler::save_energy_account() const {
  std::vector<double> v = {accounted_shift_,
                           accounted_obstacle_[0],
                           accounted_obstacle_[1],
                           accounted_obstacle_[2],
                           law_change_work_,
                           account_recorded_ ? 1.0 : 0.0,
                           static_cast<double>(smooth_states_)};
  for (const AccountedPair& p : accounted_) {
    v.push_back(p.beta);
    for (const auto* x : {&p.jump, &p.traction, &p.r})
      v.insert(v.end(), x->data(), x->data() + x->size());
    v.push_back(p.regime);
    v.push_back(p.regime_steps);
    for (const auto* x : {&p.prev_jump, &p.prev_adhesive})
      v.insert(v.end(), x->data(), x->data() + x->size());
  }
  return v;
}

void InterfaceAssembler::load_energy_account(const std::vector<double>& v) {
  start_energy_account(); // sizes every pair's vectors
  const std::size_t n = static_cast<std::size_t>(dim_);
  // A checkpoint written before the three-point rule has no stencil (6 head values, a pair's
  // β, jump, traction and r): it loads, and the rule starts again from it.
  const std::size_t old_size = 6 + accounted_.size() * (1 + 3 * n);
  const std::size_t size = 7 + accounted_.size() * (3 + 5 * n);
  if (v.size() != size && v.size() != old_size)
    throw Error("interface '" + iface_.name + "': the energy state has " +
                std::to_string(v.size()) + " values, its " + std::to_string(accounted_.size()) +
                " pairs need " + std::to_string(size));
  const bool stencil = v.size() == size;
  accounted_shift_ = v[0];
  accounted_obstacle_ = {v[1], v[2], v[3]};
  law_change_work_ = v[4];
  account_recorded_ = v[5] != 0.0;
  smooth_states_ = stencil ? static_cast<int>(v[6]) : 1;
  std::size_t at = stencil ? 7 : 6;
  const auto read = [&](LocalVector& x) {
    for (std::size_t i = 0; i < n; ++i)
      x(static_cast<Eigen::Index>(i)) = v[at++];
  };
  for (AccountedPair& p : accounted_) {
    p.beta = v[at++];
    for (auto* x : {&p.jump, &p.traction, &p.r})
      read(*x);
    if (!stencil) continue;
    p.regime = static_cast<int>(v[at++]);
    p.regime_steps = static_cast<int>(v[at++]);
    read(p.prev_jump);
    read(p.prev_adhesive);
  }
}

} // namespace bipot::contact
