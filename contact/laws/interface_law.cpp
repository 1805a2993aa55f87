#include "contact/laws/interface_law.hpp"

#include <cassert>

namespace bipot::contact {

double InterfaceLaw::update_adhesion(double, const LocalVector& jump, double,
                                     LocalVector* dbeta_djump) const {
  if (dbeta_djump) *dbeta_djump = LocalVector::Zero(jump.size());
  return 0.0;
}

LocalVector InterfaceLaw::adhesive_traction(double, const LocalVector& jump,
                                            LocalMatrix* dt_djump) const {
  if (dt_djump) *dt_djump = LocalMatrix::Zero(jump.size(), jump.size());
  return LocalVector::Zero(jump.size());
}

LocalVector InterfaceLaw::adhesive_traction_dbeta(double, const LocalVector& jump) const {
  return LocalVector::Zero(jump.size());
}

InterfaceState initial_state(const InterfaceLaw& law, int local_size) {
  assert(local_size == 2 || local_size == 3);
  InterfaceState s;
  s.beta = law.initial_adhesion();
  s.jump = LocalVector::Zero(local_size);
  s.r = LocalVector::Zero(local_size);
  return s;
}

InterfaceResponse evaluate_tie(const InterfaceState& old, const LocalVector& jump,
                               const LocalVector& r, double rho,
                               InterfaceResponseDerivatives* derivatives) {
  // The augmented Lagrangian of the equality jump = old.jump: no cone, no projection. Its
  // fixed point r_new = r holds the jump exactly where it was (to the solver's tolerance,
  // not a penalty's error), like a sticking pair that cannot open.
  const Eigen::Index d = jump.size();
  InterfaceResponse out;
  out.beta = 1.0;
  out.tau = r - rho * (jump - old.jump);
  out.r = out.tau;
  out.traction = out.r;
  out.status = ContactStatus::Stick;
  if (derivatives) {
    const LocalMatrix I = LocalMatrix::Identity(d, d);
    derivatives->dbeta_djump = LocalVector::Zero(d);
    derivatives->dr_djump = derivatives->dt_djump = -rho * I;
    derivatives->dr_dr = derivatives->dt_dr = I;
  }
  return out;
}

InterfaceResponse evaluate(const InterfaceLaw& law, const InterfaceState& old,
                           const LocalVector& jump, const LocalVector& r, double dtau, double rho,
                           InterfaceResponseDerivatives* derivatives) {
  const Eigen::Index d = jump.size();
  assert((d == 2 || d == 3) && r.size() == d && old.jump.size() == d);
  if (law.is_tied()) return evaluate_tie(old, jump, r, rho, derivatives);

  InterfaceResponse out;
  LocalVector dbeta_djump;
  out.beta = law.update_adhesion(old.beta, jump, dtau, derivatives ? &dbeta_djump : nullptr);
  out.mu_bar = law.friction_coefficient(out.beta);
  const LocalVector slip_inc = jump.tail(d - 1) - old.jump.tail(d - 1);
  PredictorDerivatives dpred;
  out.tau =
      bipotential_predictor(r, jump(0), slip_inc, out.mu_bar, rho, derivatives ? &dpred : nullptr);
  const ConeProjection proj = project_onto_cone(out.tau, out.mu_bar);
  out.r = proj.r;
  out.status = proj.status;
  LocalMatrix da_djump;
  out.traction = out.r + law.adhesive_traction(out.beta, jump, derivatives ? &da_djump : nullptr);

  if (derivatives) {
    // Chain rule through β(jump) → μ̄(β) → τ(r, jump, μ̄) → Proj(τ, μ̄).
    const LocalVector dmu_djump = law.friction_coefficient_dbeta(out.beta) * dbeta_djump;
    const LocalMatrix dtau_djump = dpred.dtau_djump + dpred.dtau_dmu * dmu_djump.transpose();
    derivatives->dbeta_djump = dbeta_djump;
    derivatives->dr_djump = proj.dr_dtau * dtau_djump + proj.dr_dmu * dmu_djump.transpose();
    derivatives->dr_dr = proj.dr_dtau;
    derivatives->dt_djump = derivatives->dr_djump + da_djump +
                            law.adhesive_traction_dbeta(out.beta, jump) * dbeta_djump.transpose();
    derivatives->dt_dr = proj.dr_dtau;
  }
  return out;
}

} // namespace bipot::contact
