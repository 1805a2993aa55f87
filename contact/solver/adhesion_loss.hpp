#pragma once
/// What a pair's adhesion loss dissipates over one increment, for the energy account
/// (interface_energy.cpp). Point-wise: the ledger's quadrature, not the law's integration.
///
/// With Ψ = ½ β² Ẽ(g) the springs' energy (Ẽ = C_n g_n² + C_t ‖g_t‖²), the power lost as β
/// falls is D(β̇) = β Ẽ (−β̇): w (−β̇) for the adhesion itself and (β Ẽ − w)(−β̇) for its
/// viscosity (= α β̇² for RCCM). The increment's work on the springs is the trapezoidal rule,
/// second order; so must be the dissipation or the balance is only first order (a backward-
/// Euler end point, (β_new Ẽ_new − w) Δβ, leaves an error of order Δt · Δβ per step). The
/// viscous part is therefore the trapezoid of the driving force (β Ẽ − w)⁺ over the step times
/// the loss β_old − β_new; (·)⁺ because β does not move while the force is below w, which also
/// leaves the rate-independent law (β Ẽ = w on its branch) with no viscous term
/// (docs/adhesion_dissipation.md).

namespace bipot::contact {

struct AdhesionLoss {
  double adhesion = 0; ///< w (β_old − β_new), per unit area
  double viscous = 0; ///< ½ [(β Ẽ − w)⁺_old + (β Ẽ − w)⁺_new] (β_old − β_new), per unit area
};

/// w: the decohesion energy; drive_* = β Ẽ(g) at either end of the increment (−a·g/β with a
/// the adhesive traction; 0 where β = 0). Nothing when β did not fall.
AdhesionLoss adhesion_loss(double w, double beta_old, double drive_old, double beta_new,
                           double drive_new);

} // namespace bipot::contact
