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
                           InterfaceResponseDerivatives* derivatives, ConeTie tie) {
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
  const ConeProjection proj = project_onto_cone(out.tau, out.mu_bar, tie);
  out.r = proj.r;
  out.status = proj.status;
  out.tie = proj.tie;
  LocalMatrix da_djump;
  out.traction = out.r + law.adhesive_traction(out.beta, jump, derivatives ? &da_djump : nullptr);

  if (derivatives) {
    // Chain rule through β(jump) → μ̄(β) → τ(r, jump, μ̄) → Proj(τ, μ̄).
    const LocalVector dmu_djump = law.friction_coefficient_dbeta(out.beta) * dbeta_djump;
    // On the slip branch, linearise ‖Δg_t‖ along the slip the projection implies, not along
    // the iterate's Δg_t. τ − r is the cone's outward normal there, so the law's solution
    // slides along −e, e = τ_t/‖τ_t‖, and ‖Δg_t‖ ≥ −e·Δg_t with equality exactly when it
    // does: the derivatives below are those of τ_n = r_n − ρ(g_n + μ̄ φ(Δg_t)) with φ the
    // line of slope −e through ‖Δg_t‖ at the iterate.
    // Where the iterate already slides along −e (in 2D every iterate near a sliding solution)
    // that is the generalized Jacobian; at Δg_t = 0 it is the element −e of the
    // subdifferential. Elsewhere (an iterate sliding against its friction force, as stick →
    // slip changes produce) the exact derivative is that of a piece the solution is not on,
    // with the normal coupled to a slip of the wrong sign, and Newton overshoots. Measured
    // with bench/frictional_block.py (15 steps, 2k/10k/30k DOFs): 17/24/27 Newton iterations
    // with the exact element, 15/21/23 with this one; the Coulomb pile's default run 120 →
    // 104 linear solves.
    if (proj.status == ContactStatus::Slip) {
      const LocalVector e = out.tau.tail(d - 1).normalized();
      dpred.dtau_djump.block(0, 1, 1, d - 1) = rho * out.mu_bar * e.transpose();
    }
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
