#include "fem/input/stage_schema.hpp"

#include "fem/input/problem_reader.hpp"

namespace bipot {

ParamSpec& describe_duration(ParamSpec& spec) {
  spec.doc = "pseudo-time spanned by the stage (matters for a viscous RCCM interface only)";
  return spec.positive();
}

ParamSpec& describe_control_type(ParamSpec& spec) {
  spec.doc = "how the load factor advances: ramp (the planned increments), arc_length (steps of "
             "equal interface displacement, Crisfield) or dissipation (ramp, then steps of equal "
             "energy released by adhesion loss); both path-following types trace the snap-backs "
             "a ramp jumps over (docs/theory.md, Path-following)";
  return spec.one_of({"ramp", "arc_length", "dissipation"});
}

ParamSpec& describe_dissipation_step(ParamSpec& spec) {
  spec.doc = "energy adhesion loss releases per traced step (control dissipation); default: the "
             "interfaces' adhesion energy / increments";
  return spec.positive();
}

ParamSpec& describe_max_increments(ParamSpec& spec) {
  spec.doc = "traced steps allowed (control arc_length or dissipation); default: 20 x increments";
  return spec.at_least(1).at_most(max_increments_per_stage);
}

ParamSpec& describe_energy_tolerance(ParamSpec& spec) {
  spec.doc = "the run's energy balance error allowed after every increment, as a fraction of "
             "the work put in; an increment that breaks it is redone in halves, up to "
             "max_cutbacks (0: no control; docs/energy_step_control.md)";
  return spec.non_negative().less_than(1.0).because(
      "a fraction of the work put in: 0 turns the control off, 1 or more would allow any "
      "balance");
}

ParamSchemaOf<StageSpec> stage_schema() {
  using S = StageSpec;
  ParamSchemaOf<S> s("stage", "a load stage's own settings (its conditions, loads and control "
                              "are keys of their own)");
  s.integer("increments", &S::increments,
            "load increments of the stage (the ramp's planned levels k / increments)")
      .at_least(1)
      .at_most(max_increments_per_stage)
      .defaulted();
  add_duration_key(s, &S::duration);
  s.boolean("reset_displacements", &S::reset_displacements,
            "zero the displacements at the end of the stage and keep the stresses (as after a "
            "geostatic stage)")
      .defaulted();
  add_energy_tolerance_key(s, &S::energy_tolerance);
  s.real_list("output_at", &S::output_at, "",
              "load factors at which the ramp also ends an increment exactly and writes the "
              "results, VTK included whatever output.every says (traced steps do not stop on "
              "them)")
      .greater_than(0.0)
      .at_most(1.0)
      .strictly_increasing()
      .because("load factors are fractions of the stage")
      .defaulted();
  return s;
}

namespace {

// A rule: `key`, when given, belongs to the control type `type` only.
void only_for(ParamSchemaOf<ControlSpec>& s, const std::string& key,
              std::optional<double> ControlSpec::*member, const std::string& type) {
  s.rule(key, key + " only with type: " + type,
         [member, type](const ControlSpec& c) -> std::optional<std::string> {
           if (!(c.*member) || c.type == type) return std::nullopt;
           return "only for type: " + type + " (this control is " + c.type + ")";
         },
         {"type", key});
}

} // namespace

ParamSchemaOf<ControlSpec> control_schema() {
  using C = ControlSpec;
  ParamSchemaOf<C> s("control", "how a stage advances its load factor: `control: <type>` or "
                                "`control: {type: <type>, ...}` (docs/theory.md, Path-following)");
  add_control_type_key(s, "type", &C::type);
  s.real("arc_length", &C::arc_length, "m",
         "interface displacement of the first traced step (control arc_length); default: that "
         "of the first increment")
      .positive();
  add_dissipation_step_key(s, &C::dissipation_step);
  add_max_increments_key(s, &C::max_increments);
  only_for(s, "arc_length", &C::arc_length, "arc_length");
  only_for(s, "dissipation_step", &C::dissipation_step, "dissipation");
  s.rule("max_increments", "max_increments only with type: arc_length or dissipation",
         [](const C& c) -> std::optional<std::string> {
           if (!c.max_increments || c.path_following()) return std::nullopt;
           return "only for path-following controls (arc_length, dissipation)";
         },
         {"type", "max_increments"});
  return s;
}

} // namespace bipot
