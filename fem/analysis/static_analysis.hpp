#pragma once
/// Quasi-static analysis in load stages: each stage ramps its boundary conditions and loads
/// linearly from their state at the end of the previous stage over its increments, and each
/// increment is solved by Newton's method on R(u) = f_ext − f_int(u) + f_interfaces(u) = 0,
/// with the interface multipliers updated as the contact solver says (see
/// contact/solver/contact_solver_options.hpp). An increment that does not converge is
/// halved (up to the contact solver's max_cutbacks); if the smallest one still fails, a
/// staggered iteration (β held, solve, update β, repeat) looks for the equilibrium after a
/// debonding jump, and only then does the run stop. A stage with `energy_tolerance` also
/// halves a converged increment whose energy balance would break that budget, before anything
/// of it is committed (energy_step_control.hpp).

#include "fem/analysis/energy_ledger.hpp"
#include "fem/analysis/model.hpp"
#include "fem/assembly/dof_map.hpp"
#include "fem/assembly/interface_enforcement.hpp"
#include "fem/core/error.hpp"
#include "fem/core/state_arrays.hpp"

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace bipot {

class ResultWriter;
struct StepReport;

struct AnalysisOptions {
  int max_iterations = 25;          ///< Newton iterations per increment
  double residual_tolerance = 1e-8; ///< relative to the first residual of the increment
  /// Called on every rank at the end of each stage, after its displacement reset, with the
  /// number of stages done and the pseudo-time (s): where save_state() is complete.
  std::function<void(std::size_t stages_done, double time)> on_stage_end;
  /// Called on every rank after each converged increment, once the stage driver has moved
  /// past it (after the writer and run()'s on_step): where save_step_state() is complete.
  std::function<void(const StepReport&)> on_increment_end;
};

/// What a converged increment reports (progress lines, tests).
struct StepReport {
  std::string stage;
  int stage_index = 0;
  int step = 0;  ///< increment within the stage, 1-based (sub-increments count)
  int steps = 0; ///< planned increments of the stage
  /// k when the increment ends on the planned load level k/steps; 0 for a sub-increment
  /// (after a cut-back, the sub-increments end exactly on the next planned level).
  int planned_step = 0;
  bool stage_end = false; ///< the last increment of the stage (load factor 1)
  /// Path-following gave up on this increment (a traced step failed at every halving): it
  /// and the rest of its stage are ramped (RunSummary::abandoned_paths).
  bool path_abandoned = false;
  /// Ends on a load factor the stage's `output_at` asks for (results and VTK are written).
  bool requested_output = false;
  int global_step = 0;    ///< converged increments so far, 1-based
  double time = 0;        ///< pseudo-time at the end of the increment (s)
  double load_factor = 0; ///< λ within the stage, in (0, 1]
  int iterations = 0;     ///< Newton iterations
  int linear_iterations = 0;
  double residual = 0; ///< final relative residual
  /// Relative force residual at each iteration of the converged attempt (the convergence
  /// rate: quadratic for generalized_newton on a smooth branch).
  std::vector<double> residual_history;
  double seconds = 0;        ///< wall time of the increment, its failed attempts included
  double failed_seconds = 0; ///< of which in attempts that failed and were cut back
  /// The halving level the step was solved at owed to convergence failures (of this or earlier
  /// increments of the stage, not yet grown back); the step is the planned increment over
  /// 2^(cutbacks + energy_cutbacks).
  int cutbacks = 0;
  /// The part of the halving level owed to the stage's energy_tolerance (its halvings of this
  /// or earlier increments, not yet grown back), which says nothing of the solver.
  int energy_cutbacks = 0;
  int uzawa_updates = 0; ///< multiplier updates (bipotential_uzawa)
  /// β updates of the staggered fallback (0 unless the increment jumped: a debonding
  /// snap-back the monolithic iteration could not cross even at the smallest step).
  int staggered = 0;
  /// Cut back, or a snap-back: an interface resultant component lost over 20% of its largest
  /// value (and over 5% of the largest interface force of the model) in one step.
  bool unstable = false;
  /// Traced by path-following (stage `control:` arc_length or dissipation): λ was an unknown
  /// of the step and may have decreased (an unstable branch).
  bool traced = false;
  /// Energy adhesion loss released in the increment (kJ, what dissipation control measures);
  /// 0 outside path-following stages.
  double dissipation = 0;
  /// The run's energy balance up to this increment (energy.csv).
  EnergyTotals energy;
  /// Halvings the stage's energy_tolerance asked for before this increment was kept (each
  /// a converged attempt whose energy balance broke the budget; counted in energy_cutbacks,
  /// never in cutbacks).
  int energy_halvings = 0;
  /// Kept over the stage's energy_tolerance: at the smallest step (max_cutbacks) the
  /// increment's error still broke its budget (a jump; its own error is excused from then
  /// on), or the run's error was over once the work put in fell (energy_step_control.hpp).
  bool over_energy_budget = false;
};

struct RunSummary {
  int steps = 0;
  int linear_solves = 0;
  int linear_iterations = 0;    ///< Krylov iterations over all solves
  int matrix_setups = 0;        ///< preconditioner/factorisation set-ups
  int staggered_increments = 0; ///< increments solved by the staggered fallback (jumps)
  int cutbacks = 0;             ///< failed attempts, each followed by a halving
  int sub_increments = 0;       ///< converged increments between planned and asked levels
  int traced_increments = 0;    ///< increments traced by path-following
  int abandoned_paths = 0;      ///< stages ramped on after a traced step failed every halving
  int energy_halvings = 0;      ///< converged attempts redone for the energy_tolerance
  int over_energy_budget = 0;   ///< increments kept over the energy_tolerance (flagged)
  /// Largest |balance error| / work put in after an increment of a stage with an
  /// energy_tolerance, the excused errors of flagged increments left out.
  double worst_controlled_energy_error = 0;
  /// The same with every error counted (energy.csv's largest relative_error in those stages).
  double worst_energy_error = 0;
  /// energy.csv's largest |relative_error| over the whole run, every stage, and the stage
  /// and step where it was (step 0: none).
  double worst_balance_error = 0;
  std::string worst_balance_stage;
  int worst_balance_step = 0;
  double failed_seconds = 0; ///< wall time of the failed attempts
  Index num_dofs = 0;
  double seconds = 0;          ///< whole run, wall time
  double assembly_seconds = 0; ///< cell loops, loads, reactions
  double setup_seconds = 0;    ///< preconditioner or factorisation
  double solve_seconds = 0;    ///< Krylov or triangular solves
  double output_seconds = 0;   ///< VTK and CSV
};

/// An increment that did not converge after its cut-backs. The message names the stage, step
/// and the first and last few residuals; `details()` holds the whole residual history, too
/// long to print (the apps write it to failure.log in the failed results folder).
class IncrementFailure : public SolverError {
public:
  IncrementFailure(const std::string& message, std::string details)
      : SolverError(message), details_(std::move(details)) {}
  const std::string& details() const { return details_; }

private:
  std::string details_;
};

class StaticAnalysis {
public:
  /// `writer` (optional, not owned) receives every converged increment.
  StaticAnalysis(const Model& model, AnalysisOptions options = {}, ResultWriter* writer = nullptr);
  ~StaticAnalysis();

  /// Runs every stage. Throws IncrementFailure naming the stage, step, iteration and residual
  /// history if an increment does not converge; increments converged before stay written.
  RunSummary run(const std::function<void(const StepReport&)>& on_step = {});

  /// The complete state after `stages_done` stages ending at pseudo-time `time` (call it from
  /// AnalysisOptions::on_stage_end; collective): displacements, the solid's per-point state
  /// gathered from every rank by global cell, every interface's committed state, the load and
  /// reaction memory and the step count (analysis_state.cpp). The same on every rank.
  StateArrays save_state(std::size_t stages_done, double time) const;
  /// The complete state within a stage, after the increment AnalysisOptions::on_increment_end
  /// reports (collective): save_state()'s arrays plus the stage driver's position — load
  /// factor, step count, cut-back level, the last increment's size and u before it (the
  /// predictor), the stage's start values of prescribed DOFs, gap shifts and obstacles
  /// (stage_progress.cpp). Throws bipot::Error in a path-following stage (`control:`), whose
  /// path state is not saved.
  StateArrays save_step_state() const;
  /// Restores a save_state() or save_step_state() made by the same model at any rank count
  /// (every rank, before run()); run() then continues with the next stage, or within the
  /// stage, as the saved run did. The laws the stages up to there put in force are put in
  /// force again. Throws bipot::Error if the arrays do not fit this model.
  void load_state(const StateArrays& state);

  /// Total displacement, all DOFs, replicated on every rank.
  const std::vector<double>& displacement() const;
  const DofMap& dofs() const;
  /// Reaction force (f_int − f_ext) summed over the nodes of a node or facet set, one value
  /// per spatial component, at the last converged increment.
  std::vector<double> reaction(const std::string& set) const;
  /// Rigid body `body` (Model::rigid_bodies order) at the last converged increment: its
  /// reference node's components (rigid_body_components(): translations, then rotations)
  /// followed by what the reference node transmits to the body along each (forces, kN;
  /// moments, kN·m about the reference point): the applied load, or the reaction of a
  /// prescribed component.
  std::vector<double> rigid_body_state(std::size_t body) const;
  /// Interface states of the last converged increment (one enforcement per interface).
  const std::vector<std::unique_ptr<InterfaceEnforcement>>& interfaces() const;
  /// Committed cell averages of strain and stress for the cells this rank owns.
  void cell_results(std::vector<Index>& cells, std::vector<double>& strain,
                    std::vector<double>& stress) const;
  /// Names of the materials' output fields and their committed cell averages for the cells
  /// of cell_results(), fields interleaved (SolidAssembler::cell_output_fields).
  std::vector<std::string> output_field_names() const;
  std::vector<double> cell_output_fields() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

} // namespace bipot
