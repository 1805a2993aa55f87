#include "fem/analysis/model.hpp"

#include "fem/analysis/initial_stress.hpp"

#include "fem/core/error.hpp"

#include "fem/core/nearest_name.hpp"
#include "fem/gmsh/gmsh_reader.hpp"
#include "fem/mesh/structured_mesh.hpp"
#include <algorithm>
#include <cmath>

namespace bipot {

namespace {

CellType parse_cell(const std::string& name) {
  for (CellType t : {CellType::Tri3, CellType::Tri6, CellType::Quad4, CellType::Quad8,
                     CellType::Tet4, CellType::Hex8})
    if (to_string(t) == name) return t;
  throw InputError("unknown cell type '" + name + "'");
}

std::vector<std::string> keys_of(const std::map<std::string, std::vector<Index>>& m) {
  std::vector<std::string> out;
  for (const auto& kv : m)
    out.push_back(kv.first);
  return out;
}

std::string unknown_set(const std::string& kind, const std::string& name,
                        const std::vector<std::string>& known) {
  return unknown_in_mesh(kind, name, known);
}

// Node sets selected by boxes; the tolerance is relative to the mesh size so that nodes on a
// box face are in. An empty set is an error (a typo in a coordinate, most likely).
void add_box_sets(const MeshSpec& spec, Mesh& mesh, std::vector<std::string>& problems) {
  if (spec.box_sets.empty()) return;
  std::array<double, 3> lo = {INFINITY, INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY, -INFINITY};
  for (const auto& x : mesh.nodes)
    for (int i = 0; i < 3; ++i)
      lo[i] = std::min(lo[i], x[i]), hi[i] = std::max(hi[i], x[i]);
  double diagonal = 0;
  for (int i = 0; i < 3; ++i)
    diagonal += (hi[i] - lo[i]) * (hi[i] - lo[i]);
  const double tol = 1e-9 * std::sqrt(diagonal);
  for (const auto& box : spec.box_sets) {
    std::vector<Index> ids;
    for (Index n = 0; n < mesh.num_nodes(); ++n) {
      bool inside = true;
      for (std::size_t i = 0; i < box.min.size(); ++i)
        inside =
            inside && mesh.nodes[n][i] >= box.min[i] - tol && mesh.nodes[n][i] <= box.max[i] + tol;
      if (inside) ids.push_back(n);
    }
    if (ids.empty())
      problems.push_back(box.where + ": no mesh node lies in this box");
    else if (mesh.node_sets.count(box.name) || mesh.facet_sets.count(box.name))
      problems.push_back(box.where + ": the mesh already has a set named '" + box.name + "'");
    else
      mesh.node_sets[box.name] = ids;
  }
}

// Keeps in each region-restricted box set only the nodes of that region's cells. Runs after
// the interface split, so that the set takes one side's copies of the interface nodes.
void restrict_sets_to_regions(const MeshSpec& spec, Mesh& mesh) {
  std::vector<std::string> problems;
  for (const auto& box : spec.box_sets) {
    if (box.region.empty()) continue;
    const int region = mesh.regions.at(box.region);
    std::vector<bool> in_region(mesh.num_nodes(), false);
    for (Index c = 0; c < mesh.num_cells(); ++c)
      if (mesh.cell_regions[c] == region)
        for (int k = 0; k < mesh.cell_num_nodes(c); ++k)
          in_region[mesh.cell(c)[k]] = true;
    auto& ids = mesh.node_sets[box.name];
    ids.erase(std::remove_if(ids.begin(), ids.end(), [&](Index n) { return !in_region[n]; }),
              ids.end());
    if (ids.empty())
      problems.push_back(box.where + ": no node of region '" + box.region + "' lies in this box");
  }
  if (!problems.empty()) throw InputError(problems);
}

} // namespace

Mesh build_mesh(const MeshSpec& spec, int dim) {
  if (!spec.has_blocks) return read_gmsh(spec.file);
  BlockMeshSpec b;
  b.x = spec.x;
  b.y = spec.y;
  if (dim == 3) b.z = spec.z;
  b.cell = parse_cell(spec.cell);
  b.block_regions = spec.block_regions;
  for (Diagonals d :
       {Diagonals::Right, Diagonals::Left, Diagonals::Alternating, Diagonals::Crossed})
    if (spec.diagonals == to_string(d)) b.diagonals = d; // validated by the reader
  return make_block_mesh(b);
}

Model build_model(const ProblemSpec& spec, const Registry<Material>& materials,
                  std::shared_ptr<const InterfaceModule> interfaces) {
  Model model;
  model.spec = spec;
  model.kinematics = parse_kinematics(spec.kinematics);
  const int dim = spatial_dim(model.kinematics);
  try {
    model.mesh = build_mesh(spec.mesh, dim);
  } catch (const InputError& e) {
    std::vector<std::string> problems;
    for (const auto& p : e.problems())
      problems.push_back(spec.mesh.where + ": " + p);
    throw InputError(problems);
  }
  std::vector<std::string> problems;
  add_box_sets(spec.mesh, model.mesh, problems);
  const Mesh& mesh = model.mesh;
  if (mesh.dim != dim)
    problems.push_back(spec.mesh.where + ": the mesh is " + std::to_string(mesh.dim) +
                       "D but kinematics '" + spec.kinematics + "' needs " + std::to_string(dim) +
                       "D");
  if (model.kinematics == Kinematics::Axisymmetric) {
    for (Index n = 0; n < mesh.num_nodes(); ++n)
      if (mesh.nodes[n][0] < -1e-12) {
        problems.push_back(spec.mesh.where + ": axisymmetric meshes need r = x >= 0; node " +
                           std::to_string(n) + " has r = " + std::to_string(mesh.nodes[n][0]));
        break;
      }
  }

  // Materials by region.
  std::vector<std::string> region_names;
  int max_id = -1;
  for (const auto& [name, id] : mesh.regions) {
    region_names.push_back(name);
    max_id = std::max(max_id, id);
  }
  model.material_of_region.assign(max_id + 1, nullptr);
  for (const auto& m : spec.materials) {
    auto it = mesh.regions.find(m.region);
    if (it == mesh.regions.end()) {
      problems.push_back(m.where + ": " + unknown_set("region", m.region, region_names));
      continue;
    }
    model.materials.push_back(materials.create_validated(m.type, m.parameters));
    model.material_of_region[it->second] = model.materials.back().get();
  }
  std::vector<bool> region_used(max_id + 1, false);
  for (int r : mesh.cell_regions)
    region_used[r] = true;
  // A named pair, not a structured binding: C++17 lambdas may not capture bindings, which
  // clang (the fuzzing build, scripts/fuzz.sh) refuses.
  for (const auto& region : mesh.regions) {
    const std::string& name = region.first;
    if (region_used[region.second] && !model.material_of_region[region.second] &&
        std::none_of(spec.materials.begin(), spec.materials.end(),
                     [&](const MaterialSpec& m) { return m.region == name; }))
      problems.push_back(spec.file + ": materials: region '" + name +
                         "' of the mesh has no material");
  }

  // Sets named by stages.
  std::vector<std::string> facet_names;
  for (const auto& kv : mesh.facet_sets)
    facet_names.push_back(kv.first);
  const auto node_names = keys_of(mesh.node_sets);
  for (const auto& stage : spec.stages) {
    for (const auto& bc : stage.boundary_conditions)
      if (!mesh.node_sets.count(bc.set) && !mesh.facet_sets.count(bc.set))
        problems.push_back(bc.where + ": " + unknown_set("node or facet set", bc.set, node_names));
    for (const auto& ld : stage.loads)
      if (ld.type != LoadSpec::Type::Gravity && !mesh.facet_sets.count(ld.set))
        problems.push_back(ld.where + ": " + unknown_set("facet set", ld.set, facet_names));
  }
  for (const auto& box : spec.mesh.box_sets)
    if (!box.region.empty() && !mesh.regions.count(box.region))
      problems.push_back(box.where + ": " + unknown_set("region", box.region, region_names));
  std::vector<std::string> interface_names;
  for (const auto& iface : spec.interfaces)
    interface_names.push_back(iface.name);
  for (const auto& stage : spec.stages)
    for (const auto& gap : stage.interface_gaps)
      if (std::find(interface_names.begin(), interface_names.end(), gap.interface) ==
          interface_names.end()) {
        std::string msg = "no interface named '" + gap.interface + "'";
        const auto near = nearest_name(gap.interface, interface_names);
        if (!near.empty()) msg += " (did you mean '" + near + "'?)";
        problems.push_back(
            gap.where + ": " + msg + "; declared: " +
            (interface_names.empty() ? std::string("none") : join_names(interface_names)));
      }
  for (const auto& stage : spec.stages)
    for (const auto& d : stage.obstacle_displacements) {
      const auto it = std::find_if(spec.interfaces.begin(), spec.interfaces.end(),
                                   [&](const InterfaceSpec& i) { return i.name == d.interface; });
      std::vector<std::string> obstacles;
      for (const auto& iface : spec.interfaces)
        if (iface.obstacle) obstacles.push_back(iface.name);
      if (it == spec.interfaces.end() || !it->obstacle) {
        std::string msg = it == spec.interfaces.end()
                              ? "no interface named '" + d.interface + "'"
                              : "interface '" + d.interface + "' has no obstacle";
        const auto near = nearest_name(d.interface, obstacles);
        if (!near.empty() && near != d.interface) msg += " (did you mean '" + near + "'?)";
        problems.push_back(d.where + ": " + msg + "; interfaces with an obstacle: " +
                           (obstacles.empty() ? std::string("none") : join_names(obstacles)));
      }
    }
  for (const auto& s : spec.initial_stress)
    if (!mesh.regions.count(s.region))
      problems.push_back(s.where + ": " + unknown_set("region", s.region, region_names));
  if (!problems.empty()) throw InputError(problems);
  if (interfaces) {
    interfaces->build(model); // splits the mesh along the interfaces
  } else if (!spec.interfaces.empty()) {
    throw InputError({spec.interfaces.front().where +
                      ": no interface module was given to build and enforce interfaces"});
  }
  model.interface_module = std::move(interfaces);
  restrict_sets_to_regions(spec.mesh, model.mesh);
  check_initial_stress_admissible(model);
  add_rigid_bodies(model); // last: its reference nodes end the mesh
  return model;
}

} // namespace bipot
