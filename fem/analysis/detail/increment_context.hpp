#pragma once
/// Internal to fem/analysis: what the increment solvers act on, and the small operations on
/// it that more than one of them needs.

#include "fem/analysis/static_analysis.hpp"
#include "fem/assembly/constraints.hpp"
#include "fem/assembly/interface_enforcement.hpp"
#include "fem/assembly/rigid_body_constraint.hpp"
#include "fem/assembly/solid_assembler.hpp"
#include "fem/core/nonlinear_solver_options.hpp"
#include "fem/linalg/distributed_vector.hpp"
#include "fem/linalg/dof_distribution.hpp"
#include "fem/linalg/linear_solver.hpp"
#include "fem/linalg/sparse_matrix.hpp"

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace bipot {

namespace analysis_detail {
inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
} // namespace analysis_detail

/// The system one increment is solved on and the stage state the solvers read: references
/// into the analysis (StaticAnalysis::Impl builds it once and outlives every solver). The
/// stage driver sets the stage's targets, loads and the predictor; a solver moves `u`, the
/// interfaces' state and the scratch vectors, and adds its work to `summary`.
struct IncrementContext {
  // What to solve to.
  const NonlinearSolverOptions& contact_solver;
  const AnalysisOptions& options; ///< the limits without contact
  bool has_contact;               ///< some interface acts on the system
  bool linear;                    ///< every bulk material is linear

  // The discretised model.
  const DofDistribution& dist;
  const RigidBodyConstraints& rigid;
  SolidAssembler& solid;
  const std::vector<std::unique_ptr<InterfaceEnforcement>>& interfaces;

  // The global system: matrix, scratch vectors and the sparse linear solver.
  SparseMatrix& K;
  DistributedVector &R, &du;
  DistributedVector& F_step; ///< the loads at the increment's end (set by begin_increment)
  LinearSolver& solver;
  bool& matrix_ready; ///< K and `solver` hold the current tangent (the driver resets it)

  // The stage, as the driver set it up.
  std::vector<double>& u;                     ///< all DOFs, on every rank
  const std::map<Index, double>& target;      ///< prescribed DOFs: values at the stage's end
  const std::map<Index, double>& start;       ///< and at its start
  const DistributedVector &F_prev, &F_cur;    ///< the loads at the stage's start and end
  const std::vector<double>& gap_start;       ///< interface gap shifts at the stage's start
  const std::vector<double>& gap_target;      ///< and end
  std::function<void(double)> move_obstacles; ///< to load factor λ of the stage
  const double& extrapolation;  ///< the predictor's ratio (this increment's size / the last)
  const double& reaction_scale; ///< ‖reaction‖ at the last converged increment

  RunSummary& summary; ///< counts and times of the linear algebra

  /// At the start of an increment to stage load factor `lambda`: the loads, gap shifts and
  /// obstacles there, and the interfaces' multiplier predictor.
  void begin_increment(double lambda);
  /// F_step = the loads at stage load factor `lambda` (begin_increment's, and a path step's
  /// as its outer iterations move λ).
  void set_step_loads(double lambda);
  /// R += F_step on the DOFs `constraints` leaves free (their rows are the equilibrium).
  void add_step_loads(const Constraints& constraints);
  /// ‖v‖ over the rows `constraints` leaves free (collective): the equilibrium part of a
  /// residual.
  double free_norm(const DistributedVector& v, const Constraints& constraints) const;
  /// ‖R‖ at a trial displacement for the current multipliers (a line search's merit). Uses R
  /// as scratch; no matrix. `constraints` hold their DOFs (zero values, IncrementContext::held).
  double residual_norm(const std::vector<double>& trial, double dtau,
                       const Constraints& constraints);
  /// The prescribed DOFs, flagged over all DOFs.
  std::vector<bool> prescribed() const;
  /// Every prescribed DOF held at its current value (the iterations after the first).
  Constraints held() const;
  /// The largest force and force round-off of the interfaces at their last evaluate().
  double interface_force_scale() const;
  double interface_roundoff() const;
};

} // namespace bipot
