#include "fem/input/increment_checks.hpp"

#include "fem/input/detail/check_support.hpp"
#include "fem/input/detail/sections.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace bipot {

namespace {

// The diagonal of the bounding box of the finite coordinates (the mesh checks report the
// others); 0 for an empty mesh.
double model_size(const Mesh& mesh) {
  std::array<double, 3> lo, hi;
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  bool any = false;
  for (const auto& x : mesh.nodes) {
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) continue;
    any = true;
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], x[i]);
      hi[i] = std::max(hi[i], x[i]);
    }
  }
  if (!any) return 0.0;
  return std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

} // namespace

std::vector<std::string> large_increment_warnings(const ProblemSpec& spec, const Mesh& mesh) {
  std::vector<std::string> warnings;
  const double size = model_size(mesh);
  if (!(size > 0.0)) return warnings;
  const auto& components = input::component_names(spec.kinematics);
  std::map<std::pair<std::string, int>, double> previous; // end of the previous stage
  for (const auto& stage : spec.stages) {
    std::map<std::pair<std::string, int>, double> current;
    for (const auto& bc : stage.boundary_conditions) {
      const auto key = std::make_pair(bc.set, bc.component);
      current[key] = bc.value;
      if (bc.component < 0 || bc.component >= static_cast<int>(components.size()) ||
          mesh.node_sets.count(bc.set) == 0)
        continue;
      const auto it = previous.find(key);
      const double from = it == previous.end() ? 0.0 : it->second;
      const double step = std::abs(bc.value - from) / std::max(stage.increments, 1);
      if (!(step > size)) continue;
      warnings.push_back(
          bc.where + ": stage '" + stage.name + "': set '" + bc.set + "' component " +
          components[bc.component] + " moves " + input::number(step) + " m per increment (from " +
          input::number(from) + " to " + input::number(bc.value) + " m in " +
          std::to_string(stage.increments) + " increment" + (stage.increments == 1 ? "" : "s") +
          "), more than the model's size, " + input::number(size) +
          " m (its bounding-box diagonal): small-strain kinematics cannot describe such a step; "
          "check the value's units, or use more increments");
    }
    if (stage.reset_displacements) current.clear(); // the next stage starts from 0
    previous = std::move(current);
  }
  return warnings;
}

} // namespace bipot
