#pragma once
/// Internal to fem/analysis: the state of a StaticAnalysis, shared by static_analysis.cpp (the
/// stage driver and the public accessors) and the driver's other files (rigid bodies,
/// obstacles, saved states). The increment solvers (increment_solver.hpp) see only the part
/// of it their IncrementContext names.

#include "fem/analysis/detail/increment_context.hpp"
#include "fem/analysis/detail/increment_solver.hpp"
#include "fem/analysis/detail/path_step.hpp"
#include "fem/analysis/detail/staggered_increment.hpp"
#include "fem/analysis/energy_step_control.hpp"
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

// The whole residual history of a failed increment, for failure.log.
inline std::string residual_history_text(const std::vector<double>& history) {
  std::ostringstream full;
  full << "relative residual history of the failed increment (" << history.size() << " values):\n";
  for (std::size_t i = 0; i < history.size(); ++i)
    full << i + 1 << " " << history[i] << "\n";
  return full.str();
}

} // namespace analysis_detail

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
  /// The stages' energy_tolerance (a member, not a local of run(): checkpoints save it).
  EnergyStepControl energy_control;
  /// ‖reaction‖ at the last converged increment: a force scale for the relative residual.
  /// Without it, an increment that the predictor already solves (a linear model under
  /// proportional loading) measured its residual against its own round-off and never
  /// converged.
  double reaction_scale = 0;
  // generalized_newton: the interface equations, on the bulk condensed onto the interface
  // DOFs (ExactNewtonIncrement), refactorised only when the bulk tangent or the constrained
  // DOFs change.
  std::unique_ptr<CondensedInterfaceSystem> newton_system;
  /// generalized_newton with a linear bulk and no rigid bodies: the bulk residual of each
  /// increment from products with the factorised K (assembled with it) instead of a cell loop.
  LinearBulkResidual bulk_product{dist};
  bool schur_ready = false; ///< the condensed K is factorised (cleared when K is overwritten)

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
    make_increment_solvers();
  }

  // The increment solvers on this analysis' system: the one of the contact solver option,
  // and the staggered fallback around it.
  std::unique_ptr<IncrementContext> increment_context;
  std::unique_ptr<IncrementSolver> increment, staggered_fallback;
  void make_increment_solvers() {
    auto obstacles_at = [this](double lambda) { move_obstacles(lambda); };
    increment_context.reset(new IncrementContext{model.contact_solver,
                                                 options,
                                                 has_contact,
                                                 linear,
                                                 dist,
                                                 rigid,
                                                 solid,
                                                 interfaces,
                                                 *K,
                                                 R,
                                                 du,
                                                 F_step,
                                                 solver,
                                                 matrix_ready,
                                                 u,
                                                 target,
                                                 start,
                                                 F_prev,
                                                 F_cur,
                                                 gap_start,
                                                 gap_target,
                                                 obstacles_at,
                                                 extrapolation,
                                                 reaction_scale,
                                                 summary});
    increment =
        make_increment_solver(*increment_context, newton_system.get(), bulk_product, schur_ready);
    staggered_fallback = std::make_unique<StaggeredIncrement>(*increment_context, *increment);
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

  // Predictor of the next increment: its size over the last converged one's in this stage
  // (0 at a stage's first increment); u and the multipliers start at committed + this ×
  // (their last change). Set by the stage driver.
  double extrapolation = 0.0;
  void tied_interface_forces(double gravity_factor);
  /// generalized_newton on a linear bulk without rigid bodies: adds f_int(u) to `reaction`
  /// from products with the factorised K (LinearBulkResidual::internal_force) instead of a
  /// cell loop, if K is that of the stage's supports; false (nothing added) otherwise.
  bool reactions_by_product() {
    if (!newton_system || !schur_ready || !linear || !rigid.empty()) return false;
    Constraints supports;
    for (const auto& kv : target)
      supports.set(kv.first, 0.0);
    return bulk_product.internal_force(solid, *K, u, supports, reaction);
  }
  // Share of gravity in the loads at the end of the previous stage and of the current one
  // (0 or 1), ramped like the loads.
  double gravity_before = 0.0, gravity_now = 0.0;
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
    /// The part of `level` owed to the energy budget (the rest: convergence failures).
    int energy_level = 0;
    int planned_step = 0; ///< the planned level k the last increment ended on
    double step_time = 0; ///< pseudo-time at the end of the last increment
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
