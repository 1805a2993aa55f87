// Rigid obstacles: an interface's `obstacle` map and a stage's `obstacle_displacements`.
#include "fem/input/detail/sections.hpp"

#include "fem/core/nearest_name.hpp"

#include <algorithm>
#include <cmath>

namespace bipot::input {

namespace {

// The keys each obstacle type takes (besides `type`), and the dimensions it exists in.
struct ObstacleType {
  const char* name;
  std::vector<std::string> keys;
  bool in_2d, in_3d;
  const char* doc;
};

const std::vector<ObstacleType>& obstacle_types() {
  static const std::vector<ObstacleType> types = {
      {"plane", {"point", "normal"}, true, true, "point and unit normal out of the obstacle"},
      {"line", {"point", "normal"}, true, false, "2D name of a plane"},
      {"circle", {"point", "radius"}, true, false, "2D disc: centre point and radius"},
      {"sphere", {"point", "radius"}, false, true, "3D ball: centre point and radius"},
      {"cylinder", {"point", "axis", "radius"}, false, true, "3D: a point of the axis, axis"},
  };
  return types;
}

// Reads `key` as a vector of `dim` reals; with `unit`, one of non-zero length, normalised.
void read_vector(const YamlMap& m, const std::string& key, int dim, bool unit,
                 std::vector<double>& out) {
  if (!m.reals(key, out, true) || !m.has(key)) return;
  if (static_cast<int>(out.size()) != dim) {
    m.error(key,
            "expected " + std::to_string(dim) + " components, got " + std::to_string(out.size()));
    return;
  }
  if (!unit) return;
  double length = 0;
  for (double v : out)
    length += v * v;
  length = std::sqrt(length);
  if (!(length > 0) || !std::isfinite(length)) {
    m.error(key, "the " + key + " has zero length; give a direction, e.g. [0, 1" +
                     std::string(dim == 3 ? ", 0]" : "]"));
    return;
  }
  for (double& v : out)
    v /= length;
}

} // namespace

void read_obstacle_interface(const YamlMap& m, const std::string& kinematics, InterfaceSpec& spec) {
  const int dim = kinematics == "three_d" ? 3 : 2;
  if (m.has("between"))
    m.error("between", "an obstacle interface joins one facet set of a body to the obstacle; "
                       "give 'facet_sets: [set]', not 'between'");
  if (!m.has("facet_sets"))
    m.missing("facet_sets", "the facet set of the body that meets the obstacle: [set]");
  else if (spec.facet_sets.size() != 1)
    m.error("facet_sets", "an obstacle interface takes one facet set (the body's side), got " +
                              std::to_string(spec.facet_sets.size()));
  if (m.has("pairing"))
    m.error("pairing", "an obstacle pairs each node with its closest point on the surface; "
                       "'pairing' is for two facet sets");

  std::vector<std::string> allowed = {"type"}, names;
  for (const ObstacleType& t : obstacle_types()) {
    names.push_back(t.name);
    for (const std::string& k : t.keys)
      if (std::find(allowed.begin(), allowed.end(), k) == allowed.end()) allowed.push_back(k);
  }
  const YamlMap o(m.node("obstacle"), m.path("obstacle"), m.diag(), allowed);
  if (!o.valid()) return;
  ObstacleSpec ob;
  ob.where = o.where();
  if (!o.string("type", ob.type, true) || !o.has("type")) return;
  const ObstacleType* type = nullptr;
  for (const ObstacleType& t : obstacle_types())
    if (ob.type == t.name) type = &t;
  if (!type) {
    o.error("type", "unknown obstacle type '" + ob.type + "'; allowed: " + join_names(names));
    return;
  }
  if (!(dim == 2 ? type->in_2d : type->in_3d)) {
    o.error("type", "a " + ob.type + " obstacle does not exist in " + kinematics + "; allowed: " +
                        (dim == 2 ? "plane (or line), circle" : "plane, sphere, cylinder"));
    return;
  }
  for (const std::string& k : allowed)
    if (k != "type" && o.has(k) &&
        std::find(type->keys.begin(), type->keys.end(), k) == type->keys.end())
      o.error(k,
              "a " + ob.type + " obstacle takes " + join_names(type->keys) + ", not '" + k + "'");
  read_vector(o, "point", dim, false, ob.point);
  if (ob.type == "plane" || ob.type == "line") {
    ob.type = "plane";
    read_vector(o, "normal", dim, true, ob.normal);
  } else {
    if (ob.type == "cylinder") read_vector(o, "axis", dim, true, ob.axis);
    if (o.real("radius", ob.radius, true) && o.has("radius") && !(ob.radius > 0))
      o.error("radius", "value must be > 0 m");
  }
  spec.obstacle = ob;
}

void read_obstacle_displacements(const YamlMap& stage, int dim, StageSpec& st) {
  for (const YamlMap& g : list_entries(stage, "obstacle_displacements", {"interface", "value"},
                                       "expected a list of {interface, value}")) {
    if (!g.valid()) continue;
    ObstacleDisplacementSpec d;
    d.where = g.where("interface");
    g.string("interface", d.interface, true);
    if (g.reals("value", d.value, true) && g.has("value") &&
        static_cast<int>(d.value.size()) != dim)
      g.error("value", "expected " + std::to_string(dim) + " displacement components (m)");
    st.obstacle_displacements.push_back(d);
  }
}

} // namespace bipot::input
