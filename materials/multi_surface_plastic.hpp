#pragma once
/// Implicit return onto yield surfaces that are planes in ordered principal stress space
/// (σ1 ≥ σ2 ≥ σ3, tension positive), shared by mohr_coulomb and tresca.
///
/// Surface i: f_i = n_i·σ − (k_i + h_i κ) ≤ 0, plastic flow Δεp = Σ Δλ_i m_i (principal
/// components), hardening Δκ = Σ w_i Δλ_i. With the principal directions fixed (isotropy),
/// the return from the trial σ* for an active set A is linear:
///   σ = σ* − C Σ_{i∈A} Δλ_i m_i,   M Δλ = f_A(σ*, κ_n),   M_ji = n_j·C m_i + h_j w_i,
/// C = λ 1⊗1 + 2G I the principal elasticity. The candidate sets are tried in the order
/// given; the first whose Δλ ≥ 0, whose stress is ordered and on or inside every surface is
/// the solution (it satisfies the discrete Kuhn–Tucker conditions). Its Jacobian
///   ∂σ/∂σ* = I − C M_A M⁻¹ N_Aᵀ
/// is exact for the linear return; the rotation of the principal directions is added by
/// isotropic_jacobian(). (de Souza Neto, Perić & Owen 2008, §8.2; Clausen, Damkilde &
/// Andersen 2006, "Efficient return algorithms for associated plasticity with multiple yield
/// planes", IJNME 66.)

#include "materials/elasto_plastic.hpp"

#include <vector>

namespace bipot {

struct PrincipalSurface {
  Vec3 normal;             ///< n: ∂f/∂σ in principal components
  Vec3 flow;               ///< m: ∂g/∂σ of the plastic potential
  double strength;         ///< k (kPa)
  double hardening;        ///< h: ∂(strength)/∂κ (kPa)
  double hardening_weight; ///< w: Δκ = w Δλ
};

/// A candidate active set: indices into the surfaces (at most 3) and the branch code the
/// material reports when it is taken. Several sets may share a code: where four planes meet
/// at a point (e.g. σ1 = σ2 = σt on the Mohr–Coulomb surface) the flow is any non-negative
/// combination of four vectors in 3D, which is the union of the cones of its 3-vector
/// subsets (Carathéodory), so each subset is one candidate.
struct ActiveSet {
  std::vector<int> surfaces;
  int branch;
};

struct PrincipalResult {
  int set = -1;  ///< index of the accepted candidate set, -1 = none admissible
  Vec3 stress;   ///< ordered principal stresses after the return
  Mat3 jacobian; ///< ∂σ/∂σ* in principal components
  double hardening_increment = 0.0;
};

/// Tries the candidate active sets in order; `lambda`, `G` are the
/// Lamé constants. Sets whose matrix M is singular are skipped (e.g. the apex without
/// dilatancy, where no plastic flow can change the mean stress).
PrincipalResult principal_return(const Vec3& trial, double kappa,
                                 const std::vector<PrincipalSurface>& surfaces,
                                 const std::vector<ActiveSet>& candidate_sets, double lambda,
                                 double G);

/// max_i f_i(σ, κ) over the surfaces, for ordered principal stresses σ.
double max_yield(const Vec3& stress, double kappa, const std::vector<PrincipalSurface>& surfaces);

/// An ElastoPlastic material whose yield surfaces are planes in principal stress space
/// (mohr_coulomb, tresca): the derived class only lists the surfaces and the candidate sets;
/// this class does the spectral decomposition, principal_return() and the tangent with the
/// rotation of the principal directions.
class MultiSurfacePlastic : public ElastoPlastic {
public:
  Return return_stress(const Mat3& trial, double kappa) const override;
  double yield_function(const Mat3& stress, double kappa) const override;

protected:
  using ElastoPlastic::ElastoPlastic;
  /// Sets the surfaces and candidate active sets. `apex_stress`, if finite, is the mean
  /// stress of a vertex every surface passes through, used when no candidate set is
  /// admissible and the trial's mean stress is at or beyond it (no dilatancy: no flow can
  /// change the mean stress, so the return is the vertex itself and the volumetric
  /// difference is plastic); such a return reports branch code `apex_branch`, with a zero
  /// Jacobian. Any other failure throws SolverError with the trial principal stresses.
  void set_surfaces(std::vector<PrincipalSurface> surfaces, std::vector<ActiveSet> sets,
                    double apex_stress, int apex_branch);

private:
  std::vector<PrincipalSurface> surfaces_;
  std::vector<ActiveSet> sets_;
  double apex_stress_ = 0.0;
  int apex_branch_ = -1;
};

} // namespace bipot
