// `output.checkpoint`: where a run saves its complete state for `--restart` (at stage ends,
// at chosen planned steps of a stage, or every n-th planned step), and the checks that need
// the stages.
#include "fem/core/nearest_name.hpp"
#include "fem/input/detail/sections.hpp"

#include <algorithm>

namespace bipot::input {

void read_checkpoint(const YamlMap& output, OutputSpec& out) {
  if (!output.has("checkpoint")) return;
  const YamlMap c(output.node("checkpoint"), output.path("checkpoint"), output.diag(),
                  {"after", "steps", "every"});
  if (!c.valid()) return;
  out.checkpoint_where = c.where("after");
  if (c.strings("after", out.checkpoint_after) && c.has("after") && out.checkpoint_after.empty())
    c.error("after", "expected a non-empty list of stage names");
  if (c.integer("every", out.checkpoint_every) && c.has("every") && out.checkpoint_every < 1)
    c.error("every", "value " + std::to_string(out.checkpoint_every) +
                         " is out of range [1, inf) (every n-th planned increment of a stage)");
  if (c.has("steps")) {
    const auto entries =
        list_entries(c, "steps", {"stage", "step"}, "expected a list of {stage: name, step: k}");
    if (c.node("steps").IsSequence() && c.node("steps").size() == 0)
      c.error("steps", "expected a non-empty list of {stage: name, step: k}");
    for (const YamlMap& e : entries) {
      if (!e.valid()) continue;
      OutputSpec::CheckpointStep s;
      s.where = e.where("stage");
      s.step_where = e.where("step");
      if (e.string("stage", s.stage, true) && e.integer("step", s.step, true) && e.has("stage") &&
          e.has("step"))
        out.checkpoint_steps.push_back(s);
    }
  }
  if (!c.has("after") && !c.has("steps") && !c.has("every"))
    c.diag().error_at(c.where(),
                      "expected at least one of after: [stage names], steps: [{stage, step}], "
                      "every: n");
}

void check_checkpoints(const ProblemSpec& spec, Diagnostics& diag) {
  std::vector<std::string> names;
  for (const auto& st : spec.stages)
    names.push_back(st.name);
  const auto unknown = [&](const std::string& name, const std::string& where) {
    const std::string near = nearest_name(name, names);
    diag.error_at(where, "no stage named '" + name + "'" +
                             (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                             "; stages: " + join_names(names));
  };
  for (const auto& name : spec.output.checkpoint_after)
    if (std::find(names.begin(), names.end(), name) == names.end())
      unknown(name, spec.output.checkpoint_where);
  for (const auto& c : spec.output.checkpoint_steps) {
    const auto it = std::find(names.begin(), names.end(), c.stage);
    if (it == names.end()) {
      unknown(c.stage, c.where);
      continue;
    }
    const StageSpec& st = spec.stages[static_cast<std::size_t>(it - names.begin())];
    if (st.control.path_following())
      diag.error_at(c.where, "stage '" + st.name +
                                 "' is path-following (control: " + st.control.type +
                                 "), whose path state a checkpoint does not hold: checkpoints "
                                 "within it are not supported; use after: [" +
                                 st.name + "] for its end");
    else if (c.step < 1 || c.step > st.increments)
      diag.error_at(c.step_where, "step " + std::to_string(c.step) + " is out of range [1, " +
                                      std::to_string(st.increments) + "]: stage '" + st.name +
                                      "' has " + std::to_string(st.increments) +
                                      " planned increments (step k is its load level k/" +
                                      std::to_string(st.increments) + ")");
  }
}

} // namespace bipot::input
