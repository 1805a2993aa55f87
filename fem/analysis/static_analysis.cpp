#include "fem/analysis/static_analysis.hpp"
#include "fem/analysis/detail/static_analysis_impl.hpp"

namespace bipot {

using namespace analysis_detail;

// Tractions of tied (perfect bonding) interfaces, for output: at a shared node the force
// body 1 exerts on body 2 is what body 1's cells do not balance themselves, i.e. minus their
// internal force plus their body force. Needs the interface's body-1 region (`between`);
// surface loads on body-1 facets at interface nodes are not separated out.
void StaticAnalysis::Impl::tied_interface_forces(double gravity_factor) {
  for (std::size_t k = 0; k < interfaces.size(); ++k) {
    if (interfaces[k]->transmitted_force() != TransmittedForce::FromBody1) continue;
    const int region = model.mesh.regions.at(model.spec.interfaces[k].between[0]);
    DistributedVector& f = du; // scratch: du is not needed between increments
    f.set_zero();
    solid.internal_force(u, f, region);
    f.finish_assembly();
    std::vector<const Material*> body1(model.material_of_region.size(), nullptr);
    body1[region] = model.material_of_region[region];
    DistributedVector& g = R; // scratch as well
    g.set_zero();
    loads.add_gravity(body1, g);
    g.finish_assembly();
    f.axpy(-gravity_factor, g);
    f.scale(-1.0);
    // At a supported node body 1's force also carries the support's reaction (how it splits
    // between the bodies is not determined): the support is taken to act on body 1, the
    // first of `between` (a pile head pulled by its jack), so body 1 passes on the rest.
    std::vector<double> force = f.gather_all();
    for (const auto& kv : target)
      force[kv.first] += reaction_all[kv.first];
    interfaces[k]->set_transmitted_forces(force);
  }
}

RunSummary StaticAnalysis::Impl::run(const std::function<void(const StepReport&)>& on_step) {
  const auto run_start = std::chrono::steady_clock::now();
  summary = RunSummary{};
  summary.num_dofs = dofs.num_dofs();
  summary.steps = start_steps; // a restart numbers its increments on
  if (!energy || (first_stage == 0 && !resume_point)) {
    energy = std::make_unique<EnergyLedger>(interfaces);
    energy_control = EnergyStepControl{};
  }
  const int max_cutbacks = model.contact_solver.max_cutbacks;
  double time = start_time;
  // Interface resultants (per interface and component) of the last step and the largest
  // magnitudes seen, for the snap-back flag (restored by a restart).
  last_resultant.resize(interfaces.size(), {0, 0, 0});
  largest_resultant.resize(interfaces.size(), {0, 0, 0});

  for (std::size_t s = first_stage; s < model.spec.stages.size(); ++s) {
    const StageSpec& stage = model.spec.stages[s];
    // A checkpoint within this stage: its laws are in force and ρ restored already.
    const bool resuming = s == first_stage && resume_point;
    target.clear();
    for (const auto& bc : stage.boundary_conditions)
      for (Index node : set_nodes(bc.set))
        target[dofs.dof(node, bc.component)] = bc.value;
    begin_obstacle_stage(stage);
    begin_rigid_body_stage(stage);
    start.clear();
    for (const auto& [d, v] : target)
      start[d] = u[d];
    assemble_loads(stage, F_cur);
    gravity_now = std::any_of(stage.loads.begin(), stage.loads.end(),
                              [](const LoadSpec& l) { return l.type == LoadSpec::Type::Gravity; });
    matrix_ready = false; // the constrained set may have changed
    // A gap shift not named by the stage keeps its value (it is a state, not a load).
    gap_start.resize(interfaces.size());
    gap_target.resize(interfaces.size());
    for (std::size_t k = 0; k < interfaces.size(); ++k) {
      gap_start[k] = gap_target[k] = interfaces[k]->gap_shift();
      for (const auto& gap : stage.interface_gaps)
        if (gap.interface == interfaces[k]->name()) gap_target[k] = gap.value;
    }

    // Laws the stage puts in force (the state carries over); ρ follows the new laws'
    // stiffness.
    bool law_changed = false;
    if (!resuming)
      for (const auto& ia : interfaces)
        law_changed = ia->enter_stage(s) || law_changed;
    if (law_changed && has_contact) {
      choose_augmentation();
      schur_ready = false; // K was overwritten by the unconstrained bulk matrix
    }

    const double planned = 1.0 / stage.increments;
    progress = StageProgress{};
    progress.stage = s;
    progress.stage_time = time;
    if (resuming) resume_stage(); // the position and start values a checkpoint saved
    double &done = progress.done, &last_size = progress.last_size;
    std::vector<double>& u_before_last = progress.u_before_last;
    int &level = progress.level, &step = progress.step;
    // An increment's time includes its failed attempts: the clock restarts only when one
    // converges.
    auto step_start = std::chrono::steady_clock::now();
    double failed_seconds = 0;
    PathControl path(stage, newton_system.get(), interfaces);
    energy_control.begin_stage(stage.energy_tolerance, energy->totals());
    // Another stage drives the bodies along another path: the ledger's three-point rule does
    // not reach back across its start.
    if (!resuming) energy->break_path();
    // energy_halvings: of the increment under way; energy_level: the part of the cut-back
    // level owed to the energy budget, which says nothing of the solver's convergence.
    int traced_steps = 0, energy_halvings = 0;
    int& energy_level = progress.energy_level;
    // A step the energy budget shortened that then fails to converge at the smallest step
    // (a dissipation step too short for the Jacobian at a limit point) goes back to the last
    // attempt that converged and keeps it, flagged over the budget: the control never makes
    // a run fail that would have gone on without it.
    int energy_converged_level = -1;
    int ramp_failed_at = -1; // the halving level of the ramp failure that handed over
    bool abandoned = false;  // path-following gave up during the increment being solved
    bool energy_last_resort = false;
    const auto energy_retreat = [&](std::chrono::steady_clock::time_point attempt_start) {
      if (energy_converged_level < 0 || energy_last_resort) return false;
      --energy_level; // the halving after that attempt
      level = energy_converged_level;
      energy_last_resort = true;
      failed_seconds += seconds_since(attempt_start);
      return true;
    };
    while (done < 1.0 - 1e-12) {
      const auto attempt_start = std::chrono::steady_clock::now();
      const double size = planned / std::pow(2.0, level);
      // Keep the plan: an increment never steps over the next planned load level k/n, so
      // that after a cut-back the sub-increments end exactly on it and every planned level
      // has its result (a sliver below 1e-9 of a planned increment is merged into it).
      const int next_k = std::min(stage.increments,
                                  static_cast<int>(std::floor(done * stage.increments + 1e-9)) + 1);
      const double planned_level =
          next_k == stage.increments ? 1.0 : static_cast<double>(next_k) / stage.increments;
      // A level the stage asks results at (output_at) is a stop as well.
      const auto asked =
          std::upper_bound(stage.output_at.begin(), stage.output_at.end(), done + 1e-9 * planned);
      const bool asked_first =
          asked != stage.output_at.end() && *asked < planned_level - 1e-9 * planned;
      const double next_level = asked_first ? *asked : planned_level;
      double lambda = done + size > next_level - 1e-9 * planned ? next_level : done + size;
      const std::vector<double> u_begin = u;
      IncrementLog log;
      if (path.following()) {
        // Path-following: Δλ is an unknown of the step; a failure halves the step.
        PathStep& ps = path.step(level);
        extrapolation = 0.0;
        const double dtau = path.pseudo_time_step() * stage.duration;
        bool converged = increment->solve({done, dtau, &ps}, log);
        if (converged && !path.forward(ps)) {
          converged = false;
          log.failure = "the step turned back along the path (its interface displacement "
                        "opposes the last step's)";
        }
        if (converged) lambda = done + ps.dlambda;
        if (converged && lambda > 1.0 - 1e-9 * planned) {
          // The stage ends at λ = 1 exactly: back to the ramp for the last stretch.
          u = u_begin;
          path.finish();
          continue;
        }
        if (!converged) {
          u = u_begin;
          // The traced step found no pair softening within reach (the ramp had failed for the
          // bulk's sake, e.g. a plastic soil): the ramp takes the increment back at the length
          // it failed with, now with the contact solver's own iteration limit rather than the
          // hand-over's (ramp_iterations()), and cuts back from there as a ramp alone would:
          // where nothing softens, dissipation control changes nothing of the run. Halving the
          // traced step would not help: its predictor is the ramp's step whatever its length
          // when the last increment released nothing.
          if (log.nothing_softens && ramp_failed_at >= 0) {
            path.decline();
            level = ramp_failed_at;
            ramp_failed_at = -1;
            failed_seconds += seconds_since(attempt_start);
            continue;
          }
          if (level < max_cutbacks) {
            ++level;
            ++summary.cutbacks;
            failed_seconds += seconds_since(attempt_start);
            continue;
          }
          if (energy_retreat(attempt_start)) continue;
          if (path.abandon()) {
            // The ramp, at the length it failed with under the hand-over's iteration limit
            // (now with the solver's own) or whole if it had converged and handed over for
            // releasing too much; a run that the traced steps would end.
            level = std::max(ramp_failed_at, 0);
            ramp_failed_at = -1;
            abandoned = true;
            ++summary.abandoned_paths;
            failed_seconds += seconds_since(attempt_start);
            continue;
          }
          throw IncrementFailure(
              path.failure_message(s, step + 1, done, level, log.history, log.failure),
              residual_history_text(log.history));
        }
        ++summary.traced_increments;
        if (path.too_many(++traced_steps))
          throw SolverError(path.failure_message(
              s, step + 1, done, level, {},
              "the stage's " + std::to_string(traced_steps - 1) +
                  " path-following increments (control.max_increments) did not reach load "
                  "factor 1"));
      } else {
        const double dtau = (lambda - done) * stage.duration;
        // Predictor: extrapolate u (and, in the increment solver, the multipliers) along the last
        // converged increment of this stage. Only the starting point changes; a retry after a
        // cut-back extrapolates less. Default pile run: 529 -> 274 linear solves (with ρ
        // factor 30), and far fewer cut-backs at the debonding front.
        extrapolation = last_size > 0 ? (lambda - done) / last_size : 0.0;
        if (last_size > 0)
          for (std::size_t i = 0; i < u.size(); ++i)
            u[i] += extrapolation * (u[i] - u_before_last[i]);
        bool converged = increment->solve({lambda, dtau, nullptr, path.ramp_iterations()}, log);
        bool beta_can_change = false;
        if (!converged && path.switch_on_failure()) {
          // A ramp that cannot follow a softening interface: dissipation control from here.
          ramp_failed_at = level;
          u = u_begin;
          matrix_ready = false;
          failed_seconds += seconds_since(attempt_start);
          continue;
        }
        if (!converged) {
          u = u_begin;
          matrix_ready = false;
          if (level < max_cutbacks) {
            ++level;
            ++summary.cutbacks;
            failed_seconds += seconds_since(attempt_start);
            continue;
          }
          if (energy_retreat(attempt_start)) continue;
          // The fallback holds β and updates it: without adhesion left anywhere it would only
          // repeat the failed solve.
          beta_can_change = std::any_of(interfaces.begin(), interfaces.end(),
                                        [](const auto& ia) { return ia->adhesion_can_change(); });
          if (has_contact && beta_can_change) {
            IncrementLog staggered;
            converged = staggered_fallback->solve({lambda, dtau}, staggered);
            if (converged) {
              log = staggered;
              ++summary.staggered_increments;
            } else {
              u = u_begin;
              matrix_ready = false;
              log.failure += "; then " + staggered.failure + " after " +
                             std::to_string(staggered.staggered) + " beta updates";
            }
          }
        }
        if (!converged) {
          std::ostringstream msg;
          msg << "stage '" << stage.name << "' (" << s + 1 << "), step " << step + 1 << " of "
              << stage.increments << " (load factor " << done << " -> " << lambda << " after "
              << level << " cut-backs): " << log.failure << "; relative residual history";
          // The first and last few residuals tell how it went (diverged, stalled, cycled); the
          // whole history, hundreds of values after cut-backs, goes to the error's details.
          const std::size_t n = log.history.size(), shown = 3;
          if (n > 2 * shown) {
            msg << " (" << n << " values, first and last " << shown << "):";
            for (std::size_t i = 0; i < shown; ++i)
              msg << " " << log.history[i];
            msg << " ...";
            for (std::size_t i = n - shown; i < n; ++i)
              msg << " " << log.history[i];
          } else {
            msg << ":";
            for (double h : log.history)
              msg << " " << h;
          }
          msg << "; multiplier change " << log.contact
              << ". To get through: more increments in this stage (smaller steps), "
              << (beta_can_change ? "a larger adhesion_viscosity (debonding snap-backs), " : "")
              << "or a looser contact_solver.tolerance if the residual history stalls just above "
                 "it.";
          throw IncrementFailure(msg.str(), residual_history_text(log.history));
        }
      }
      ramp_failed_at = -1; // an increment converged: a later hand-over starts afresh
      auto t0 = std::chrono::steady_clock::now();
      // Reaction = f_int − f_interfaces − f_ext: a supported node on an interface (the top
      // of a pile shaft) also carries the interface force of its pair.
      reaction.set_zero();
      if (!reactions_by_product()) solid.internal_force(u, reaction);
      reaction.finish_assembly();
      const std::vector<double> internal = reaction.gather_all();
      reaction.axpy(-1.0, F_step);
      if (has_contact) {
        R.set_zero();
        for (const auto& ia : interfaces)
          ia->add_to_system(Constraints{}, nullptr, R);
        R.finish_assembly();
        reaction.axpy(-1.0, R);
      }
      std::vector<double> reactions = reaction.gather_all();
      // External forces on the bodies: the loads and the supports' reactions. Recorded
      // before the interfaces commit (the ledger reads β before and after the step).
      std::vector<double> external = F_step.gather_all();
      for (std::size_t d = 0; d < external.size(); ++d)
        external[d] += reactions[d];
      // The staggered fallback jumps: no smooth path joins its states to the ones before.
      const bool jumped = log.staggered > 0;
      // The stage's energy_tolerance: an increment whose balance breaks the budget is redone
      // in halves before anything of it is committed.
      auto energy_verdict = EnergyStepControl::Verdict::Accept;
      const EnergyTotals energy_before = energy->totals();
      if (energy_control.active()) {
        energy_verdict =
            energy_control.judge(energy_before, energy->trial(u, external, internal, jumped),
                                 level < max_cutbacks && !energy_last_resort);
        if (energy_verdict == EnergyStepControl::Verdict::Halve) {
          u = u_begin;
          matrix_ready = false;
          energy_converged_level = level;
          if (path.following()) {
            // The attempt is redone: it is neither a traced increment nor one of the stage's.
            --summary.traced_increments;
            --traced_steps;
          }
          ++level;
          ++energy_level;
          ++energy_halvings;
          ++summary.energy_halvings;
          summary.assembly_seconds += seconds_since(t0);
          failed_seconds += seconds_since(attempt_start);
          continue;
        }
      }
      // Commit after that cell loop at the converged u: generalized_newton's last bulk
      // assembly was at the start of the increment (the rest followed by condensation).
      solid.commit();
      reaction_all = std::move(reactions);
      reaction_scale = reaction.norm2();
      energy->record(u, external, internal, jumped);
      energy_control.accept(energy_before, energy->totals(), energy_verdict);
      // A step the energy budget shortened, or one whose error leaves no room for a longer
      // one (traced steps grow by 1.5, the ramp by 2), does not grow.
      const auto may_grow = [&](double growth) {
        return energy_halvings == 0 &&
               energy_control.may_grow(energy_before, energy->totals(), growth);
      };
      path.end_increment(u, u_begin, lambda - done, log.iterations, may_grow(1.5));
      for (const auto& ia : interfaces)
        ia->commit();
      tied_interface_forces((1.0 - lambda) * gravity_before + lambda * gravity_now);
      record_rigid_body_forces();
      summary.assembly_seconds += seconds_since(t0);

      StepReport rep;
      rep.stage = stage.name;
      rep.stage_index = static_cast<int>(s);
      rep.step = ++step;
      rep.steps = stage.increments;
      rep.traced = path.traced_last();
      rep.path_abandoned = abandoned;
      abandoned = false;
      rep.dissipation = path.last_dissipation();
      rep.energy = energy->totals();
      rep.energy_halvings = energy_halvings;
      rep.over_energy_budget = energy_verdict == EnergyStepControl::Verdict::OverBudget;
      if (rep.over_energy_budget) ++summary.over_energy_budget;
      if (summary.worst_balance_step == 0 ||
          std::abs(rep.energy.relative_error()) > summary.worst_balance_error) {
        summary.worst_balance_error = std::abs(rep.energy.relative_error());
        summary.worst_balance_stage = rep.stage;
        summary.worst_balance_step = rep.step;
      }
      if (energy_control.active()) {
        summary.worst_controlled_energy_error = std::max(
            summary.worst_controlled_energy_error, energy_control.controlled_error(rep.energy));
        summary.worst_energy_error =
            std::max(summary.worst_energy_error, std::abs(rep.energy.relative_error()));
      }
      rep.planned_step = lambda == next_level && !asked_first && !rep.traced ? next_k : 0;
      rep.requested_output = !rep.traced && lambda == next_level &&
                             (asked_first || std::binary_search(stage.output_at.begin(),
                                                                stage.output_at.end(), next_level));
      rep.stage_end = lambda == 1.0;
      rep.global_step = ++summary.steps;
      if (rep.planned_step == 0 && !rep.traced && !rep.requested_output) ++summary.sub_increments;
      rep.time = time + lambda * stage.duration;
      rep.load_factor = lambda;
      rep.iterations = log.iterations;
      rep.linear_iterations = log.linear_iterations;
      rep.uzawa_updates = log.uzawa_updates;
      rep.residual = log.history.empty() ? 0.0 : log.history.back();
      rep.residual_history = log.history;
      // The level split by what asked for it: convergence failures (the CSV flag `cutbacks`)
      // and the energy budget, whose halvings counted as cut-backs before.
      rep.energy_cutbacks = std::min(energy_level, level);
      rep.cutbacks = level - rep.energy_cutbacks;
      rep.staggered = log.staggered;
      // A traced step on which the load factor falls is on the unstable branch.
      rep.unstable = rep.cutbacks > 0 || log.staggered > 0 || (rep.traced && lambda < done);
      // Snap-back: a resultant component lost over 20% of the largest value it has had, and
      // the loss is over 5% of the largest interface force of the model (so that a small
      // interface unloading smoothly, like a pile toe, is not flagged).
      for (std::size_t k = 0; k < interfaces.size(); ++k) {
        const auto f = interfaces[k]->resultant();
        for (int c = 0; c < 3; ++c) {
          const double drop = std::abs(last_resultant[k][c]) - std::abs(f[c]);
          if (drop > 0.2 * largest_resultant[k][c] && drop > 0.05 * largest_any)
            rep.unstable = true;
          largest_resultant[k][c] = std::max(largest_resultant[k][c], std::abs(f[c]));
          largest_any = std::max(largest_any, largest_resultant[k][c]);
        }
        last_resultant[k] = f;
      }
      rep.seconds = seconds_since(step_start);
      rep.failed_seconds = failed_seconds;
      summary.failed_seconds += failed_seconds;
      t0 = std::chrono::steady_clock::now();
      if (rep.stage_end) increment->release_workspace(); // before the output's arrays
      if (writer) writer->write_step(rep, *this_analysis);
      summary.output_seconds += seconds_since(t0);
      if (on_step) on_step(rep);
      // After a traced step (Δλ may be negative) the ramp starts without extrapolation.
      last_size = rep.traced ? 0.0 : lambda - done;
      u_before_last = u_begin;
      done = lambda;
      if (rep.traced)
        level = 0; // the path control keeps the step that converged
      else if (level > 0 && may_grow(2.0))
        --level; // grow back towards the planned increment
      energy_level = std::min(energy_level, level);
      step_start = std::chrono::steady_clock::now();
      failed_seconds = 0;
      energy_halvings = 0;
      energy_converged_level = -1;
      energy_last_resort = false;
      progress.planned_step = rep.planned_step;
      progress.step_time = rep.time;
      if (options.on_increment_end) options.on_increment_end(rep);
    }
    F_prev.copy(F_cur);
    gravity_before = gravity_now;
    time += stage.duration;
    if (stage.reset_displacements) {
      solid.absorb_stress_into_initial(u);
      bulk_product.initial_stress_changed();
      for (const auto& ia : interfaces)
        ia->absorb_displacements();
      energy->reset_displacements();
      std::fill(u.begin(), u.end(), 0.0);
    }
    if (options.on_stage_end) options.on_stage_end(s + 1, time);
  }
  summary.seconds = seconds_since(run_start);
  return summary;
}

std::vector<double> StaticAnalysis::rigid_body_state(std::size_t body) const {
  const Model& m = impl_->model;
  const RigidBody& b = m.rigid_bodies.at(body);
  const int n = rigid_body_components(m.kinematics);
  std::vector<double> out(2 * n, 0.0);
  for (int k = 0; k < n; ++k) {
    const Index d = rigid_body_dof(b, impl_->dofs, m.kinematics, k);
    out[k] = impl_->u[d];
    out[n + k] = impl_->rigid_force_all.empty() ? 0.0 : impl_->rigid_force_all[d];
  }
  return out;
}

const std::vector<std::unique_ptr<InterfaceEnforcement>>& StaticAnalysis::interfaces() const {
  return impl_->interfaces;
}

StaticAnalysis::StaticAnalysis(const Model& model, AnalysisOptions options, ResultWriter* writer)
    : impl_(std::make_unique<Impl>(model, options, writer)) {
  impl_->this_analysis = this;
}

StaticAnalysis::~StaticAnalysis() = default;

RunSummary StaticAnalysis::run(const std::function<void(const StepReport&)>& on_step) {
  return impl_->run(on_step);
}

StateArrays StaticAnalysis::save_state(std::size_t stages_done, double time) const {
  return impl_->save_state(stages_done, time);
}

StateArrays StaticAnalysis::save_step_state() const {
  return impl_->save_step_state();
}

void StaticAnalysis::load_state(const StateArrays& state) {
  impl_->load_state(state);
}

const std::vector<double>& StaticAnalysis::displacement() const {
  return impl_->u;
}
const DofMap& StaticAnalysis::dofs() const {
  return impl_->dofs;
}

std::vector<double> StaticAnalysis::reaction(const std::string& set) const {
  std::vector<double> sum(impl_->dim, 0.0);
  if (impl_->reaction_all.empty()) return sum;
  for (Index node : impl_->set_nodes(set))
    for (int i = 0; i < impl_->dim; ++i)
      sum[i] += impl_->reaction_all[impl_->dofs.dof(node, i)];
  return sum;
}

void StaticAnalysis::cell_results(std::vector<Index>& cells, std::vector<double>& strain,
                                  std::vector<double>& stress) const {
  cells = impl_->solid.owned_cells();
  impl_->solid.cell_averages(impl_->u, strain, stress);
}

std::vector<std::string> StaticAnalysis::output_field_names() const {
  return impl_->solid.output_field_names();
}

std::vector<double> StaticAnalysis::cell_output_fields() const {
  return impl_->solid.cell_output_fields();
}

} // namespace bipot
