// A stage's `interfaces:` map: per interface, a new law and/or new parameters from this stage
// on (docs/input_reference.md, "Stages"; what happens to the state: docs/theory.md).
#include "fem/core/nearest_name.hpp"
#include "fem/input/detail/sections.hpp"

#include <algorithm>

namespace bipot::input {

void read_stage_interfaces(const YamlMap& stage, const std::vector<InterfaceSpec>& interfaces,
                           const SchemaIndex& laws, std::vector<InterfaceLawChangeSpec>& active,
                           StageSpec& st) {
  const YAML::Node node = stage.node("interfaces");
  const std::string path = stage.path("interfaces");
  Diagnostics& diag = stage.diag();
  if (!node.IsMap() || node.size() == 0) {
    stage.error("interfaces", "expected a map: interface name -> {law: <law>, parameters: "
                              "{...}} (either or both)");
    return;
  }
  report_duplicate_keys(node, path, diag);
  std::vector<std::string> names;
  for (const InterfaceSpec& f : interfaces)
    names.push_back(f.name);
  for (const auto& kv : node) {
    const std::string name = kv.first.Scalar();
    const std::string entry_path = join_path(path, name);
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) {
      const std::string near = nearest_name(name, names);
      diag.error(kv.first, entry_path,
                 "no interface named '" + name + "'" +
                     (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                     "; interfaces: " + (names.empty() ? std::string("none") : join_names(names)));
      continue;
    }
    const YamlMap m(kv.second, entry_path, diag, {"law", "parameters"});
    if (!m.valid()) continue;
    if (!m.has("law") && !m.has("parameters")) {
      diag.error(kv.second, entry_path, "give a new law, new parameters, or both");
      continue;
    }
    InterfaceLawChangeSpec& now = active[static_cast<std::size_t>(it - names.begin())];
    InterfaceLawChangeSpec change{name, now.law, {}, m.where()};
    if (m.has("law") && m.string("law", change.law, true) && !laws.contains(change.law)) {
      m.error("law", laws.unknown_message(change.law));
      continue;
    }
    if (now.law.empty() || !laws.contains(change.law)) continue; // the interface's own error
    const ParamSchema schema = laws.schema(change.law);
    // The same law: the keys given change, the others keep their values in force. A new law
    // starts from its own defaults.
    const ParameterSet* base = change.law == now.law ? &now.parameters : nullptr;
    if (m.has("parameters")) {
      change.parameters =
          read_parameters_node(m.node("parameters"), m.path("parameters"), diag, schema, {}, base);
    } else if (!base) {
      for (const auto& p : validate(schema, change.parameters))
        m.error("law", "parameters." + p.key + ": " + p.message);
    }
    now.law = change.law;
    now.parameters = change.parameters;
    st.interface_laws.push_back(std::move(change));
  }
}

} // namespace bipot::input
