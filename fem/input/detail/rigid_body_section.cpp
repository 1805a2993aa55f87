// Rigid bodies: the `rigid_bodies` section (which nodes, which reference point) and the
// conditions a stage puts on their reference nodes.
#include "fem/input/detail/sections.hpp"

#include "fem/core/nearest_name.hpp"

#include <algorithm>

namespace bipot::input {

namespace {

// The reference node's components by kinematics, in RigidBodyConditionSpec's numbering.
std::vector<std::pair<std::string, int>> reference_components(const std::string& kinematics) {
  if (kinematics == "three_d")
    return {{"x", 0}, {"y", 1}, {"z", 2}, {"rx", 3}, {"ry", 4}, {"rz", 5}};
  if (kinematics == "axisymmetric") return {{"z", 1}, {"y", 1}}; // axial translation only
  return {{"x", 0}, {"y", 1}, {"rz", 2}};
}

} // namespace

std::vector<RigidBodySpec> read_rigid_bodies(const YamlMap& top, int dim) {
  std::vector<RigidBodySpec> out;
  UniqueNames names("rigid_body", "stages name the body whose reference node they move");
  const auto entries =
      list_entries(top, "rigid_bodies", {"name", "region", "set", "reference_point"},
                   "expected a list of {name, region | set, reference_point}");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const YamlMap& m = entries[i];
    if (!m.valid()) continue;
    RigidBodySpec b;
    b.where = m.where();
    b.name = names.read(m, i);
    m.string("region", b.region);
    m.string("set", b.set);
    if (m.has("region") == m.has("set"))
      m.error("region", "give exactly one of 'region' (its cells' nodes) or 'set' (a node or "
                        "facet set)");
    if (m.reals("reference_point", b.reference_point) && m.has("reference_point") &&
        static_cast<int>(b.reference_point.size()) != dim)
      m.error("reference_point", "expected " + std::to_string(dim) + " coordinates (m)");
    out.push_back(b);
  }
  return out;
}

void read_stage_rigid_bodies(const YamlMap& stage, const std::string& kinematics, StageSpec& st) {
  const auto components = reference_components(kinematics);
  std::vector<std::string> allowed;
  for (const auto& c : components)
    if (kinematics != "axisymmetric" || c.first == "z") allowed.push_back(c.first);
  std::vector<std::pair<std::string, std::string>> seen; // (body, component) -> entry
  std::vector<std::string> seen_entry;
  for (const YamlMap& e :
       list_entries(stage, "rigid_bodies", {"body", "component", "value", "force"},
                    "expected a list of {body, component, value | force}")) {
    if (!e.valid()) continue;
    RigidBodyConditionSpec c;
    c.where = e.where("body");
    e.string("body", c.body, true);
    std::string name;
    bool complete = e.string("component", name, true) && e.has("component") && e.has("body");
    const auto it = std::find_if(components.begin(), components.end(),
                                 [&](const auto& p) { return p.first == name; });
    if (e.has("component") && it == components.end()) {
      e.error("component",
              "unknown component '" + name + "' of a rigid body's reference node in " + kinematics +
                  "; allowed: " + join_names(allowed) +
                  (kinematics == "axisymmetric" ? " (a rigid body of revolution only moves axially)"
                                                : ""));
      complete = false;
    } else if (it != components.end()) {
      c.component = it->second;
    }
    if (e.has("value") == e.has("force")) {
      e.error("value", "give exactly one of 'value' (a displacement, m, or a rotation, rad) and "
                       "'force' (a force, kN, or a moment, kN m)");
      complete = false;
    }
    c.force = e.has("force");
    complete = e.real(c.force ? "force" : "value", c.value, true) && complete;
    st.rigid_body_conditions.push_back(c);
    if (!complete) continue;
    for (std::size_t k = 0; k < seen.size(); ++k)
      if (seen[k].first == c.body && seen[k].second == std::to_string(c.component))
        e.error("component", "component " + name + " of rigid body '" + c.body +
                                 "' is already given by " + seen_entry[k] + " in the same stage");
    seen.emplace_back(c.body, std::to_string(c.component));
    seen_entry.push_back(e.path_and_line());
  }
}

} // namespace bipot::input
