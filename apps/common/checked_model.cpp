#include "apps/common/checked_model.hpp"

#include "fem/core/error.hpp"
#include "fem/input/condition_checks.hpp"
#include "fem/input/mesh_checks.hpp"
#include "fem/input/rigid_body_checks.hpp"

#include <algorithm>

namespace bipot::app {

Model checked_model(const ProblemSpec& spec) {
  Model model = build_model(spec);
  // Every interface's pairs coincide on purpose; those that can open do not hold one body to
  // the other.
  std::vector<std::pair<Index, Index>> joined;
  std::vector<OpeningInterface> opening;
  for (std::size_t k = 0; k < model.interfaces.size(); ++k) {
    const contact::Interface& iface = model.interfaces[k];
    OpeningInterface o;
    o.name = iface.name;
    o.smallest_gap = iface.pairs.empty() ? 0.0 : iface.pairs.front().gap;
    for (const auto& pair : iface.pairs) {
      joined.emplace_back(pair.node_a, pair.node_b);
      o.pairs.emplace_back(pair.node_a, pair.node_b);
      o.smallest_gap = std::min(o.smallest_gap, pair.gap);
    }
    o.smallest_gap += iface.initial_gap;
    if (!contact::shares_nodes(iface)) opening.push_back(std::move(o));
  }
  const MeshSpec& m = model.spec.mesh;
  const std::string where = m.where + (m.has_blocks || m.file.empty() ? "" : ": " + m.file);
  std::vector<std::string> problems = conflicting_conditions(model.spec, model.mesh);
  const auto mesh = mesh_problems(model.mesh, model.kinematics, joined, where);
  problems.insert(problems.end(), mesh.begin(), mesh.end());
  // Rigid motions of a mesh with NaN nodes or inverted cells would only add noise.
  if (mesh.empty()) {
    const auto free = free_rigid_body_modes(model.spec, model.mesh, opening);
    problems.insert(problems.end(), free.begin(), free.end());
  }
  if (!problems.empty()) throw InputError(problems);
  return model;
}

} // namespace bipot::app
