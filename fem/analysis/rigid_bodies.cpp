// Rigid bodies in the model: which nodes follow which reference node, and the checks that
// need the mesh.
#include "fem/analysis/model.hpp"

#include "fem/core/error.hpp"
#include "fem/core/nearest_name.hpp"

#include <algorithm>
#include <set>

namespace bipot {

namespace {

// The nodes of a region's cells, or of a node or facet set; empty with a problem if unknown.
std::vector<Index> body_nodes(const Mesh& mesh, const RigidBodySpec& b,
                              std::vector<std::string>& problems) {
  std::vector<Index> nodes;
  if (!b.region.empty()) {
    const auto it = mesh.regions.find(b.region);
    if (it == mesh.regions.end()) {
      std::vector<std::string> known;
      for (const auto& kv : mesh.regions)
        known.push_back(kv.first);
      problems.push_back(b.where + ": rigid body '" + b.name +
                         "': " + unknown_in_mesh("region", b.region, known));
      return nodes;
    }
    for (Index c = 0; c < mesh.num_cells(); ++c)
      if (mesh.cell_regions[c] == it->second)
        nodes.insert(nodes.end(), mesh.cell(c), mesh.cell(c) + mesh.cell_num_nodes(c));
  } else {
    if (!mesh.node_sets.count(b.set) && !mesh.facet_sets.count(b.set)) {
      std::vector<std::string> known;
      for (const auto& kv : mesh.node_sets)
        known.push_back(kv.first);
      for (const auto& kv : mesh.facet_sets)
        known.push_back(kv.first);
      problems.push_back(b.where + ": rigid body '" + b.name +
                         "': " + unknown_in_mesh("node or facet set", b.set, known));
      return nodes;
    }
    nodes = mesh.set_nodes(b.set);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  if (nodes.empty()) problems.push_back(b.where + ": rigid body '" + b.name + "' has no nodes");
  return nodes;
}

} // namespace

void add_rigid_bodies(Model& model) {
  const ProblemSpec& spec = model.spec;
  if (spec.rigid_bodies.empty()) {
    for (const auto& stage : spec.stages)
      if (!stage.rigid_body_conditions.empty())
        throw InputError({stage.rigid_body_conditions.front().where +
                          ": no rigid body is declared (top-level 'rigid_bodies')"});
    return;
  }
  Mesh& mesh = model.mesh;
  std::vector<std::string> problems;
  std::vector<int> body_of(mesh.num_nodes(), -1);
  std::vector<std::string> names;
  for (std::size_t k = 0; k < spec.rigid_bodies.size(); ++k) {
    const RigidBodySpec& b = spec.rigid_bodies[k];
    names.push_back(b.name);
    RigidBody body;
    body.name = b.name;
    body.nodes = body_nodes(mesh, b, problems);
    for (Index n : body.nodes) {
      if (body_of[n] >= 0) {
        problems.push_back(b.where + ": rigid body '" + b.name + "': " + mesh.describe_node(n) +
                           " also belongs to rigid body '" + spec.rigid_bodies[body_of[n]].name +
                           "'; make them one body");
        break;
      }
      body_of[n] = static_cast<int>(k);
    }
    if (!b.reference_point.empty()) {
      for (std::size_t i = 0; i < b.reference_point.size(); ++i)
        body.point[i] = b.reference_point[i];
    } else if (!body.nodes.empty()) {
      for (Index n : body.nodes)
        for (int i = 0; i < 3; ++i)
          body.point[i] += mesh.nodes[n][i] / static_cast<double>(body.nodes.size());
    }
    model.rigid_bodies.push_back(std::move(body));
  }
  // A bonded obstacle holds its nodes: they cannot also follow a reference node.
  const std::vector<Index> held =
      model.interface_module ? model.interface_module->held_nodes(model) : std::vector<Index>{};
  for (std::size_t k = 0; k < model.interfaces.size(); ++k) {
    if (!model.interfaces[k].obstacle) continue;
    for (const auto& p : model.interfaces[k].pairs)
      if (body_of[p.node_a] >= 0 && std::count(held.begin(), held.end(), p.node_a)) {
        problems.push_back(spec.interfaces[k].where + ": interface '" + model.interfaces[k].name +
                           "': " + mesh.describe_node(p.node_a) +
                           " is held by this bonded obstacle and belongs to rigid body '" +
                           spec.rigid_bodies[body_of[p.node_a]].name +
                           "'; bond the body through its reference node instead");
        break;
      }
  }
  // generalized_newton condenses on the interface DOFs, which must be unknowns.
  if (model.contact_solver.exact_newton())
    for (std::size_t k = 0; k < model.interfaces.size(); ++k) {
      if (shares_nodes(model.interfaces[k])) continue; // tied: not condensed
      for (const auto& p : model.interfaces[k].pairs) {
        const Index n = body_of[p.node_a] >= 0 ? p.node_a : p.node_b;
        if (n < 0 || body_of[n] < 0) continue;
        problems.push_back(
            (spec.contact_solver.where.empty() ? spec.file : spec.contact_solver.where) +
            ": contact_solver.type: generalized_newton condenses the model on its "
            "interface nodes, and " +
            mesh.describe_node(n) + " of interface '" + model.interfaces[k].name +
            "' belongs to rigid body '" + spec.rigid_bodies[body_of[n]].name +
            "'; use semismooth_newton or bipotential_uzawa");
        break;
      }
    }
  // A boundary condition on a body's node would fight its reference node.
  for (const auto& stage : spec.stages) {
    for (const auto& bc : stage.boundary_conditions) {
      if (!mesh.node_sets.count(bc.set) && !mesh.facet_sets.count(bc.set)) continue;
      for (Index n : mesh.set_nodes(bc.set))
        if (body_of[n] >= 0) {
          problems.push_back(bc.where + ": " + mesh.describe_node(n) + " of set '" + bc.set +
                             "' belongs to rigid body '" + spec.rigid_bodies[body_of[n]].name +
                             "', whose motion is its reference node's; give the condition to the "
                             "body in the stage's 'rigid_bodies'");
          break;
        }
    }
    for (const auto& c : stage.rigid_body_conditions)
      if (std::find(names.begin(), names.end(), c.body) == names.end()) {
        std::string msg = "no rigid body named '" + c.body + "'";
        const auto near = nearest_name(c.body, names);
        if (!near.empty()) msg += " (did you mean '" + near + "'?)";
        problems.push_back(c.where + ": " + msg + "; declared: " + join_names(names));
      }
  }
  if (!problems.empty()) throw InputError(problems);
  for (RigidBody& body : model.rigid_bodies) {
    body.reference = mesh.num_nodes();
    mesh.nodes.push_back(body.point);
    body.rotation = mesh.num_nodes();
    mesh.nodes.push_back(body.point);
  }
}

} // namespace bipot
