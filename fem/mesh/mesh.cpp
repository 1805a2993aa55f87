#include "fem/mesh/mesh.hpp"

#include "fem/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace bipot {

Index Mesh::add_cell(CellType type, const std::vector<Index>& node_ids, int region) {
  cell_types.push_back(type);
  cell_nodes.insert(cell_nodes.end(), node_ids.begin(), node_ids.end());
  cell_offsets.push_back(static_cast<Index>(cell_nodes.size()));
  cell_regions.push_back(region);
  return num_cells() - 1;
}

int Mesh::region_id(const std::string& name) {
  auto it = regions.find(name);
  if (it != regions.end()) return it->second;
  int id = 0;
  for (const auto& kv : regions)
    id = std::max(id, kv.second + 1);
  regions[name] = id;
  return id;
}

std::string Mesh::region_name(int id) const {
  for (const auto& kv : regions)
    if (kv.second == id) return kv.first;
  return "";
}

std::vector<Index> Mesh::facet_set_nodes(const std::string& name) const {
  std::vector<Index> out;
  auto it = facet_sets.find(name);
  if (it == facet_sets.end()) return out;
  for (const auto& f : it->second)
    out.insert(out.end(), f.nodes.begin(), f.nodes.end());
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<Index> Mesh::set_nodes(const std::string& name) const {
  const auto it = node_sets.find(name);
  return it != node_sets.end() ? it->second : facet_set_nodes(name);
}

std::string Mesh::describe_node(Index id) const {
  std::string at = " at (";
  for (int i = 0; i < dim; ++i) {
    char buf[32];
    // "nan" whatever its sign bit: "-nan" reads as a negative number.
    std::snprintf(buf, sizeof buf, "%.9g",
                  std::isnan(nodes[id][i]) ? std::fabs(nodes[id][i]) : nodes[id][i]);
    at += (i ? ", " : "") + std::string(buf);
  }
  return "node " + std::to_string(id) + at + ")";
}

void Mesh::check_consistency() const {
  const Index n = num_nodes();
  if (cell_offsets.size() != cell_types.size() + 1 || cell_regions.size() != cell_types.size())
    throw Error("mesh: cell arrays have inconsistent sizes");
  for (Index c = 0; c < num_cells(); ++c) {
    if (cell_num_nodes(c) != bipot::num_nodes(cell_types[c]))
      throw Error("mesh: cell " + std::to_string(c) + " has the wrong number of nodes");
    for (int a = 0; a < cell_num_nodes(c); ++a)
      if (cell(c)[a] < 0 || cell(c)[a] >= n)
        throw Error("mesh: cell " + std::to_string(c) + " references missing node");
  }
  for (const auto& [name, ids] : node_sets)
    for (Index i : ids)
      if (i < 0 || i >= n) throw Error("mesh: node set '" + name + "' references missing node");
  for (const auto& [name, facets] : facet_sets)
    for (const auto& f : facets) {
      for (Index i : f.nodes)
        if (i < 0 || i >= n) throw Error("mesh: facet set '" + name + "' references missing node");
      if (f.cell >= num_cells())
        throw Error("mesh: facet set '" + name + "' references missing cell");
    }
}

} // namespace bipot
