#pragma once
/// An interface between bodies as the analysis drives it: what it adds to the global system
/// at a displacement, the state it commits, and what it reports. The FE core knows interfaces
/// only through this class; the contact module implements it (contact/solver: the
/// bipotential/RCCM family on split pairs, InterfaceAssembler, and exact tying by shared
/// nodes, TiedInterface), as FEBio separates a law from its enforcement.
///
/// Every rank holds the whole interface state (interfaces are small next to the bulk); each
/// rank assembles the pairs it owns.

#include "fem/assembly/constraints.hpp"
#include "fem/assembly/rigid_body_constraint.hpp"
#include "fem/core/interface_point.hpp"
#include "fem/core/state_arrays.hpp"
#include "fem/core/three_point_rule.hpp"
#include "fem/core/types.hpp"

#include <array>
#include <string>
#include <vector>

namespace bipot {

class DistributedVector;
class SparseMatrix;
class SparsityPattern;

/// What a pair looks like after an evaluation (output, tests). Local frame
/// (fem/core/interface_point.hpp).
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

/// An interface's share of the energy balance (kJ; axisymmetric: full revolution): the energy
/// stored in it now and the increments of what it dissipates and of the work of prescribed
/// interface motions (docs/theory.md, "Energy balance").
struct InterfaceEnergy {
  /// In: the ledger's rule for the step's path integrals (the trapezoid where the path is not
  /// known to be smooth over the last two steps).
  ThreePointRule rule;
  /// Out: what the rule adds to the trapezoidal external work on the adhesive springs
  /// (docs/energy_quadrature.md), and whether some pair's path has a kink within the rule's
  /// stencil (then the ledger keeps the trapezoid for all).
  double external_work_correction = 0;
  bool kinked = false;
  /// In: false where no path is known to join the step's states (a jump: the staggered
  /// fallback, a displacement reset). Out: what integrals exact along the pairs' paths
  /// (InterfaceLaw::spring_work) add to the trapezoidal external work on the adhesive
  /// springs; kinks do not matter to them.
  bool on_path = true;
  double exact_work_correction = 0;
  double interference_work = 0;    ///< of gap shifts, moving obstacles and law changes
  double stored = 0;               ///< ½ β² (C_n g_n² + C_t ‖g_t‖²) A, now
  double adhesion_dissipation = 0; ///< w (β0 − β) A: adhesion lost
  double viscous_dissipation = 0;  ///< mean (β Ẽ − w)⁺ of the step × (β_old − β) A
  double contact_work = 0;         ///< of the irreversible traction r: friction (and contact)
};

/// How the forces of an interface that adds nothing to the system are found, for output.
enum class TransmittedForce {
  None,     ///< it computes its own forces (or, tied without a body-1 region, none)
  FromBody1 ///< minus the unbalanced force of body 1's cells at the shared nodes
};

class InterfaceEnforcement {
public:
  virtual ~InterfaceEnforcement() = default;

  /// The interface's name in the input.
  virtual const std::string& name() const = 0;
  virtual std::size_t num_pairs() const = 0;

  // --- The global system ---------------------------------------------------------------
  /// False when it adds nothing to the system (bodies tied by shared nodes: exact).
  virtual bool acts_on_system() const = 0;
  /// Adds the DOF blocks of its owned pairs.
  virtual void add_to_pattern(SparsityPattern& pattern) const = 0;
  /// Rigid bodies (not owned, null for none): pairs on a body's nodes put their blocks on its
  /// reference node.
  virtual void set_rigid_bodies(const RigidBodyConstraints* rigid) = 0;
  /// Chooses its augmentation (penalty-like) parameters, from the bulk stiffness diagonal of
  /// all DOFs where it has no value of its own.
  virtual void set_augmentation(const std::vector<double>& diagonal_all) = 0;
  /// Starts an increment; multipliers extrapolated along the last committed increment by
  /// `extrapolation` (this increment's size over the last one's; 0 at a stage's start).
  virtual void begin_increment(double extrapolation) = 0;
  /// Evaluates every pair at `u` (all DOFs) over the pseudo-time step `dtau` (s).
  virtual void evaluate(const std::vector<double>& u, double dtau) = 0;
  /// Adds the owned pairs' forces of the last evaluation to R (and the tangent to K if not
  /// null); rows constrained in `constraints` are left out.
  virtual void add_to_system(const Constraints& constraints, SparseMatrix* K,
                             DistributedVector& R) const = 0;
  /// How far the multipliers of the last evaluation are from the law's fixed point (kN).
  virtual double multiplier_change() const = 0;
  /// Moves the multipliers to the last evaluation's (the Uzawa corrector).
  virtual void update_multipliers() = 0;
  /// The tangent of the last evaluation differs from the one last put into a matrix.
  virtual bool tangent_changed() const = 0;
  virtual void mark_tangent_assembled() = 0;
  /// Accepts the last evaluation as the converged state of the increment.
  virtual void commit() = 0;
  /// Largest pair force (kN) of the last evaluation: a scale for convergence tests.
  virtual double force_scale() const = 0;
  /// Round-off in its forces of the last evaluation (kN): a floor for convergence tests.
  virtual double roundoff_force() const = 0;

  // --- Adhesion (the staggered fallback and path-following) -----------------------------
  /// Some pair has adhesion that the law can still change (β > 0 under an adhesive law).
  virtual bool adhesion_can_change() const = 0;
  /// β of every pair at the start of the increment.
  virtual std::vector<double> committed_adhesion() const = 0;
  /// β the law gives at `u` from the committed state over `dtau`, per pair.
  virtual std::vector<double> adhesion_at(const std::vector<double>& u, double dtau) const = 0;
  /// evaluate() holds each pair's β at `beta` until unfreeze_adhesion().
  virtual void freeze_adhesion(const std::vector<double>& beta) = 0;
  virtual void unfreeze_adhesion() = 0;
  /// Σ A w(β) at the committed β: what adhesion loss can still dissipate (kJ).
  virtual double adhesion_capacity() const = 0;

  // --- Stage data ----------------------------------------------------------------------
  /// Puts in force the law stage `stage` (0-based) gives this interface, if any (the state
  /// carries over); true if it did.
  virtual bool enter_stage(std::size_t stage) = 0;
  /// Extra normal offset (m) on every pair's g_n (a stage ramps it: an installation).
  virtual void set_gap_shift(double shift) = 0;
  virtual double gap_shift() const = 0;
  /// Against a rigid obstacle: its translation (m, global components, 0 beyond dim).
  virtual bool has_obstacle() const = 0;
  virtual void set_obstacle_displacement(const std::array<double, 3>& u) = 0;
  virtual std::array<double, 3> obstacle_displacement() const = 0;
  /// Displacement reset keeping forces (geostatic stage): the jumps become an offset.
  virtual void absorb_displacements() = 0;
  /// Where its forces come from when it adds nothing to the system.
  virtual TransmittedForce transmitted_force() const { return TransmittedForce::None; }
  /// For transmitted_force() ≠ None: the force body 1 exerts on body 2 at every DOF.
  virtual void set_transmitted_forces(const std::vector<double>& /*force_all*/) {}

  // --- Committed state (checkpoints) ---------------------------------------------------
  virtual StateArrays save_state() const = 0;
  /// Throws bipot::Error naming the interface if an array is missing or of another size.
  virtual void load_state(const StateArrays& state) = 0;

  // --- Energy balance ------------------------------------------------------------------
  /// Starts its energy account at the committed state (the run's start).
  virtual void start_energy_account() = 0;
  /// After a converged increment, before commit(): adds the increment's dissipation and
  /// interference work to `energy` and sets `energy.stored` += what it stores now.
  virtual void record_energy(InterfaceEnergy& energy) = 0;
  virtual std::vector<double> save_energy_account() const = 0;
  /// Throws bipot::Error if the values do not fit.
  virtual void load_energy_account(const std::vector<double>& values) = 0;

  // --- Output --------------------------------------------------------------------------
  /// Resultant force body 1 exerts on body 2 (kN, global components), last evaluation.
  virtual std::array<double, 3> resultant() const = 0;
  /// Last evaluation of every pair.
  virtual const std::vector<PairResult>& results() const = 0;
};

} // namespace bipot
