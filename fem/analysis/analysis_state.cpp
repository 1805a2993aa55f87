// The complete state of a StaticAnalysis at a stage end, for checkpoints and restarts.
#include "fem/analysis/detail/static_analysis_impl.hpp"

namespace bipot {

using namespace analysis_detail;

namespace {

const std::vector<double>& array(const StateArrays& state, const std::string& name,
                                 std::size_t size = 0) {
  const auto it = state.find(name);
  if (it == state.end()) throw Error("analysis state: no array '" + name + "'");
  if (size > 0 && it->second.size() != size)
    throw Error("analysis state: array '" + name + "' holds " + std::to_string(it->second.size()) +
                " values, this model needs " + std::to_string(size));
  return it->second;
}

// The arrays of `state` whose name starts with `prefix`, without it.
StateArrays with_prefix(const StateArrays& state, const std::string& prefix) {
  StateArrays out;
  for (const auto& [name, values] : state)
    if (name.compare(0, prefix.size(), prefix) == 0) out[name.substr(prefix.size())] = values;
  return out;
}

std::vector<double> flatten(const std::vector<std::array<double, 3>>& v) {
  std::vector<double> out;
  for (const auto& a : v)
    out.insert(out.end(), a.begin(), a.end());
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
  return out;
}

void StaticAnalysis::Impl::load_state(const StateArrays& state) {
  const std::vector<double>& position = array(state, "analysis.position", 3);
  const auto stages_done = static_cast<std::size_t>(position[0]);
  if (stages_done < 1 || stages_done > model.spec.stages.size())
    throw Error("analysis state: saved after " + std::to_string(stages_done) +
                " stages, the model has " + std::to_string(model.spec.stages.size()));
  first_stage = stages_done;
  start_time = position[1];
  start_steps = static_cast<int>(position[2]);
  u = array(state, "analysis.u", u.size());
  reaction_all = array(state, "analysis.reaction_all", u.size());
  const std::vector<double>& scalars = array(state, "analysis.scalars", 3);
  reaction_scale = scalars[0];
  gravity_before = scalars[1];
  largest_any = scalars[2];
  const auto unflatten = [&](const std::string& name) {
    const std::vector<double>& v = array(state, name, 3 * interfaces.size());
    std::vector<std::array<double, 3>> out(interfaces.size());
    for (std::size_t k = 0; k < out.size(); ++k)
      out[k] = {v[3 * k], v[3 * k + 1], v[3 * k + 2]};
    return out;
  };
  last_resultant = unflatten("analysis.last_resultant");
  largest_resultant = unflatten("analysis.largest_resultant");
  solid.load_state(with_prefix(state, "solid."));
  // The laws the done stages put in force, then the interface states saved under them.
  for (const auto& sl : model.stage_laws)
    if (sl.stage < stages_done) interfaces[sl.interface]->set_law(*sl.law);
  for (std::size_t k = 0; k < interfaces.size(); ++k)
    interfaces[k]->load_state(with_prefix(state, "interface." + std::to_string(k) + "."));
  // The energy balance so far (energy.csv continues it).
  energy = std::make_unique<EnergyLedger>(interfaces);
  energy->load_state(with_prefix(state, "energy."));
  // The loads in force at the end of the last stage done (what the next one ramps from).
  assemble_loads(model.spec.stages[stages_done - 1], F_prev);
}

} // namespace bipot
