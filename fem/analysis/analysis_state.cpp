// The complete state of a StaticAnalysis at a stage end, for checkpoints and restarts (within
// a stage: stage_progress.cpp adds the stage driver's position).
#include "fem/analysis/detail/state_access.hpp"
#include "fem/analysis/detail/static_analysis_impl.hpp"

namespace bipot {

using namespace analysis_detail;

namespace {

// The arrays of `state` whose name starts with `prefix`, without it.
StateArrays with_prefix(const StateArrays& state, const std::string& prefix) {
  StateArrays out;
  for (const auto& [name, values] : state)
    if (name.compare(0, prefix.size(), prefix) == 0) out[name.substr(prefix.size())] = values;
  return out;
}

} // namespace

StateArrays StaticAnalysis::Impl::save_state(std::size_t stages_done, double time) const {
  StateArrays out;
  out["analysis.position"] = {static_cast<double>(stages_done), time,
                              static_cast<double>(summary.steps)};
  out["analysis.u"] = u;
  out["analysis.reaction_all"] = reaction_all;
  out["analysis.scalars"] = {reaction_scale, gravity_before, largest_any};
  out["analysis.last_resultant"] = flatten(last_resultant);
  out["analysis.largest_resultant"] = flatten(largest_resultant);
  // Where the obstacles are: a later stage that does not move one starts from there.
  std::vector<std::array<double, 3>> obstacles;
  for (const auto& ia : interfaces)
    obstacles.push_back(ia->obstacle_displacement());
  out["analysis.obstacles"] = flatten(obstacles);
  // The solid's arrays cover the cells each rank owns: gathered in rank order (every rank
  // holds the same names, so the collective calls match).
  for (const auto& [name, values] : solid.save_state())
    out["solid." + name] = gather_all(values);
  for (std::size_t k = 0; k < interfaces.size(); ++k)
    for (auto& [name, values] : interfaces[k]->save_state())
      out["interface." + std::to_string(k) + "." + name] = std::move(values);
  if (energy)
    for (auto& [name, values] : energy->save_state())
      out["energy." + name] = std::move(values);
  // The energy control's excused error: without it a restart excused the whole error the run
  // carried, and judged the increments after it otherwise than the uninterrupted run.
  out["analysis.energy_control"] = energy_control.save_state();
  return out;
}

void StaticAnalysis::Impl::load_state(const StateArrays& state) {
  const std::vector<double>& position = state_array(state, "analysis.position", 3);
  const auto stages_done = static_cast<std::size_t>(position[0]);
  // Saved within a stage (save_step_state): that stage's laws are in force too.
  const bool within = state.count("analysis.in_stage") > 0;
  if (stages_done < (within ? 0u : 1u) || stages_done + (within ? 1 : 0) > model.spec.stages.size())
    throw Error("analysis state: saved after " + std::to_string(stages_done) +
                " stages, the model has " + std::to_string(model.spec.stages.size()));
  first_stage = stages_done;
  start_time = position[1];
  start_steps = static_cast<int>(position[2]);
  u = state_array(state, "analysis.u", u.size());
  reaction_all = state_array(state, "analysis.reaction_all", u.size());
  const std::vector<double>& scalars = state_array(state, "analysis.scalars", 3);
  reaction_scale = scalars[0];
  gravity_before = scalars[1];
  largest_any = scalars[2];
  last_resultant = unflatten(state, "analysis.last_resultant", interfaces.size());
  largest_resultant = unflatten(state, "analysis.largest_resultant", interfaces.size());
  const auto obstacles = unflatten(state, "analysis.obstacles", interfaces.size());
  for (std::size_t k = 0; k < interfaces.size(); ++k)
    interfaces[k]->set_obstacle_displacement(obstacles[k]);
  solid.load_state(with_prefix(state, "solid."));
  bulk_product.initial_stress_changed();
  // The laws the done stages put in force, then the interface states saved under them.
  for (std::size_t s = 0; s < stages_done + (within ? 1 : 0); ++s)
    for (const auto& ia : interfaces)
      ia->enter_stage(s);
  for (std::size_t k = 0; k < interfaces.size(); ++k)
    interfaces[k]->load_state(with_prefix(state, "interface." + std::to_string(k) + "."));
  // The energy balance so far (energy.csv continues it).
  energy = std::make_unique<EnergyLedger>(interfaces);
  energy->load_state(with_prefix(state, "energy."));
  energy_control.load_state(state_array(state, "analysis.energy_control", 2));
  // The loads in force at the end of the last stage done (what the next one ramps from).
  if (stages_done > 0)
    assemble_loads(model.spec.stages[stages_done - 1], F_prev);
  else
    F_prev.set_zero();
  resume_point.reset();
  if (within) load_step_state(state);
}

} // namespace bipot
