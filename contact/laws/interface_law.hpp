#pragma once
/// Abstract point-wise interface law and the point-wise map iterated by the contact solvers.
/// Conventions (docs/formulation.md §1–4): local frame [normal, tangential...]; jump g = u_2 − u_1
/// with g_n ≥ 0 admissible; t is the traction body 1 exerts on body 2, compression positive,
///     t = r − β² (C_n g_n n + C_t g_t),
/// where r (contact pressure p = r_n ≥ 0 and friction r_t) lies in the Coulomb cone K_μ̄.
/// Units: jumps m, tractions kPa, interface stiffnesses kN/m³, pseudo-time s.

#include "contact/laws/coulomb_cone.hpp"

#include <optional>
#include <string>

namespace bipot::contact {

/// A law of the interface between two bodies at one point. Pure point-wise code: kinematics and
/// converged old state in, traction, derivatives and new state out. The base-class defaults
/// describe a law without adhesion (β ≡ 0, no adhesive traction).
class InterfaceLaw {
public:
  virtual ~InterfaceLaw() = default;

  /// The YAML name (also the file stem).
  virtual std::string name() const = 0;

  /// Perfect bonding: the solver eliminates the jump exactly (constraint elimination, g = 0)
  /// and never calls the point-wise functions below.
  virtual bool is_tied() const { return false; }

  /// β0, the adhesion intensity of the sound interface at the start (0 without adhesion).
  virtual double initial_adhesion() const { return 0.0; }

  /// New adhesion intensity β ∈ [0, β_old] after a pseudo-time step `dtau` (s) ending with the
  /// jump `jump` = [g_n, g_t...] (m) (docs/formulation.md §3, implicit Euler). Fills
  /// `*dbeta_djump` (1/m, size of `jump`) with ∂β/∂jump, zero where β stays at β_old.
  virtual double update_adhesion(double beta_old, const LocalVector& jump, double dtau,
                                 LocalVector* dbeta_djump = nullptr) const;

  /// Reversible (adhesive) traction −β² [C_n g_n, C_t g_t] (kPa) for the jump (m); fills
  /// `*dt_djump` (kN/m³) with its derivative at fixed β.
  virtual LocalVector adhesive_traction(double beta, const LocalVector& jump,
                                        LocalMatrix* dt_djump = nullptr) const;

  /// ∂(adhesive_traction)/∂β at fixed jump (kPa).
  virtual LocalVector adhesive_traction_dbeta(double beta, const LocalVector& jump) const;

  /// Effective friction coefficient μ̄(β) of the Coulomb cone (dimensionless).
  virtual double friction_coefficient(double beta) const = 0;

  /// dμ̄/dβ.
  virtual double friction_coefficient_dbeta(double /*beta*/) const { return 0.0; }

  /// A representative interface stiffness (kN/m³) solvers use to pick ρ automatically; 0 when
  /// the law has none.
  virtual double stiffness_scale() const { return 0.0; }

  /// Energy per area (kJ/m²) that adhesion loss can still dissipate from intensity β (0 for
  /// a law without adhesion), linear in β: what a dissipation-controlled step measures.
  virtual double adhesion_energy(double /*beta*/) const { return 0.0; }

  /// The work −∫ a·dg (kJ/m²) done on the adhesive springs a = adhesive_traction(β, g) while
  /// the jump goes from `from` to `to` in a straight line, β starting at `beta_old` and
  /// following the law along the way; std::nullopt where the end states do not determine it
  /// (a rate-dependent β) or the law does not know it. The energy ledger integrates the
  /// springs' share of the external work by it (docs/energy_quadrature.md).
  virtual std::optional<double> spring_work(double /*beta_old*/, const LocalVector& /*from*/,
                                            const LocalVector& /*to*/) const {
    return std::nullopt;
  }
};

/// Converged values at one interface point at the end of the previous step.
struct InterfaceState {
  double beta = 0.0; ///< adhesion intensity β ∈ [0, 1]
  LocalVector jump;  ///< [g_n, g_t...] (m)
  LocalVector r;     ///< irreversible traction [p, r_t...] (kPa)
};

/// The state before the first step: β = β0, zero jump and r; `local_size` is 2 or 3.
InterfaceState initial_state(const InterfaceLaw& law, int local_size);

/// Result of evaluate().
struct InterfaceResponse {
  double beta = 0.0;    ///< new adhesion intensity
  double mu_bar = 0.0;  ///< friction coefficient μ̄(β) of the cone used
  LocalVector tau;      ///< bipotential predictor τ (kPa)
  LocalVector r;        ///< Proj_{K_μ̄}(τ) (kPa)
  LocalVector traction; ///< total traction t = r + adhesive_traction(β, jump) (kPa)
  ContactStatus status = ContactStatus::Open;
  bool tie = false; ///< τ on the stick/slip boundary to within round-off (ConeTie)
};

/// Derivatives of evaluate() for a semi-smooth Newton solver (generalized Jacobians).
struct InterfaceResponseDerivatives {
  LocalVector dbeta_djump; ///< ∂β/∂jump (1/m)
  LocalMatrix dr_djump;    ///< ∂r/∂jump at fixed input r (kPa/m)
  LocalMatrix dr_dr;       ///< ∂r/∂(input r), = ∂Proj/∂τ
  LocalMatrix dt_djump;    ///< ∂t/∂jump at fixed input r (kPa/m)
  LocalMatrix dt_dr;       ///< ∂t/∂(input r), = ∂Proj/∂τ
};

/// The point-wise map the bipotential solvers iterate (docs/formulation.md §4): for the current
/// jump (m) and irreversible traction `r` (kPa), with `old` the converged previous step,
///   β = update_adhesion(old.beta, jump, dtau),  μ̄ = friction_coefficient(β),
///   τ = r − ρ[Δg_t + (g_n + μ̄‖Δg_t‖) n] with Δg_t = g_t − old.g_t,
///   r_new = Proj_{K_μ̄}(τ),  t = r_new − β²(C_n g_n n + C_t g_t).
/// `dtau` is the pseudo-time step (s), `rho` > 0 the augmentation parameter (kPa/m). Its fixed
/// points r_new = r are exactly the solutions of the interface law. Fills `derivatives` when
/// non-null; `tie` picks the branch where τ is on the stick/slip boundary to within round-off
/// (project_onto_cone()). A tied law gives evaluate_tie().
InterfaceResponse evaluate(const InterfaceLaw& law, const InterfaceState& old,
                           const LocalVector& jump, const LocalVector& r, double dtau, double rho,
                           InterfaceResponseDerivatives* derivatives = nullptr,
                           ConeTie tie = ConeTie::ByValue);

/// The map of a tied law (perfect bonding) on a split pair: the augmented Lagrangian of the
/// equality jump = old.jump (docs/theory.md, "Interface changes between stages"),
///   τ = r − ρ (jump − old.jump),  r_new = τ,  t = r_new,  β = 1, status stick,
/// whose fixed point r_new = r holds the jump exactly, with r the traction that does it.
InterfaceResponse evaluate_tie(const InterfaceState& old, const LocalVector& jump,
                               const LocalVector& r, double rho,
                               InterfaceResponseDerivatives* derivatives = nullptr);

} // namespace bipot::contact
