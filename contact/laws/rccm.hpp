#pragma once
/// RCCM adhesive interface (Raous–Cangémi–Cocu–Monerie): unilateral contact, Coulomb friction
/// and adhesion coupled through the adhesion intensity β ∈ [0, 1].

#include "contact/laws/interface_law.hpp"
#include "fem/core/parameter_binding.hpp"

namespace bipot::contact {

/// RCCM law. With jump g = (g_n, g_t), traction t = r − β²(C_n g_n n + C_t g_t) (body 1 on
/// body 2, compression positive; docs/formulation.md §1–3):
/// - Signorini with adhesion: g_n ≥ 0, p = r_n ≥ 0, p g_n = 0;
/// - Coulomb with adhesion: ‖r_t‖ ≤ μ̄ p with μ̄ = μ(1 − β); stick (Δg_t = 0) inside the cone,
///   r_t = −μ̄ p Δg_t/‖Δg_t‖ on its boundary;
/// - adhesion, never healing: α β̇ = −⟨E β − w⟩₊, E = C_n ⟨g_n⟩₊² + C_t ‖g_t‖², integrated by
///   implicit Euler over the pseudo-time step Δτ:
///     β⁺ = min(β, (β + w Δτ/α)/(1 + E Δτ/α))      (α > 0),
///     β⁺ = min(β, w/E)  (β⁺ = β when E = 0)        (α = 0, quasi-static limit).
/// Monotonic quasi-static opening from β0 = 1 gives t_n = −C_n g_n up to g* = √(w/C_n), then
/// −w²/(C_n g_n³): peak √(w C_n), work of separation w.
///
/// The seed paper (Terfaya, Raous, Berga 2010, eqs. (3)–(9), (20)–(22)) writes the normal gap
/// with the opposite sign (u_n ≤ 0 admissible), keeps a general h(β) in the free energy (here
/// h(β) = β, which gives ⟨E β − w⟩₊) and writes the predictor with velocities; the signs and
/// increments of docs/formulation.md are used here.
/// References: M. Raous, L. Cangémi, M. Cocu, "A consistent model coupling adhesion, friction
/// and unilateral contact", Comput. Methods Appl. Mech. Engrg. 177 (1999) 383–399;
/// M. Raous, Y. Monerie, "Unilateral contact, friction and adhesion in composite materials",
/// in J. Martins, M. Marques (eds), Contact Mechanics, Kluwer (2002) 333–346.
class Rccm : public InterfaceLaw {
public:
  /// C_n, C_t, w, μ, α, β0 (units and ranges in schema()).
  struct Parameters {
    double normal_stiffness = 0;     ///< C_n (kN/m³)
    double tangential_stiffness = 0; ///< C_t (kN/m³)
    double decohesion_energy = 0;    ///< w (kJ/m²)
    double friction_coefficient = 0; ///< μ
    double adhesion_viscosity = 0;   ///< α (kN·s/m)
    double initial_adhesion = 1;     ///< β0
  };
  static ParamSchemaOf<Parameters> schema();

  /// Validates `p` through schema(): throws InputError with the input file's messages.
  explicit Rccm(const Parameters& p) : Rccm(schema().checked(p)) {}
  explicit Rccm(Checked<Parameters> p);

  std::string name() const override { return "rccm"; }
  double initial_adhesion() const override { return beta0_; }
  double update_adhesion(double beta_old, const LocalVector& jump, double dtau,
                         LocalVector* dbeta_djump = nullptr) const override;
  LocalVector adhesive_traction(double beta, const LocalVector& jump,
                                LocalMatrix* dt_djump = nullptr) const override;
  LocalVector adhesive_traction_dbeta(double beta, const LocalVector& jump) const override;
  /// μ̄ = μ(1 − β).
  double friction_coefficient(double beta) const override { return mu_ * (1.0 - beta); }
  double friction_coefficient_dbeta(double) const override { return -mu_; }
  /// max(C_n, C_t).
  double stiffness_scale() const override;
  /// Without viscosity (α = 0): β = min(β_old, w/max Ẽ) along the path, so the work
  /// ∫ β² d(½ Ẽ) (+ the compressed normal spring's, Ẽ counting ⟨g_n⟩₊ only) depends on Ẽ's end
  /// values alone wherever Ẽ rises while above the threshold w/β_old, as on any straight line
  /// (Ẽ is convex): ½ β_old² (Ẽ* − Ẽ_0) + ½ w (β_old − w/Ẽ_1) past it, a kink the trapezoid
  /// misses. The normal spring in penetration (⟨g_n⟩₋, within the contact tolerance) by the
  /// trapezoid in β² where β may fall meanwhile. std::nullopt with a viscosity, or from a
  /// state above the threshold (not on the law's branch, e.g. after a law change).
  std::optional<double> spring_work(double beta_old, const LocalVector& from,
                                    const LocalVector& to) const override;

  double normal_stiffness() const { return cn_; }     ///< C_n (kN/m³)
  double tangential_stiffness() const { return ct_; } ///< C_t (kN/m³)
  double decohesion_energy() const { return w_; }     ///< w (kJ/m²)
  /// w β: the work of separation of the quasi-static law from β to 0 (docs/laws/rccm.md).
  double adhesion_energy(double beta) const override { return w_ * beta; }
  double adhesion_viscosity() const { return alpha_; } ///< α (kN·s/m)

private:
  /// Ẽ = C_n ⟨g_n⟩₊² + C_t ‖g_t‖², the energy that drives β down.
  double driving_energy(const LocalVector& jump) const;

  double cn_, ct_, w_, mu_, alpha_, beta0_;
};

} // namespace bipot::contact
