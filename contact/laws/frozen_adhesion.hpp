#pragma once
/// A law with its adhesion held: β stays at the value it is given (the "old" β), with zero
/// derivative; tractions, friction and stiffness are the wrapped law's. The solvers use it in
/// their staggered fallback (static_analysis.cpp): at a debonding snap-back the implicit
/// β = min(β_old, w/E(g)) has no solution close to the last state, but with β held the
/// contact problem is well posed, and updating β between such solves converges (β only
/// decreases) to the equilibrium after the jump.

#include "contact/laws/interface_law.hpp"

namespace bipot::contact {

class FrozenAdhesion : public InterfaceLaw {
public:
  /// `base` is not owned and must outlive this object.
  explicit FrozenAdhesion(const InterfaceLaw& base) : base_(base) {}

  std::string name() const override { return base_.name(); }
  bool is_tied() const override { return base_.is_tied(); }
  double initial_adhesion() const override { return base_.initial_adhesion(); }
  double adhesion_energy(double beta) const override { return base_.adhesion_energy(beta); }
  double update_adhesion(double beta_old, const LocalVector& jump, double dtau,
                         LocalVector* dbeta_djump = nullptr) const override;
  LocalVector adhesive_traction(double beta, const LocalVector& jump,
                                LocalMatrix* dt_djump = nullptr) const override {
    return base_.adhesive_traction(beta, jump, dt_djump);
  }
  LocalVector adhesive_traction_dbeta(double beta, const LocalVector& jump) const override {
    return base_.adhesive_traction_dbeta(beta, jump);
  }
  double friction_coefficient(double beta) const override {
    return base_.friction_coefficient(beta);
  }
  double friction_coefficient_dbeta(double beta) const override {
    return base_.friction_coefficient_dbeta(beta);
  }
  double stiffness_scale() const override { return base_.stiffness_scale(); }

private:
  const InterfaceLaw& base_;
};

} // namespace bipot::contact
