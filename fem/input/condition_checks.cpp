#include "fem/input/condition_checks.hpp"

#include "fem/input/detail/check_support.hpp"
#include "fem/input/detail/sections.hpp"

#include <set>
#include <unordered_map>

namespace bipot {

std::vector<std::string> conflicting_conditions(const ProblemSpec& spec, const Mesh& mesh) {
  std::vector<std::string> problems;
  const auto& components = input::component_names(spec.kinematics);
  for (const auto& stage : spec.stages) {
    const auto& bcs = stage.boundary_conditions;
    std::unordered_map<Index, std::size_t> first; // node * 3 + component -> condition
    std::set<std::pair<std::size_t, std::size_t>> reported;
    for (std::size_t j = 0; j < bcs.size(); ++j) {
      const DirichletSpec& bc = bcs[j];
      if (bc.component < 0 || bc.component >= static_cast<int>(components.size())) continue;
      for (Index node : mesh.set_nodes(bc.set)) {
        const auto [at, inserted] = first.emplace(3 * node + bc.component, j);
        const DirichletSpec& other = bcs[at->second];
        if (inserted || other.set == bc.set || other.value == bc.value ||
            !reported.emplace(at->second, j).second)
          continue;
        problems.push_back(bc.where + ": " + mesh.describe_node(node) + " of set '" + bc.set +
                           "' is also in set '" + other.set + "', whose condition (" + other.where +
                           ") fixes its component " + components[bc.component] + " to " +
                           input::number(other.value) + " in the same stage, this one to " +
                           input::number(bc.value));
      }
    }
  }
  return problems;
}

} // namespace bipot
