#pragma once
/// The Coulomb cone projection and the De Saxcé bipotential predictor (docs/formulation.md §4):
/// the point-wise map r ↦ Proj_{K_μ̄}(r − ρ[Δg_t + (g_n + μ̄‖Δg_t‖) n]) iterated by the
/// bipotential Uzawa solver, with generalized Jacobians for a semi-smooth Newton solver.
///
/// Local frame: a LocalVector holds the normal component first, then 1 (2D, axisymmetric) or
/// 2 (3D) tangential components. Forces are tractions (kPa), jumps lengths (m).

#include <Eigen/Core>

namespace bipot::contact {

/// A vector in the interface's local frame [normal, tangential...] (size 2 or 3, no heap).
using LocalVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
/// A matrix acting on local-frame vectors (2×2 or 3×3, no heap).
using LocalMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;

/// Which branch of the projection (hence of the contact law) is active.
enum class ContactStatus {
  Open,  ///< separation: r = 0
  Stick, ///< r = τ inside (or on) the cone
  Slip   ///< r on the cone's boundary (frictionless: closed contact with free sliding)
};

/// "open", "stick", "slip".
const char* to_string(ContactStatus status);

/// Result of project_onto_cone().
struct ConeProjection {
  LocalVector r;                              ///< Proj_{K_μ̄}(τ), same units as τ
  ContactStatus status = ContactStatus::Open; ///< the branch taken
  LocalMatrix dr_dtau; ///< an element of the generalized (Clarke) Jacobian ∂r/∂τ
  LocalVector dr_dmu;  ///< ∂r/∂μ̄ in the same branch
};

/// Euclidean projection of τ = (τ_n, τ_t) onto K_μ̄ = {(r_n, r_t) : ‖r_t‖ ≤ μ̄ r_n}, μ̄ ≥ 0:
/// - stick       τ_n ≥ 0 and ‖τ_t‖ ≤ μ̄ τ_n : r = τ,
/// - separation  μ̄‖τ_t‖ ≤ −τ_n              : r = 0,
/// - slip        otherwise                   : r_n = (τ_n + μ̄‖τ_t‖)/(1+μ̄²),
///                                             r_t = μ̄ r_n τ_t/‖τ_t‖.
/// μ̄ = 0 is the half-line r_n ≥ 0, r_t = 0 (Signorini): r = (max(τ_n, 0), 0), status Slip
/// when τ_n > 0 and τ_t ≠ 0 (closed, sliding freely), Stick when τ_t = 0.
///
/// Jacobians are exact inside each branch. On a branch boundary the tests above are applied in
/// the order listed, so the Jacobian returned is the one-sided limit from that branch (I on
/// the stick/slip boundary and at the apex, 0 on the separation/slip boundary), which is an
/// element of the Clarke generalized Jacobian. No division by ‖τ_t‖ happens unless the slip
/// branch is taken, where ‖τ_t‖ > 0 is guaranteed.
ConeProjection project_onto_cone(const LocalVector& tau, double mu_bar);

/// Derivatives of bipotential_predictor() (τ is also linear in r: ∂τ/∂r = I).
struct PredictorDerivatives {
  /// ∂τ/∂[g_n, Δg_t]: column 0 w.r.t. g_n, columns 1.. w.r.t. the slip increment Δg_t (equal to
  /// the derivative w.r.t. the current g_t since Δg_t = g_t − g_t,old). At Δg_t = 0 the
  /// non-differentiable ‖Δg_t‖ contributes its subgradient 0.
  LocalMatrix dtau_djump;
  /// ∂τ/∂μ̄ = −ρ‖Δg_t‖ n.
  LocalVector dtau_dmu;
};

/// The bipotential predictor τ = r − ρ[Δg_t + (g_n + μ̄‖Δg_t‖) n] in the local frame.
/// `r`: current irreversible traction (kPa, size d); `g_n`: normal opening (m);
/// `slip_inc`: tangential slip increment Δg_t over the step (m, size d − 1); `mu_bar` ≥ 0;
/// `rho` > 0: augmentation parameter (kPa/m). Fills `derivatives` when non-null.
LocalVector bipotential_predictor(const LocalVector& r, double g_n, const LocalVector& slip_inc,
                                  double mu_bar, double rho,
                                  PredictorDerivatives* derivatives = nullptr);

} // namespace bipot::contact
