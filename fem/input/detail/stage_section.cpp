// The `stages` section: per stage, its own settings (stage_schema()), boundary conditions,
// loads, interface gaps and control (control_schema()).
#include "fem/input/detail/sections.hpp"

#include "fem/core/nearest_name.hpp"
#include "fem/input/stage_schema.hpp"

#include <algorithm>

namespace bipot::input {

// In axisymmetry r and z name x and y (r is x, z is y); x and y are accepted too.
const std::vector<std::string>& component_names(const std::string& kinematics) {
  static const std::vector<std::string> plane = {"x", "y"}, axisymmetric = {"r", "z"},
                                        three_d = {"x", "y", "z"};
  return kinematics == "three_d" ? three_d : kinematics == "axisymmetric" ? axisymmetric : plane;
}

namespace {

int component_index(const std::string& name, const std::string& kinematics) {
  const auto& names = component_names(kinematics);
  const auto it = std::find(names.begin(), names.end(), name);
  if (it != names.end()) return static_cast<int>(it - names.begin());
  if (kinematics == "axisymmetric" && (name == "x" || name == "y")) return name == "x" ? 0 : 1;
  return -1;
}

// A condition read completely, kept to find a later one of the stage that fixes the same set
// and component to another value (which would silently win).
struct FixedComponent {
  std::string set;
  int component = 0;
  double value = 0;
  std::string value_text, entry; ///< entry: "stages[0].boundary_conditions[1] (line 16)"
};

void read_boundary_conditions(const YamlMap& m, const std::string& kinematics, StageSpec& st) {
  std::vector<FixedComponent> fixed;
  for (const YamlMap& b :
       list_entries(m, "boundary_conditions", {"set", "component", "value"}, "expected a list")) {
    if (!b.valid()) continue;
    DirichletSpec bc;
    bc.where = b.where("set");
    bool complete = b.string("set", bc.set, true) && b.has("set");
    std::string comp;
    if (b.string("component", comp, true) && b.has("component")) {
      bc.component = component_index(comp, kinematics);
      if (bc.component < 0)
        b.error("component", "unknown component '" + comp + "' in " + kinematics +
                                 "; allowed: " + join_names(component_names(kinematics)) +
                                 (kinematics == "axisymmetric" ? " (or x, y)" : ""));
    }
    complete = complete && bc.component >= 0 && b.real("value", bc.value);
    st.boundary_conditions.push_back(bc);
    if (!complete) continue;
    const FixedComponent f{bc.set, bc.component, bc.value,
                           b.has("value") ? b.node("value").Scalar() : "0", b.path_and_line()};
    for (const FixedComponent& other : fixed)
      if (other.set == f.set && other.component == f.component && other.value != f.value)
        b.error("value", "component " + comp + " of set '" + f.set + "' is fixed to " +
                             f.value_text + " here and to " + other.value_text + " by " +
                             other.entry + " in the same stage");
    fixed.push_back(f);
  }
}

void read_loads(const YamlMap& m, int dim, StageSpec& st) {
  for (const YamlMap& l : list_entries(m, "loads", {"type", "set", "value"}, "expected a list")) {
    if (!l.valid()) continue;
    LoadSpec ld;
    ld.where = l.where("set");
    std::string type;
    l.string("type", type, true);
    if (type == "pressure") {
      ld.type = LoadSpec::Type::Pressure;
      l.string("set", ld.set, true);
      l.real("value", ld.pressure, true);
    } else if (type == "traction") {
      ld.type = LoadSpec::Type::Traction;
      l.string("set", ld.set, true);
      if (l.reals("value", ld.traction, true) && l.has("value") &&
          static_cast<int>(ld.traction.size()) != dim)
        l.error("value", "expected " + std::to_string(dim) + " traction components (kPa)");
    } else if (type == "gravity") {
      ld.type = LoadSpec::Type::Gravity;
      ld.where = l.where("type");
      if (l.has("set") || l.has("value"))
        l.error("type", "gravity takes no set or value: it uses each material's unit_weight");
    } else if (!type.empty()) {
      l.error("type", "unknown load type '" + type + "'; allowed: pressure, traction, gravity");
    }
    st.loads.push_back(ld);
  }
}

void read_interface_gaps(const YamlMap& m, StageSpec& st) {
  for (const YamlMap& g :
       list_entries(m, "interface_gaps", {"interface", "value"}, "expected a list")) {
    if (!g.valid()) continue;
    InterfaceGapSpec gap;
    gap.where = g.where("interface");
    g.string("interface", gap.interface, true);
    g.real("value", gap.value, true);
    st.interface_gaps.push_back(gap);
  }
}

// `control: dissipation` (the type alone) or `control: {type: dissipation, dissipation_step:
// 0.01}`: the type alone is checked against the same schema, and reported at `control`.
void read_control(const YamlMap& m, const ParamSchemaOf<ControlSpec>& schema, StageSpec& st) {
  ParameterSet given;
  if (m.node("control").IsScalar()) {
    given.set("type", m.node("control").Scalar());
    for (const auto& p : validate(schema, given))
      m.error("control", p.message);
  } else {
    given = read_parameters(m, "control", schema, {});
  }
  st.control = schema.fill(given).value();
  st.control.where = m.where("control");
}

} // namespace

std::vector<StageSpec> read_stages(const YamlMap& top, const std::string& kinematics,
                                   const std::vector<InterfaceSpec>& interfaces,
                                   const SchemaIndex& laws) {
  std::vector<StageSpec> out;
  const std::string expected = "expected a non-empty list of stages";
  if (top.node("stages").IsSequence() && top.node("stages").size() == 0)
    top.error("stages", expected);
  UniqueNames names("stage", "each stage needs its own: progress lines and failure reports "
                             "name stages");
  const auto schema = stage_schema();
  const auto control = control_schema();
  std::vector<std::string> keys = {"name"};
  for (const auto& key : schema.keys())
    keys.push_back(key);
  for (const char* key : {"boundary_conditions", "loads", "interface_gaps", "interfaces",
                          "obstacle_displacements", "rigid_bodies", "control"})
    keys.push_back(key);
  const auto entries = list_entries(top, "stages", keys, expected);
  std::vector<InterfaceLawChangeSpec> active;
  for (const InterfaceSpec& f : interfaces)
    active.push_back({f.name, f.law, f.parameters, f.where});
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const YamlMap& m = entries[i];
    if (!m.valid()) continue;
    StageSpec st = schema.fill(read_schema_keys(m, schema)).value();
    st.where = m.where();
    st.name = names.read(m, i);
    if (m.has("boundary_conditions")) read_boundary_conditions(m, kinematics, st);
    if (m.has("loads")) read_loads(m, kinematics == "three_d" ? 3 : 2, st);
    if (m.has("interface_gaps")) read_interface_gaps(m, st);
    if (m.has("rigid_bodies")) read_stage_rigid_bodies(m, kinematics, st);
    if (m.has("obstacle_displacements"))
      read_obstacle_displacements(m, kinematics == "three_d" ? 3 : 2, st);
    if (m.has("interfaces")) read_stage_interfaces(m, interfaces, laws, active, st);
    if (m.has("control")) read_control(m, control, st);
    out.push_back(std::move(st));
  }
  return out;
}

namespace {

bool same_load(const LoadSpec& a, const LoadSpec& b) {
  return a.type == b.type && a.set == b.set && a.pressure == b.pressure && a.traction == b.traction;
}

// Whether λ scales anything in stage i: a condition whose value differs from the previous
// stage's (0 if none), or a load that the previous stage did not have.
bool stage_scales_something(const std::vector<StageSpec>& stages, std::size_t i) {
  for (const DirichletSpec& bc : stages[i].boundary_conditions) {
    double before = 0;
    if (i > 0)
      for (const DirichletSpec& old : stages[i - 1].boundary_conditions)
        if (old.set == bc.set && old.component == bc.component) before = old.value;
    if (bc.value != before) return true;
  }
  for (const LoadSpec& ld : stages[i].loads) {
    const bool zero =
        (ld.type == LoadSpec::Type::Pressure && ld.pressure == 0) ||
        (ld.type == LoadSpec::Type::Traction &&
         std::all_of(ld.traction.begin(), ld.traction.end(), [](double t) { return t == 0; }));
    const bool had = i > 0 && std::any_of(stages[i - 1].loads.begin(), stages[i - 1].loads.end(),
                                          [&](const LoadSpec& o) { return same_load(o, ld); });
    if (!zero && !had) return true;
  }
  return false;
}

} // namespace

void check_stage_controls(const ProblemSpec& spec, Diagnostics& diag) {
  const bool contact =
      std::any_of(spec.interfaces.begin(), spec.interfaces.end(),
                  [](const InterfaceSpec& f) { return f.law != "perfect_bonding"; });
  for (std::size_t i = 0; i < spec.stages.size(); ++i) {
    const StageSpec& st = spec.stages[i];
    if (!st.control.path_following()) continue;
    const std::string what = "control " + st.control.type + ": ";
    if (spec.contact_solver.type != "generalized_newton")
      diag.error_at(st.control.where, what +
                                          "path-following borders the generalized Newton step; "
                                          "it needs contact_solver.type: generalized_newton "
                                          "(the input has " +
                                          spec.contact_solver.type + ")");
    else if (!contact)
      diag.error_at(st.control.where,
                    what + "path-following follows the interfaces' equations; the model has no "
                           "interface with a contact law (perfect_bonding only, or none)");
    if (!st.interface_gaps.empty())
      diag.error_at(st.control.where, what + "a path-following stage cannot also ramp "
                                             "interface_gaps (the gap is not scaled by the load "
                                             "factor); give them their own stage");
    if (!st.obstacle_displacements.empty() || !st.rigid_body_conditions.empty())
      diag.error_at(st.control.where,
                    what + "a path-following stage cannot also move obstacles or rigid bodies "
                           "(their motion is not scaled by the load factor); give them their "
                           "own stage");
    if (!stage_scales_something(spec.stages, i))
      diag.error_at(st.control.where,
                    what + "nothing to scale: the stage changes no boundary condition value and "
                           "adds no load, so the load factor it follows has no meaning");
  }
}

} // namespace bipot::input
