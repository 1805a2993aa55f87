#pragma once
/// Node-to-node interface forces and tangents for one interface (docs/formulation.md §1–5).
///
/// For pair i with weight A_i and local frame Q_i = [n, t1 (, t2)] (columns), the local jump
/// is ĝ = Q_iᵀ (u_b − u_a) + g0 n, g0 = the interface's initial gap + the pair's gap; the
/// law's point-wise map gives the traction t (local) that body 1 (node a) exerts on body 2
/// (node b): nodal force A_i Q_i t on b and −A_i Q_i t on a.
/// The tangent uses ∂t/∂ĝ at fixed multiplier r̂ (the projection's generalized Jacobian and
/// the implicit β update). Every rank evaluates every pair (interfaces are small next to the
/// bulk) so all ranks hold the whole interface state; each rank assembles the pairs whose
/// node a it owns.
/// Against a rigid obstacle (node_b = rigid_obstacle) u_b is the obstacle's displacement,
/// data set per increment (set_obstacle_displacement()); only node a's block is assembled.

#include "contact/interface/interface_mesh.hpp"
#include "contact/laws/frozen_adhesion.hpp"
#include "contact/laws/interface_law.hpp"
#include "contact/solver/contact_solver_options.hpp"
#include "fem/assembly/constraints.hpp"
#include "fem/assembly/dof_map.hpp"
#include "fem/assembly/rigid_body_constraint.hpp"

#include <vector>

namespace bipot {
class SparseMatrix;
class SparsityPattern;
class DistributedVector;
class DofDistribution;
} // namespace bipot

namespace bipot::contact {

/// What a pair looks like after an evaluation (output, tests).
struct PairResult {
  double beta = 0;
  LocalVector jump;     ///< [g_n, g_t...] (m)
  LocalVector r;        ///< irreversible part [p, r_t...] (kPa)
  LocalVector traction; ///< total t (kPa)
  ContactStatus status = ContactStatus::Open;
};

/// Status of a pair as the outputs report it (VTK `status` codes, profile names): while its
/// adhesion is active (β > 0; tied pairs have β = 1) a pair is Bonded whatever branch the
/// projection took — with μ̄ = μ(1 − β), a sound bond under shear sits on the frictionless
/// "slip" branch although nothing slides. Otherwise its contact branch
/// (docs/formulation.md §4).
enum class PairStatus { Open = 0, Stick = 1, Slip = 2, Bonded = 3 };

/// Bonded when result.beta > 0, else result.status.
PairStatus reported_status(const PairResult& result);

/// "open", "stick", "slip", "bonded".
const char* to_string(PairStatus status);

class InterfaceAssembler {
public:
  /// `law` is not owned. Pairs with node_a == node_b (perfect bonding) are not assembled.
  InterfaceAssembler(const Interface& iface, const InterfaceLaw& law, const DofMap& dofs,
                     const DofDistribution& dist);

  const Interface& interface() const { return iface_; }
  /// Rigid bodies (not owned, null for none): pairs on a body's nodes put their blocks on
  /// its reference node (the augmented-Lagrangian solvers; generalized_newton refuses them).
  void set_rigid_bodies(const RigidBodyConstraints* rigid) { rigid_ = rigid; }
  const InterfaceLaw& law() const { return law_; }
  bool tied() const { return law_.is_tied(); }
  std::size_t num_pairs() const { return iface_.pairs.size(); }

  /// Adds the [a, b] DOF block of every owned pair.
  void add_to_pattern(SparsityPattern& pattern) const;
  /// Chooses ρ per pair: the option's value if given, else factor × (the law's stiffness
  /// scale, or 1/(A_i W_ii) from the bulk diagonal `diagonal_all` of all DOFs).
  void set_augmentation(const ContactSolverOptions& options,
                        const std::vector<double>& diagonal_all);

  /// Starts an increment: multipliers r̂ from the committed state, extrapolated along the
  /// last committed increment by `extrapolation` (= this increment's size / the last one's;
  /// 0 at the start of a stage). Only the starting guess changes, not the solution: under
  /// proportional loading it is already the converged r̂, which saves the augmented
  /// Lagrangian updates that would otherwise converge to it linearly.
  void begin_increment(double extrapolation = 0.0);
  /// Evaluates every pair at `u` (all DOFs) with the current multipliers r̂: β, traction,
  /// Proj(τ), status, tangent. Pseudo-time step `dtau` (s).
  void evaluate(const std::vector<double>& u, double dtau);
  /// Adds the owned pairs' condensed contributions of the last evaluation to R (and K if
  /// not null).
  void add_to_system(const Constraints& constraints, SparseMatrix* K, DistributedVector& R) const;
  /// max_i A_i ‖Proj(τ_i) − r̂_i‖ of the last evaluation (kN): how far the multipliers are
  /// from the bipotential fixed point.
  double multiplier_change() const { return multiplier_change_; }
  /// r̂ ← Proj(τ) of the last evaluation (the Uzawa corrector).
  void update_multipliers();
  /// True when the interface tangent of the last evaluation differs from the one last put
  /// into a matrix (then the matrix must be rebuilt).
  bool tangent_changed() const { return tangent_changed_; }
  /// Records the current tangent as the one in the matrix.
  void mark_tangent_assembled();
  /// Accepts the last evaluation as the converged state of the increment.
  void commit();
  /// Tied interfaces (perfect bonding), for output: `force_all` holds, for every DOF, the
  /// force body 1 exerts on body 2 at shared nodes (the caller computes it from body 1's
  /// cells: minus their internal force plus their body forces). Sets each pair's traction
  /// Qᵀ F / A_i (kPa; r = traction, p = its normal part, compression positive), β = 1,
  /// status stick (reported as bonded: reported_status()), and the resultant.
  void set_tied_forces(const std::vector<double>& force_all);
  /// Staggered fallback: evaluate() holds each pair's β at `beta` (no adhesion update, the
  /// law wrapped in FrozenAdhesion) until unfreeze_adhesion().
  void freeze_adhesion(const std::vector<double>& beta);
  void unfreeze_adhesion() { frozen_ = false; }
  /// β of every pair at the start of the increment (the committed state).
  std::vector<double> committed_adhesion() const;
  /// β the law gives at `u` from the committed state over a step `dtau` (the staggered
  /// update), per pair.
  std::vector<double> adhesion_at(const std::vector<double>& u, double dtau) const;
  /// Displacement reset keeping forces (geostatic stage): the current jumps become an
  /// offset, so that after the caller zeroes u the interface sees the same jumps.
  void absorb_displacements();
  /// Extra normal offset (m) added to every pair's g_n on top of the initial gap: a stage
  /// ramps it to prescribe an opening (> 0) or an interference (< 0), e.g. the radial
  /// expansion of a pile shaft at installation. Kept through displacement resets.
  void set_gap_shift(double shift) { gap_shift_ = shift; }
  double gap_shift() const { return gap_shift_; }
  /// Obstacle interfaces: the rigid translation (m, global components, 0 beyond dim) of the
  /// obstacle, i.e. u_b of every pair. Zeroed by absorb_displacements() (its jumps are kept).
  void set_obstacle_displacement(const std::array<double, 3>& u) { obstacle_u_ = u; }
  const std::array<double, 3>& obstacle_displacement() const { return obstacle_u_; }

  /// Last evaluation of every pair.
  const std::vector<PairResult>& results() const { return results_; }
  /// Generalized derivatives of the last evaluation of pair `i` (local frame), for the exact
  /// generalized Newton (InterfaceNewtonSystem).
  const InterfaceResponseDerivatives& derivatives(std::size_t i) const { return derivatives_[i]; }
  /// The multipliers r̂ the next evaluate() uses (local frame, kPa), one per pair.
  const std::vector<LocalVector>& multipliers() const { return multiplier_; }
  void set_multipliers(const std::vector<LocalVector>& r) { multiplier_ = r; }
  /// Local frame Q_i = [n, t1 (, t2)] of pair `i` (dim × dim, columns).
  LocalMatrix frame(std::size_t i) const;
  /// Resultant force body 1 exerts on body 2 (kN, global components), last evaluation.
  std::array<double, 3> resultant() const;
  /// Largest A_i ‖t_i‖ (kN): a force scale for convergence checks.
  double force_scale() const;
  /// Round-off in the interface forces of the last evaluation (kN, a 2-norm over pairs):
  /// A_i ρ_i ĝ_i takes the difference of two displacements of size ‖u‖, so it carries an
  /// error of about ε A_i ρ_i ‖u‖ that no iteration can remove. Grows with ρ.
  double roundoff_force() const { return roundoff_force_; }

private:
  LocalVector local_jump(std::size_t pair, const std::vector<double>& u) const;
  /// Component c of body 2's displacement at pair p: node b's, or the obstacle's.
  double u_b(const InterfacePair& p, int c, const std::vector<double>& u) const;

  const Interface& iface_;
  const InterfaceLaw& law_;
  const DofMap& dofs_;
  const RigidBodyConstraints* rigid_ = nullptr;
  int dim_;
  std::vector<bool> owned_;
  std::vector<double> rho_;
  std::vector<InterfaceState> committed_;
  std::vector<LocalVector> previous_r_; ///< r of the increment before the committed one
  std::vector<LocalVector> multiplier_;
  std::vector<PairResult> results_;
  std::vector<LocalMatrix> tangent_, assembled_tangent_;
  std::vector<InterfaceResponseDerivatives> derivatives_;
  std::vector<Eigen::Vector3d> force_; ///< A_i Q_i t_i, global components (padded to 3)
  std::vector<LocalVector> offset_;    ///< jump kept through displacement resets
  double multiplier_change_ = 0;
  double roundoff_force_ = 0;
  double gap_shift_ = 0;
  std::array<double, 3> obstacle_u_{0, 0, 0};
  FrozenAdhesion frozen_law_;
  bool frozen_ = false;
  std::vector<double> frozen_beta_;
  bool tangent_changed_ = true;
};

} // namespace bipot::contact
