#pragma once
/// The Coulomb cone projection and the De Saxcé bipotential predictor (docs/formulation.md §4):
/// the point-wise map r ↦ Proj_{K_μ̄}(r − ρ[Δg_t + (g_n + μ̄‖Δg_t‖) n]) iterated by the
/// bipotential Uzawa solver, with generalized Jacobians for a semi-smooth Newton solver.
///
/// Local frame and units: fem/core/interface_point.hpp.

#include "fem/core/interface_point.hpp"

#include <Eigen/Core>

namespace bipot::contact {

// The local-frame types and the contact branch live in the FE core, which reports them
// (fem/core/interface_point.hpp); spelled contact::X as well.
using bipot::ContactStatus;
using bipot::LocalMatrix;
using bipot::LocalVector;
using bipot::to_string;

/// Which element of the generalized Jacobian project_onto_cone() takes where τ is on the
/// stick/slip boundary to within round-off (|‖τ_t‖ − μ̄ τ_n| ≤ cone_tie_band μ̄ τ_n, τ_n > 0,
/// μ̄ > 0). Both branches give the same r there, and either Jacobian is an element of the
/// generalized one; which is right for the coming Newton step depends on its direction.
/// ByValue: the tests below decide, i.e. the last bits of τ.
enum class ConeTie { ByValue, Stick, Slip };
constexpr double cone_tie_band = 1e-12;

/// Result of project_onto_cone().
struct ConeProjection {
  LocalVector r;                              ///< Proj_{K_μ̄}(τ), same units as τ
  ContactStatus status = ContactStatus::Open; ///< the branch taken
  LocalMatrix dr_dtau; ///< an element of the generalized (Clarke) Jacobian ∂r/∂τ
  LocalVector dr_dmu;  ///< ∂r/∂μ̄ in the same branch
  bool tie = false;    ///< τ within cone_tie_band of the stick/slip boundary (ConeTie)
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
/// branch is taken, where ‖τ_t‖ > 0 is guaranteed. At a tie, `tie` other than ByValue picks
/// the branch instead.
ConeProjection project_onto_cone(const LocalVector& tau, double mu_bar,
                                 ConeTie tie = ConeTie::ByValue);

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
