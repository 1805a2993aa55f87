#pragma once
/// A load stage's own keys and those of its `control` mapping, each declared once and bound
/// to its StageSpec / ControlSpec member. The input reader reads them through these schemas,
/// `bipot describe stage` / `bipot describe control` print them and docs/input_stages.md
/// shows their tables. The keys that hold lists of maps (boundary_conditions, loads, ...)
/// have readers of their own (fem/input/detail/stage_section.cpp).

#include "fem/core/parameter_binding.hpp"
#include "fem/input/problem_spec.hpp"

namespace bipot {

/// `increments`, `duration`, `reset_displacements`, `energy_tolerance`, `output_at`.
ParamSchemaOf<StageSpec> stage_schema();
/// `type`, `arc_length`, `dissipation_step`, `max_increments`, with the rules saying which
/// key belongs to which type (reported at the key, and listed by `bipot describe control`).
ParamSchemaOf<ControlSpec> control_schema();

/// The keys every input with load stages shares (the general input's stages, the pile app's
/// `pullout`): each describe_*() gives a key its doc and range, and the add_*() helpers
/// declare it in any schema, bound to the member given, so the texts are written once.
ParamSpec& describe_duration(ParamSpec& spec);
ParamSpec& describe_control_type(ParamSpec& spec);
ParamSpec& describe_dissipation_step(ParamSpec& spec);
ParamSpec& describe_max_increments(ParamSpec& spec);
ParamSpec& describe_energy_tolerance(ParamSpec& spec);

/// `duration` (s), defaulted to the member's initializer.
template <class P> ParamSpec& add_duration_key(ParamSchemaOf<P>& schema, double P::*member) {
  return describe_duration(schema.real("duration", member, "s", "")).defaulted();
}
/// The control type under `key` (`type` in a stage's control map, `control` in the pile's
/// `pullout`), defaulted to the member's initializer.
template <class P>
ParamSpec& add_control_type_key(ParamSchemaOf<P>& schema, const std::string& key,
                                std::string P::*member) {
  return describe_control_type(schema.string(key, member, "")).defaulted();
}
/// `dissipation_step` (kJ); empty: derived by the analysis.
template <class P>
ParamSpec& add_dissipation_step_key(ParamSchemaOf<P>& schema, std::optional<double> P::*member) {
  return describe_dissipation_step(schema.real("dissipation_step", member, "kJ", ""));
}
/// `max_increments`; empty: derived by the analysis.
template <class P>
ParamSpec& add_max_increments_key(ParamSchemaOf<P>& schema, std::optional<int> P::*member) {
  return describe_max_increments(schema.integer("max_increments", member, ""));
}
/// `energy_tolerance`, defaulted to the member's initializer (StageSpec's: 1e-6).
template <class P>
ParamSpec& add_energy_tolerance_key(ParamSchemaOf<P>& schema, double P::*member) {
  return describe_energy_tolerance(schema.real("energy_tolerance", member, "", "")).defaulted();
}

} // namespace bipot
