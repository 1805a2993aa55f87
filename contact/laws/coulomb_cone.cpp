#include "contact/laws/coulomb_cone.hpp"

#include <cassert>
#include <cmath>

namespace bipot::contact {

ConeProjection project_onto_cone(const LocalVector& tau, double mu_bar, ConeTie tie) {
  const Eigen::Index d = tau.size();
  assert((d == 2 || d == 3) && mu_bar >= 0.0);
  const double tau_n = tau(0);
  const double s = tau.tail(d - 1).norm();

  ConeProjection out;
  out.dr_dmu = LocalVector::Zero(d);
  out.tie =
      tau_n > 0.0 && mu_bar > 0.0 && std::abs(s - mu_bar * tau_n) <= cone_tie_band * mu_bar * tau_n;
  const bool stick = out.tie && tie != ConeTie::ByValue ? tie == ConeTie::Stick
                                                        : tau_n >= 0.0 && s <= mu_bar * tau_n;
  // Stick first: with μ̄ = 0 and τ_t = 0 both stick and separation tests can hold at τ_n = 0;
  // either gives r = τ = 0, and τ_n ≥ 0 keeps a negative τ_n out of the (degenerate) cone.
  if (stick) {
    out.r = tau;
    out.status = ContactStatus::Stick;
    out.dr_dtau = LocalMatrix::Identity(d, d);
    // μ̄ = 0 (no friction, or full RCCM adhesion β = 1): the cone is the half-line r_t = 0
    // and τ_t = 0 is a single point of it. Take the slip-side element of the generalized
    // Jacobian there (no tangential part): the identity would give Newton a tangential
    // stiffness ρ for one iteration and take it away at the next, and on a confined pile
    // model that alternation stalled both solvers.
    if (mu_bar == 0.0) out.dr_dtau.bottomRightCorner(d - 1, d - 1).setZero();
    return out;
  }
  if (mu_bar * s <= -tau_n) {
    out.r = LocalVector::Zero(d);
    out.status = ContactStatus::Open;
    out.dr_dtau = LocalMatrix::Zero(d, d);
    return out;
  }

  // Slip: both tests failed, which forces s > 0 (s = 0 would pass one of them for μ̄ ≥ 0).
  const double k = 1.0 / (1.0 + mu_bar * mu_bar);
  const double r_n = (tau_n + mu_bar * s) * k;
  const LocalVector e = tau.tail(d - 1) / s;
  // μ̄ r_n / s < 1 in this branch (r_n < s/μ̄), so the curvature term below cannot overflow.
  const double curvature = (mu_bar * r_n) / s;

  out.status = ContactStatus::Slip;
  out.r.resize(d);
  out.r(0) = r_n;
  out.r.tail(d - 1) = mu_bar * r_n * e;

  out.dr_dtau.resize(d, d);
  out.dr_dtau(0, 0) = k;
  out.dr_dtau.block(0, 1, 1, d - 1) = mu_bar * k * e.transpose();
  out.dr_dtau.block(1, 0, d - 1, 1) = mu_bar * k * e;
  // ∂(μ̄ r_n e)/∂τ_t = μ̄ e ⊗ ∂r_n/∂τ_t + μ̄ r_n (I − e eᵀ)/s.
  const LocalMatrix eet = e * e.transpose();
  out.dr_dtau.block(1, 1, d - 1, d - 1) =
      mu_bar * mu_bar * k * eet + curvature * (LocalMatrix::Identity(d - 1, d - 1) - eet);

  const double dr_n_dmu = (s * (1.0 - mu_bar * mu_bar) - 2.0 * mu_bar * tau_n) * k * k;
  out.dr_dmu(0) = dr_n_dmu;
  out.dr_dmu.tail(d - 1) = (r_n + mu_bar * dr_n_dmu) * e;
  return out;
}

LocalVector bipotential_predictor(const LocalVector& r, double g_n, const LocalVector& slip_inc,
                                  double mu_bar, double rho, PredictorDerivatives* derivatives) {
  const Eigen::Index d = r.size();
  assert((d == 2 || d == 3) && slip_inc.size() == d - 1 && rho > 0.0);
  const double slip = slip_inc.norm();

  LocalVector tau = r;
  tau(0) -= rho * (g_n + mu_bar * slip);
  tau.tail(d - 1) -= rho * slip_inc;

  if (derivatives) {
    LocalMatrix& dj = derivatives->dtau_djump;
    dj = LocalMatrix::Zero(d, d);
    dj(0, 0) = -rho;
    // Subgradient 0 of ‖Δg_t‖ at Δg_t = 0.
    if (slip > 0.0) dj.block(0, 1, 1, d - 1) = -rho * mu_bar * slip_inc.transpose() / slip;
    dj.block(1, 1, d - 1, d - 1) = -rho * LocalMatrix::Identity(d - 1, d - 1);
    derivatives->dtau_dmu = LocalVector::Zero(d);
    derivatives->dtau_dmu(0) = -rho * slip;
  }
  return tau;
}

} // namespace bipot::contact
