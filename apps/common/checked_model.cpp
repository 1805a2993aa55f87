#include "apps/common/checked_model.hpp"
#include "apps/common/run_folder.hpp"

#include "fem/core/error.hpp"
#include "fem/input/condition_checks.hpp"
#include "fem/input/increment_checks.hpp"
#include "fem/input/mesh_checks.hpp"
#include "fem/input/rigid_body_checks.hpp"

#include "fem/linalg/communicator.hpp"

#include <algorithm>
#include <iostream>
#include <optional>

namespace bipot::app {

namespace {

// A node held by a bonded obstacle already has every component prescribed: a boundary
// condition of its own would silently lose to the obstacle's motion.
void held_node_conditions(const Model& model, std::vector<Index> held,
                          std::vector<std::string>& problems) {
  if (held.empty()) return;
  std::sort(held.begin(), held.end());
  for (const auto& stage : model.spec.stages)
    for (const auto& bc : stage.boundary_conditions) {
      if (!model.mesh.node_sets.count(bc.set) && !model.mesh.facet_sets.count(bc.set)) continue;
      for (Index n : model.mesh.set_nodes(bc.set))
        if (std::binary_search(held.begin(), held.end(), n)) {
          problems.push_back(bc.where + ": " + model.mesh.describe_node(n) + " of set '" + bc.set +
                             "' is held by a perfectly bonded obstacle, which prescribes its "
                             "displacement; remove the condition or move the obstacle");
          break;
        }
    }
}

} // namespace

Model checked_model(const ProblemSpec& spec, const Catalogue& catalogue) {
  Model model = build_model(spec, catalogue);
  // Every interface's pairs coincide on purpose; those that can open do not hold one body to
  // the other.
  std::vector<std::pair<Index, Index>> joined;
  std::vector<OpeningInterface> opening;
  const std::vector<Index> held = // by perfectly bonded obstacles
      model.interface_module ? model.interface_module->held_nodes(model) : std::vector<Index>{};
  for (std::size_t k = 0; k < model.interfaces.size(); ++k) {
    const InterfaceMesh& iface = model.interfaces[k];
    OpeningInterface o;
    o.name = iface.name;
    o.smallest_gap = iface.pairs.empty() ? 0.0 : iface.pairs.front().gap;
    for (const auto& pair : iface.pairs) {
      if (pair.node_b != rigid_obstacle) joined.emplace_back(pair.node_a, pair.node_b);
      o.pairs.emplace_back(pair.node_a, pair.node_b);
      o.smallest_gap = std::min(o.smallest_gap, pair.gap);
    }
    o.smallest_gap += iface.initial_gap;
    if (!shares_nodes(iface)) opening.push_back(std::move(o));
  }
  const MeshSpec& m = model.spec.mesh;
  const std::string where = m.where + (m.has_blocks || m.file.empty() ? "" : ": " + m.file);
  std::vector<std::string> problems = conflicting_conditions(model.spec, model.mesh);
  held_node_conditions(model, held, problems);
  std::vector<Index> references;
  for (const RigidBody& b : model.rigid_bodies)
    references.insert(references.end(), {b.reference, b.rotation});
  const auto mesh = mesh_problems(model.mesh, model.kinematics, joined, where, references);
  problems.insert(problems.end(), mesh.begin(), mesh.end());
  // Rigid motions of a mesh with NaN nodes or inverted cells would only add noise.
  if (mesh.empty()) {
    std::vector<ReferenceNode> reference_nodes;
    for (const RigidBody& b : model.rigid_bodies)
      reference_nodes.push_back({b.name, b.nodes.empty() ? Index(-1) : b.nodes.front(), b.point});
    const auto free = free_rigid_body_modes(model.spec, model.mesh, opening, held, reference_nodes);
    problems.insert(problems.end(), free.begin(), free.end());
  }
  // What only the whole model shows to the interface module (generalized_newton's dense
  // condensed system too large): refused here rather than once `run` has built the analysis.
  if (model.interface_module) {
    const auto found = model.interface_module->check(model);
    problems.insert(problems.end(), found.begin(), found.end());
  }
  if (!problems.empty()) throw InputError(problems);
  return model;
}

Model checked_model_and_results_folder(const ProblemSpec& spec, const Catalogue& catalogue) {
  std::vector<std::string> problems;
  std::optional<Model> model;
  try {
    model.emplace(checked_model(spec, catalogue));
  } catch (const InputError& e) {
    problems = e.problems();
  }
  const std::string output = results_folder_problem(spec.output.directory);
  if (!output.empty())
    problems.push_back((spec.output.where.empty() ? spec.file + ": output.directory (default '" +
                                                        spec.output.directory + "')"
                                                  : spec.output.where) +
                       ": cannot write the results: " + output);
  if (!problems.empty()) throw InputError(problems);
  return std::move(*model);
}

void print_model_warnings(const Model& model, const std::string& program) {
  if (mpi_rank() != 0) return;
  for (const auto& line : large_increment_warnings(model.spec, model.mesh))
    std::cerr << program << ": warning: " << line << "\n";
}

} // namespace bipot::app
