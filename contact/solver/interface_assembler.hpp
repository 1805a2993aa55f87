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
/// Bodies tied by shared nodes are the other enforcement, TiedInterface (tied_interface.hpp).

#include "contact/interface/interface_mesh.hpp"
#include "contact/laws/frozen_adhesion.hpp"
#include "contact/laws/interface_law.hpp"
#include "contact/solver/contact_solver_options.hpp"
#include "fem/assembly/constraints.hpp"
#include "fem/assembly/dof_map.hpp"
#include "fem/assembly/interface_enforcement.hpp"
#include "fem/assembly/rigid_body_constraint.hpp"
#include "fem/core/state_arrays.hpp"

#include <optional>
#include <vector>

namespace bipot {
class SparseMatrix;
class SparsityPattern;
class DistributedVector;
class DofDistribution;
} // namespace bipot

namespace bipot::contact {

// The output vocabulary lives in the FE core (fem/assembly/interface_enforcement.hpp);
// spelled contact::X as well.
using bipot::PairResult;
using bipot::PairStatus;
using bipot::reported_status;
using bipot::to_string;

/// A law a stage puts in force on an interface (stage `interfaces:`), not owned.
struct StageLaw {
  std::size_t stage = 0;
  const InterfaceLaw* law = nullptr;
};

class InterfaceAssembler final : public InterfaceEnforcement {
public:
  /// `law` and the stage laws are not owned. The interface's pairs must be split (distinct
  /// nodes, or an obstacle): bodies sharing nodes are a TiedInterface. A tied law on split
  /// pairs holds their jumps (evaluate_tie()). `options` give ρ (set_augmentation()).
  InterfaceAssembler(const Interface& iface, const InterfaceLaw& law, const DofMap& dofs,
                     const DofDistribution& dist, ContactSolverOptions options = {},
                     std::vector<StageLaw> stage_laws = {});

  const Interface& interface() const { return iface_; }
  const std::string& name() const override { return iface_.name; }
  std::size_t num_pairs() const override { return iface_.pairs.size(); }
  const InterfaceLaw& law() const { return *law_; }
  /// Puts `law` (not owned) in force from the next increment on (a stage's law change). The
  /// committed state carries over (docs/theory.md): jumps, slips and multipliers r̂ (a
  /// predictor for the new law) as they are; β becomes min(β, the new law's β0), and 1 under
  /// a tied law, which holds each pair's jump where it is. The energy account books the
  /// springs' change and starts the next step from the new law's (rebase_energy_account()).
  void set_law(const InterfaceLaw& law);
  /// set_law() with the law of stage `stage` among the stage laws, if it names one.
  bool enter_stage(std::size_t stage) override;

  bool acts_on_system() const override { return true; }
  /// Adds the [a, b] DOF block of every owned pair.
  void add_to_pattern(SparsityPattern& pattern) const override;
  /// Pairs on a rigid body's nodes put their blocks on its reference node (the
  /// augmented-Lagrangian solvers; generalized_newton refuses rigid bodies).
  void set_rigid_bodies(const RigidBodyConstraints* rigid) override { rigid_ = rigid; }
  /// Chooses ρ per pair: the options' value if given, else factor × (the law's stiffness
  /// scale, or 1/(A_i W_ii) from the bulk diagonal `diagonal_all` of all DOFs).
  void set_augmentation(const std::vector<double>& diagonal_all) override;

  /// Starts an increment: multipliers r̂ from the committed state, extrapolated along the last
  /// committed increment by `extrapolation` (= this increment's size / the last one's; 0 at
  /// the start of a stage). Only the starting guess changes, not the solution: under
  /// proportional loading it is already the converged r̂, which saves the augmented
  /// Lagrangian updates that would otherwise converge to it linearly.
  void begin_increment(double extrapolation = 0.0) override;
  /// Evaluates every pair at `u` (all DOFs) with the current multipliers r̂: β, traction,
  /// Proj(τ), status, tangent. Pseudo-time step `dtau` (s).
  void evaluate(const std::vector<double>& u, double dtau) override;
  /// Adds the owned pairs' condensed contributions of the last evaluation to R (and K if not
  /// null).
  void add_to_system(const Constraints& constraints, SparseMatrix* K,
                     DistributedVector& R) const override;
  /// max_i A_i ‖Proj(τ_i) − r̂_i‖ of the last evaluation (kN): how far the multipliers are
  /// from the bipotential fixed point.
  double multiplier_change() const override { return multiplier_change_; }
  /// r̂ ← Proj(τ) of the last evaluation (the Uzawa corrector).
  void update_multipliers() override;
  bool tangent_changed() const override { return tangent_changed_; }
  void mark_tangent_assembled() override;
  void commit() override;
  /// Largest A_i ‖t_i‖ (kN).
  double force_scale() const override;
  /// Round-off in the interface forces of the last evaluation (kN, a 2-norm over pairs):
  /// A_i ρ_i ĝ_i takes the difference of two displacements of size ‖u‖, so it carries an
  /// error of about ε A_i ρ_i ‖u‖ that no iteration can remove. Grows with ρ.
  double roundoff_force() const override { return roundoff_force_; }

  /// β > 0 somewhere under a law that is not tied.
  bool adhesion_can_change() const override;
  std::vector<double> committed_adhesion() const override;
  std::vector<double> adhesion_at(const std::vector<double>& u, double dtau) const override;
  /// evaluate() holds each pair's β at `beta` (no adhesion update, the law wrapped in
  /// FrozenAdhesion) until unfreeze_adhesion().
  void freeze_adhesion(const std::vector<double>& beta) override;
  void unfreeze_adhesion() override { frozen_ = false; }
  /// Σ A_i w(β_i), w the law's adhesion_energy.
  double adhesion_capacity() const override;

  /// Extra normal offset (m) added to every pair's g_n on top of the initial gap: a stage
  /// ramps it to prescribe an opening (> 0) or an interference (< 0), e.g. the radial
  /// expansion of a pile shaft at installation. Kept through displacement resets.
  void set_gap_shift(double shift) override { gap_shift_ = shift; }
  double gap_shift() const override { return gap_shift_; }
  bool has_obstacle() const override { return iface_.obstacle; }
  /// Obstacle interfaces: the rigid translation of the obstacle, i.e. u_b of every pair.
  /// Zeroed by absorb_displacements() (its jumps are kept).
  void set_obstacle_displacement(const std::array<double, 3>& u) override { obstacle_u_ = u; }
  std::array<double, 3> obstacle_displacement() const override { return obstacle_u_; }
  /// The current jumps become an offset, so that after the caller zeroes u the interface
  /// sees the same jumps.
  void absorb_displacements() override;

  /// The committed state (interface_state.cpp): per pair β, jump, r, the r of the increment
  /// before, the multipliers, the offsets kept through displacement resets and ρ; the gap
  /// shift. The law in force is not in it (a stage's `interfaces:` gives it).
  StateArrays save_state() const override;
  /// Restores save_state()'s arrays; the last evaluation becomes the committed state.
  void load_state(const StateArrays& state) override;

  /// The energy account (interface_energy.cpp): every pair's jump, traction, r and β at the
  /// last recorded step, and the gap shift and obstacle position then.
  void start_energy_account() override;
  void record_energy(InterfaceEnergy& energy) override;
  std::vector<double> save_energy_account() const override;
  void load_energy_account(const std::vector<double>& values) override;

  std::array<double, 3> resultant() const override;
  const std::vector<PairResult>& results() const override { return results_; }

  /// Generalized derivatives of the last evaluation of pair `i` (local frame), for the exact
  /// generalized Newton (InterfaceNewtonSystem).
  const InterfaceResponseDerivatives& derivatives(std::size_t i) const { return derivatives_[i]; }
  /// The multipliers r̂ the next evaluate() uses (local frame, kPa), one per pair.
  const std::vector<LocalVector>& multipliers() const { return multiplier_; }
  void set_multipliers(const std::vector<LocalVector>& r) { multiplier_ = r; }
  /// Local frame Q_i = [n, t1 (, t2)] of pair `i` (dim × dim, columns).
  LocalMatrix frame(std::size_t i) const;
  /// The branch each pair takes at the next evaluate()s of this increment where its τ is on
  /// the stick/slip boundary to within round-off (ConeTie; one per pair, begin_increment()
  /// forgets them). Returns whether a pair at such a tie in the last evaluate() took the
  /// other branch.
  bool set_tie_hints(std::vector<ConeTie> hints);
  /// Whether this increment started from multipliers extrapolated along the last one.
  bool predicted() const { return predicted_; }

private:
  LocalVector local_jump(std::size_t pair, const std::vector<double>& u) const;
  /// Component c of body 2's displacement at pair p: node b's, or the obstacle's.
  double u_b(const InterfacePair& p, int c, const std::vector<double>& u) const;

  /// What the energy account remembers of a pair.
  struct AccountedPair {
    LocalVector jump, traction, r;
    double beta = 0;
    /// The state before (jump and adhesive traction): the three-point rule's stencil; the
    /// last step's regime and for how many steps it has held: its kink test
    /// (spring_work_correction.hpp).
    LocalVector prev_jump, prev_adhesive;
    int regime = -1, regime_steps = 0;
  };
  /// After set_law(): the energy account's start of the next step under the new law
  /// (interface_energy.cpp).
  void rebase_energy_account();

  const Interface& iface_;
  const InterfaceLaw* law_;
  ContactSolverOptions options_;
  std::vector<StageLaw> stage_laws_;
  const DofMap& dofs_;
  const RigidBodyConstraints* rigid_ = nullptr;
  int dim_;
  std::vector<bool> owned_;
  std::vector<double> rho_;
  std::vector<InterfaceState> committed_;
  std::vector<LocalVector> previous_r_; ///< r of the increment before the committed one
  std::vector<LocalVector> multiplier_;
  std::vector<ConeTie> tie_hint_; ///< empty: the projection's own tests decide ties
  std::vector<char> at_tie_;      ///< τ on the stick/slip boundary at the last evaluate()
  bool predicted_ = false;        ///< the increment's multipliers were extrapolated
  std::vector<PairResult> results_;
  std::vector<LocalMatrix> tangent_, assembled_tangent_;
  std::vector<InterfaceResponseDerivatives> derivatives_;
  std::vector<Eigen::Vector3d> force_; ///< A_i Q_i t_i, global components (padded to 3)
  std::vector<LocalVector> offset_;    ///< jump kept through displacement resets
  double multiplier_change_ = 0;
  double roundoff_force_ = 0;
  double gap_shift_ = 0;
  std::array<double, 3> obstacle_u_{0, 0, 0};
  std::optional<FrozenAdhesion> frozen_law_;
  bool frozen_ = false;
  std::vector<double> frozen_beta_;
  bool tangent_changed_ = true;
  std::vector<AccountedPair> accounted_;
  bool account_recorded_ = false; ///< a step was recorded (or an account loaded)
  /// Change of the springs' energy by a law change, booked with the next step's interference
  /// work.
  double law_change_work_ = 0;
  double accounted_shift_ = 0;
  std::array<double, 3> accounted_obstacle_{0, 0, 0};
  /// Consecutive recorded states, up to the last, joined by steps on which no interference
  /// moved and no law changed (at most 3): the rule needs 3 before the step it integrates.
  int smooth_states_ = 1;
};

} // namespace bipot::contact
