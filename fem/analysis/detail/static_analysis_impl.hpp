#pragma once
/// Internal to fem/analysis: the state of a StaticAnalysis, shared by static_analysis.cpp (the
/// stage driver and the public accessors) and increment_solver.cpp (the iterations of one
/// increment: Newton/Uzawa, line search, the staggered fallback).

#include "fem/analysis/initial_stress.hpp"
#include "fem/analysis/path_control.hpp"
#include "fem/analysis/result_writer.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/assembly/condensed_interface_system.hpp"
#include "fem/assembly/constraints.hpp"
#include "fem/assembly/interface_enforcement.hpp"
#include "fem/assembly/linear_bulk_residual.hpp"
#include "fem/assembly/load_assembler.hpp"
#include "fem/assembly/rigid_body_constraint.hpp"
#include "fem/assembly/solid_assembler.hpp"
#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"
#include "fem/linalg/distributed_vector.hpp"
#include "fem/linalg/dof_distribution.hpp"
#include "fem/linalg/linear_solver.hpp"
#include "fem/linalg/reused_lu_solver.hpp"
#include "fem/linalg/schur_complement_solver.hpp"
#include "fem/linalg/sparse_matrix.hpp"
#include "fem/linalg/sparsity_pattern.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

namespace bipot {

namespace analysis_detail {

// A cell belongs to the rank owning its lowest node: deterministic, no communication, and
// with node-block row ownership most of its rows are local.
inline std::vector<bool> owned_cell_flags(const Mesh& mesh, const DofDistribution& dist) {
  std::vector<bool> owned(mesh.num_cells());
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const Index* nodes = mesh.cell(c);
    const Index lowest = *std::min_element(nodes, nodes + mesh.cell_num_nodes(c));
    owned[c] = dist.owner_of_node(lowest) == dist.rank();
  }
  return owned;
}

inline std::vector<Index> indices_of(const std::vector<bool>& flags) {
  std::vector<Index> out;
  for (std::size_t i = 0; i < flags.size(); ++i)
    if (flags[i]) out.push_back(static_cast<Index>(i));
  return out;
}

inline bool all_linear(const Model& model) {
  return std::all_of(model.materials.begin(), model.materials.end(),
                     [](const auto& m) { return m->is_linear(); });
}

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Backtracking (Armijo) on a merit function along a Newton direction: halves the step from 1
// up to 8 times until merit(step) < (1 − 1e-4 step) merit0. Without such a decrease, the best
// step tried, or the full one if none helped (at a kink of the contact law the Newton
// direction need not be a descent direction).
template <class Merit> double backtracking_step(double merit0, Merit merit) {
  double step = 1.0, best = merit0, best_step = 1.0;
  for (int k = 0; k < 8; ++k) {
    const double m = merit(step);
    if (m < (1.0 - 1e-4 * step) * merit0) return step;
    if (m < best) best = m, best_step = step;
    step *= 0.5;
  }
  return best < merit0 ? best_step : 1.0;
}

// The whole residual history of a failed increment, for failure.log.
inline std::string residual_history_text(const std::vector<double>& history) {
  std::ostringstream full;
  full << "relative residual history of the failed increment (" << history.size() << " values):\n";
  for (std::size_t i = 0; i < history.size(); ++i)
    full << i + 1 << " " << history[i] << "\n";
  return full.str();
}

} // namespace analysis_detail

/// One path-following increment (stage `control:` arc_length or dissipation): the load
/// factor's increment Δλ joins the unknowns of the generalized Newton step, bordered by one
/// constraint g(x, λ_c, Δλ) = 0 (fem/analysis/path_constraint.cpp, docs/theory.md):
///   arc_length:  ‖x‖ = L                                (Crisfield, cylindrical)
///   dissipation: Σ A w (β_committed − β(x)) = Δτ          (Gutiérrez 2004)
/// x the increment of the interface DOFs, β the adhesion the law gives at the trial jumps.
struct PathStep {
  enum class Kind { ArcLength, Dissipation } kind = Kind::ArcLength;
  Eigen::VectorXd x_prev;              ///< the previous increment on I (direction and predictor)
  double dlambda_prev = 0, length = 0; ///< Δλ_prev; arc_length: L (m)
  Eigen::VectorXd u0, f0;              ///< dissipation: at the increment's start
  double dissipation = 0;              ///< Δτ (kJ)
  double predictor_scale = 1;          ///< z0 = scale × (x_prev, Δλ_prev)
  // Out: the converged increment.
  Eigen::VectorXd x;
  double dlambda = 0;

  /// g and, with grad (size n + 1), its gradient with respect to (x, λ_c, Δλ), at z after
  /// the interfaces were evaluated there.
  double constraint(const CondensedInterfaceSystem& sys, const Eigen::VectorXd& z,
                    Eigen::VectorXd* grad) const;
  /// The constraint's own scale (L or Δτ).
  double scale() const { return kind == Kind::ArcLength ? length : dissipation; }
  /// |g| ≤ constraint_tolerance(tolerance) is met: √tolerance × scale(). The constraint only
  /// picks which equilibrium of the path the step ends on, and the step's length is itself a
  /// choice (adapted by factors of 0.6 to 1.5): the step's equilibrium and the interface law
  /// are what the solver tolerance is for. Held to the tolerance itself, a converged
  /// equilibrium often took one more Newton iteration for the constraint alone, and the
  /// constraint's kinks (each pair's β = min(β_old, w/E)) made it the slowest residual.
  double constraint_tolerance(double tolerance) const { return std::sqrt(tolerance) * scale(); }
};

struct StaticAnalysis::Impl {
  const Model& model;
  AnalysisOptions options;
  ResultWriter* writer;
  int dim;
  DofMap dofs;
  DofDistribution dist;
  RigidBodyConstraints rigid; ///< the rigid bodies' master–slave transformation
  std::vector<bool> cell_owned;
  SolidAssembler solid;
  LoadAssembler loads;
  std::vector<std::unique_ptr<InterfaceEnforcement>> interfaces;
  bool has_contact = false; ///< some interface acts on the system: the tangent changes
  std::unique_ptr<SparseMatrix> K;
  DistributedVector R, du, F_prev, F_cur, F_step, reaction;
  LinearSolver solver;
  std::vector<double> u;
  std::vector<double> reaction_all;
  bool linear;
  bool matrix_ready = false;                     ///< K and the solver hold the current tangent
  const StaticAnalysis* this_analysis = nullptr; ///< handed to the writer
  RunSummary summary;
  std::unique_ptr<EnergyLedger> energy; ///< created by run(), once the interfaces exist
  /// ‖reaction‖ at the last converged increment: a force scale for the relative residual.
  /// Without it, an increment that the predictor already solves (a linear model under
  /// proportional loading) measured its residual against its own round-off and never
  /// converged.
  double reaction_scale = 0;
  // generalized_newton: the bulk condensed onto the interface DOFs, refactorised only when
  // the bulk tangent or the constrained DOFs change.
  std::unique_ptr<CondensedInterfaceSystem> newton_system;
  SchurComplementSolver schur;
  /// generalized_newton with a linear bulk and no rigid bodies: the bulk residual of each
  /// increment from products with the factorised K (assembled with it) instead of a cell loop.
  LinearBulkResidual bulk_product{dist};
  ReusedLuSolver newton_matrix; ///< the dense Newton steps, factors kept across iterations
  bool schur_ready = false;
  std::vector<Index> schur_constrained; ///< constrained DOFs of the factorised matrix

  // Boundary-condition targets of the current stage and the values they start from.
  std::map<Index, double> target, start;
  // Interface gap shifts (per interface) at the start and the end of the current stage.
  std::vector<double> gap_start, gap_target;
  // Obstacle translations (per interface) at the start and the end of the current stage.
  std::vector<std::array<double, 3>> obstacle_start, obstacle_target;
  /// Reads the stage's obstacle displacements (obstacle_motion.cpp).
  void begin_obstacle_stage(const StageSpec& stage);
  // Rigid bodies (rigid_body_motion.cpp): prescribed components of the reference nodes
  // (entries of `target`, before `start` is filled), forces and moments on them plus the
  // slaves' loads moved to the masters, and what the reference nodes transmit.
  void begin_rigid_body_stage(const StageSpec& stage);
  void add_rigid_body_loads(const StageSpec& stage, DistributedVector& F) const;
  void record_rigid_body_forces();
  std::vector<double> rigid_force_all; ///< f_int at the master DOFs (others 0), all DOFs
  /// Sets every obstacle's translation at load factor `lambda` of the stage.
  void move_obstacles(double lambda);

  Impl(const Model& m, AnalysisOptions o, ResultWriter* w)
      : model(m), options(o), writer(w), dim(spatial_dim(m.kinematics)),
        dofs(m.mesh.num_nodes(), dim), dist(m.mesh.num_nodes(), dim),
        rigid(m.mesh, m.kinematics, dofs, m.rigid_bodies),
        cell_owned(analysis_detail::owned_cell_flags(m.mesh, dist)),
        solid(m.mesh, m.kinematics, dofs, m.material_of_region,
              analysis_detail::indices_of(cell_owned)),
        loads(m.mesh, m.kinematics, dofs, cell_owned), R(dist), du(dist), F_prev(dist), F_cur(dist),
        F_step(dist), reaction(dist), solver(LinearSolver::schema().fill(m.spec.linear_solver)),
        u(dofs.num_dofs(), 0.0), linear(analysis_detail::all_linear(m)) {
    if (m.interface_module) {
      EnforcedInterfaces enforced = m.interface_module->enforce(m, dofs, dist);
      interfaces = std::move(enforced.interfaces);
      newton_system = std::move(enforced.condensed);
    }
    for (const auto& ia : interfaces)
      has_contact = has_contact || ia->acts_on_system();
    SparsityPattern pattern;
    if (!rigid.empty()) solid.set_rigid_bodies(&rigid);
    solid.add_to_pattern(pattern);
    rigid.add_inactive_rows(dist, pattern);
    for (const auto& ia : interfaces) {
      if (!rigid.empty()) ia->set_rigid_bodies(&rigid);
      ia->add_to_pattern(pattern);
    }
    K = std::make_unique<SparseMatrix>(dist, pattern);
    std::vector<double> coords;
    for (Index n = dist.first_owned_node(); n < dist.first_owned_node() + dist.num_owned_nodes();
         ++n)
      coords.insert(coords.end(), m.mesh.nodes[n].begin(), m.mesh.nodes[n].end());
    // Axisymmetry too gets the three plane-strain rigid modes: u_r = const costs only
    // ε_θθ = u/r, small away from the axis, so AMG must see it, and the in-plane rotation
    // helps as well. CG + MueLu iterations on a 200x50-cell cylinder wall (r in [1, 2]),
    // axial mode only / both translations / three modes: quad8 341 / 42 / 30 (1 rank),
    // 57 / 49 with 2 ranks; quad4 129 / 18 / 13, 31 / 27 with 2 ranks.
    solver.set_near_null_space(dim, false, coords);
    if (!m.spec.initial_stress.empty()) solid.set_initial_stress(initial_stress_function(m));
    F_prev.set_zero();
    if (has_contact) choose_augmentation();
  }

  // ρ per pair from the bulk stiffness diagonal (one bulk assembly, before any constraint).
  void choose_augmentation() {
    K->set_zero();
    R.set_zero();
    solid.assemble(u, Constraints{}, K.get(), R);
    K->finish_assembly();
    R.finish_assembly();
    const std::vector<double> diagonal = K->diagonal().gather_all();
    for (const auto& ia : interfaces)
      ia->set_augmentation(diagonal);
  }

  std::vector<Index> set_nodes(const std::string& name) const {
    auto it = model.mesh.node_sets.find(name);
    if (it != model.mesh.node_sets.end()) return it->second;
    return model.mesh.facet_set_nodes(name);
  }

  void assemble_loads(const StageSpec& stage, DistributedVector& F) const {
    F.set_zero();
    for (const auto& ld : stage.loads) {
      switch (ld.type) {
      case LoadSpec::Type::Pressure:
        loads.add_pressure(ld.set, ld.pressure, F);
        break;
      case LoadSpec::Type::Traction:
        loads.add_traction(ld.set, ld.traction, F);
        break;
      case LoadSpec::Type::Gravity:
        loads.add_gravity(model.material_of_region, F);
        break;
      }
    }
    F.finish_assembly();
    add_rigid_body_loads(stage, F);
  }

  struct IncrementLog {
    int iterations = 0, linear_iterations = 0, uzawa_updates = 0, staggered = 0;
    std::vector<double> history; ///< relative force residual per iteration
    double contact = 0;          ///< last relative multiplier change
    std::string failure;
  };

  // R += F_step on the DOFs `constraints` leaves free (their rows are the equilibrium).
  void add_step_loads(const Constraints& constraints) {
    const Index first = dist.first_owned_dof();
    double* r = R.owned_values();
    const double* f = F_step.owned_values();
    for (Index i = 0; i < dist.num_owned_dofs(); ++i)
      if (!constraints.is_constrained(first + i)) r[i] += f[i];
  }

  /// ‖v‖ over the rows `constraints` leaves free (collective): the equilibrium part of a
  /// residual. The first pass of an increment puts diag(K) × the prescribed increment on the
  /// constrained rows, which is no force on the body: on a footing it was 65 times the
  /// reactions, and the increment's relative tolerance as much looser.
  double free_norm(const DistributedVector& v, const Constraints& constraints) const {
    const Index first = dist.first_owned_dof();
    const double* x = v.owned_values();
    double sum = 0;
    for (Index i = 0; i < dist.num_owned_dofs(); ++i)
      if (!constraints.is_constrained(first + i)) sum += x[i] * x[i];
    return std::sqrt(sum_all(sum));
  }

  /// With `path`, `lambda` is the load factor at the increment's start and Δλ is solved for.
  /// `max_iterations` > 0 gives up after that many Newton iterations rather than the contact
  /// solver's own limit.
  bool solve_increment_exact(double lambda, double dtau, IncrementLog& log,
                             PathStep* path = nullptr, int max_iterations = 0);
  ReusedLuSolver path_matrix; ///< the bordered Newton matrices of path-following steps
  /// `exact_iterations`: solve_increment_exact's `max_iterations` (generalized_newton only).
  bool solve_increment(double lambda, double dtau, IncrementLog& log, int exact_iterations = 0);
  static constexpr double roundoff_factor = 10.0; // safety on the round-off estimate
  // Predictor of the next increment: its size over the last converged one's in this stage
  // (0 at a stage's first increment); u and the multipliers start at committed + this ×
  // (their last change). Set by the stage driver.
  double extrapolation = 0.0;
  void tied_interface_forces(double gravity_factor);
  // Share of gravity in the loads at the end of the previous stage and of the current one
  // (0 or 1), ramped like the loads.
  double gravity_before = 0.0, gravity_now = 0.0;
  bool solve_increment_staggered(double lambda, double dtau, IncrementLog& log);
  double residual_norm(const std::vector<double>& trial, double dtau,
                       const Constraints& constraints);
  RunSummary run(const std::function<void(const StepReport&)>& on_step);

  // Where run() starts (analysis_state.cpp: a state loaded after `first_stage` stages) and the
  // snap-back monitor's memory, per interface and component (kept across stages).
  std::size_t first_stage = 0;
  double start_time = 0.0;
  int start_steps = 0;
  std::vector<std::array<double, 3>> last_resultant, largest_resultant;
  double largest_any = 0.0;
  StateArrays save_state(std::size_t stages_done, double time) const;
  void load_state(const StateArrays& state);

  /// The running stage's position: the stage driver's step-size state, kept here (not in
  /// locals of run()) so that a checkpoint within a stage can save it (stage_progress.cpp).
  struct StageProgress {
    std::size_t stage = 0;
    double stage_time = 0;             ///< pseudo-time at the stage's start
    double done = 0, last_size = 0;    ///< converged λ; size of the last converged increment
    std::vector<double> u_before_last; ///< u at the start of the last converged increment
    int level = 0, step = 0;           ///< cut-back level; converged increments so far
    int planned_step = 0;              ///< the planned level k the last increment ended on
    double step_time = 0;              ///< pseudo-time at the end of the last increment
  };
  StageProgress progress;
  /// Loaded from a checkpoint within a stage: the stage's start values, restored by
  /// resume_stage() once run() has set the stage up.
  struct ResumePoint {
    StageProgress progress;
    std::map<Index, double> start;
    std::vector<double> gap_start;
    std::vector<std::array<double, 3>> obstacle_start;
  };
  std::optional<ResumePoint> resume_point;
  StateArrays save_step_state() const;
  void load_step_state(const StateArrays& state);
  void resume_stage();
};

} // namespace bipot
