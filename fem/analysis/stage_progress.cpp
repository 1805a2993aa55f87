// Checkpoints within a stage: the stage driver's position and the stage's start values, saved
// beside save_state()'s arrays and restored when run() reaches that stage again.
#include "fem/analysis/detail/state_access.hpp"
#include "fem/analysis/detail/static_analysis_impl.hpp"

namespace bipot {

using namespace analysis_detail;

StateArrays StaticAnalysis::Impl::save_step_state() const {
  const StageSpec& stage = model.spec.stages.at(progress.stage);
  // A path-following stage's state (arc length, the last traced increment, its mode) lives
  // in its PathControl and is not saved; `check` refuses such checkpoints already.
  if (stage.control.path_following())
    throw Error("stage '" + stage.name + "' is path-following (control: " + stage.control.type +
                "): checkpoints within it are not supported, only at its end");
  // save_state()'s position is the stages done and the pseudo-time at this stage's start.
  StateArrays out = save_state(progress.stage, progress.stage_time);
  const StageProgress& p = progress;
  out["analysis.in_stage"] = {p.done,
                              p.last_size,
                              static_cast<double>(p.level),
                              static_cast<double>(p.step),
                              static_cast<double>(p.planned_step),
                              p.step_time,
                              static_cast<double>(p.energy_level)};
  out["analysis.u_before_last"] = p.u_before_last;
  // Prescribed DOFs (global numbers, exact as doubles) and the values they ramp from.
  std::vector<double>& s = out["analysis.start"];
  for (const auto& [dof, value] : start) {
    s.push_back(static_cast<double>(dof));
    s.push_back(value);
  }
  out["analysis.gap_start"] = gap_start;
  out["analysis.obstacle_start"] = flatten(obstacle_start);
  return out;
}

void StaticAnalysis::Impl::load_step_state(const StateArrays& state) {
  ResumePoint r;
  const std::vector<double>& position = state_array(state, "analysis.position", 3);
  const std::vector<double>& in_stage = state_array(state, "analysis.in_stage", 7);
  StageProgress& p = r.progress;
  p.stage = static_cast<std::size_t>(position[0]);
  p.stage_time = position[1];
  p.done = in_stage[0];
  p.last_size = in_stage[1];
  p.level = static_cast<int>(in_stage[2]);
  p.step = static_cast<int>(in_stage[3]);
  p.planned_step = static_cast<int>(in_stage[4]);
  p.step_time = in_stage[5];
  p.energy_level = static_cast<int>(in_stage[6]);
  p.u_before_last = state_array(state, "analysis.u_before_last");
  if (p.last_size > 0 && p.u_before_last.size() != u.size())
    throw Error("analysis state: array 'analysis.u_before_last' holds " +
                std::to_string(p.u_before_last.size()) + " values, this model needs " +
                std::to_string(u.size()));
  const std::vector<double>& s = state_array(state, "analysis.start");
  if (s.size() % 2 != 0) throw Error("analysis state: 'analysis.start' holds an odd count");
  for (std::size_t i = 0; i < s.size(); i += 2) {
    const auto dof = static_cast<Index>(s[i]);
    if (dof < 0 || dof >= static_cast<Index>(u.size()))
      throw Error("analysis state: 'analysis.start' names DOF " + std::to_string(dof) +
                  ", this model has " + std::to_string(u.size()));
    r.start[dof] = s[i + 1];
  }
  r.gap_start = state_array(state, "analysis.gap_start");
  if (r.gap_start.size() != interfaces.size())
    throw Error("analysis state: 'analysis.gap_start' does not fit the interfaces");
  // state_array() takes a size of 0 as "any": no interfaces, no obstacles.
  if (!interfaces.empty())
    r.obstacle_start = unflatten(state, "analysis.obstacle_start", interfaces.size());
  resume_point = std::move(r);
}

void StaticAnalysis::Impl::resume_stage() {
  ResumePoint& r = *resume_point;
  progress = r.progress;
  // The DOFs this stage prescribes follow from its conditions; the values they ramp from
  // were u at the stage's start, which the saved u no longer is.
  for (auto& [dof, value] : start) {
    const auto it = r.start.find(dof);
    if (it == r.start.end())
      throw Error("analysis state: DOF " + std::to_string(dof) +
                  " is prescribed by the stage but not in the checkpoint's start values");
    value = it->second;
  }
  gap_start = r.gap_start;
  obstacle_start = r.obstacle_start;
  resume_point.reset();
}

} // namespace bipot
