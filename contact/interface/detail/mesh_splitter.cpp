#include "contact/interface/detail/mesh_splitter.hpp"

#include "fem/core/error.hpp"
#include "fem/mesh/cell_facets.hpp"

#include <algorithm>
#include <numeric>
#include <set>

namespace bipot::contact::detail {

namespace {

void sort_unique(std::vector<Index>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

void renumber(std::vector<Index>& ids, const std::map<Index, Index>& copy_of) {
  for (Index& v : ids) {
    const auto it = copy_of.find(v);
    if (it != copy_of.end()) v = it->second;
  }
}

} // namespace

MeshSplitter::MeshSplitter(Mesh& mesh)
    : mesh_(mesh), original_cell_nodes_(mesh.cell_nodes), position_(mesh.nodes.size()) {
  std::iota(position_.begin(), position_.end(), Index(0));
  node_cell_offsets_.assign(mesh.nodes.size() + 1, 0);
  for (Index v : mesh.cell_nodes)
    ++node_cell_offsets_[v + 1];
  std::partial_sum(node_cell_offsets_.begin(), node_cell_offsets_.end(),
                   node_cell_offsets_.begin());
  node_cells_.resize(node_cell_offsets_.back());
  std::vector<Index> fill(node_cell_offsets_.begin(), node_cell_offsets_.end() - 1);
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_num_nodes(c); ++k)
      node_cells_[fill[mesh.cell(c)[k]]++] = c;
}

Index& MeshSplitter::id_in_cell(Index c, Index v) {
  for (Index k = mesh_.cell_offsets[c]; k < mesh_.cell_offsets[c + 1]; ++k)
    if (original_cell_nodes_[k] == v) return mesh_.cell_nodes[k];
  throw Error("MeshSplitter: internal: node " + std::to_string(v) + " is not in cell " +
              std::to_string(c));
}

bool MeshSplitter::held_by_region(const Facet& f, int region) const {
  if (f.nodes.empty()) return false;
  const int corners = num_corners(f.type);
  const Index v = position_[f.nodes[0]];
  for (Index j = node_cell_offsets_[v]; j < node_cell_offsets_[v + 1]; ++j) {
    const Index c = node_cells_[j];
    if (mesh_.cell_regions[c] != region) continue;
    const Index* begin = mesh_.cell(c);
    const Index* end = begin + mesh_.cell_num_nodes(c);
    bool all = true;
    for (int i = 0; i < corners && all; ++i)
      all = std::find(begin, end, f.nodes[i]) != end;
    if (all) return true;
  }
  return false;
}

void MeshSplitter::split(const std::vector<Facet>& facets, int region_a, int region_b,
                         bool tie_only, Interface& iface) {
  // Body-1 facets in current ids: region a may have been region b of an earlier interface.
  std::vector<Index> positions;
  for (const Facet& f : facets) {
    Facet g = f;
    for (Index& v : g.nodes)
      v = id_in_cell(f.cell, v);
    iface.facets_a.push_back(std::move(g));
    positions.insert(positions.end(), f.nodes.begin(), f.nodes.end());
  }
  sort_unique(positions);

  // Which cell-less set facets are on side b must be decided before the cells change.
  std::vector<const Facet*> orphans_b;
  if (!tie_only)
    for (const auto& kv : mesh_.facet_sets)
      for (const Facet& f : kv.second)
        if (f.cell < 0 && held_by_region(f, region_b)) orphans_b.push_back(&f);

  std::map<Index, Index> copy_of; // id shared by both sides -> id now used by region b
  for (Index v : positions) {
    Index id_a = -1, id_b = -1;
    bool shared = false;
    for (Index j = node_cell_offsets_[v]; j < node_cell_offsets_[v + 1]; ++j) {
      const Index c = node_cells_[j];
      if (mesh_.cell_regions[c] == region_a) id_a = id_in_cell(c, v);
    }
    for (Index j = node_cell_offsets_[v]; j < node_cell_offsets_[v + 1]; ++j) {
      const Index c = node_cells_[j];
      if (mesh_.cell_regions[c] != region_b) continue;
      id_b = id_in_cell(c, v);
      shared = shared || id_b == id_a;
    }
    if (tie_only) {
      id_b = id_a;
    } else if (shared) {
      // Every region-b cell at v uses id_a (cells of one region at one position always share
      // an id): all of them move to the copy.
      const auto [it, created] = copies_.try_emplace({v, region_a}, mesh_.num_nodes());
      if (created) {
        mesh_.nodes.push_back(mesh_.nodes[v]);
        position_.push_back(v);
      }
      id_b = it->second;
      for (Index j = node_cell_offsets_[v]; j < node_cell_offsets_[v + 1]; ++j) {
        const Index c = node_cells_[j];
        if (mesh_.cell_regions[c] == region_b) id_in_cell(c, v) = id_b;
      }
      copy_of[id_a] = id_b;
    }
    // else: an earlier interface already separated the two sides here.
    InterfacePair p;
    p.node_a = id_a;
    p.node_b = id_b;
    iface.pairs.push_back(p);
  }

  if (!copy_of.empty()) {
    update_sets(copy_of, region_b, orphans_b);
    for (Built& b : built_) {
      if (b.region_a == region_b) {
        for (InterfacePair& p : b.iface->pairs)
          if (copy_of.count(p.node_a)) p.node_a = copy_of.at(p.node_a);
        for (Facet& f : b.iface->facets_a)
          renumber(f.nodes, copy_of);
      }
      if (b.region_b == region_b)
        for (InterfacePair& p : b.iface->pairs)
          if (copy_of.count(p.node_b)) p.node_b = copy_of.at(p.node_b);
    }
  }
  built_.push_back({&iface, region_a, region_b});
}

void MeshSplitter::update_sets(const std::map<Index, Index>& copy_of, int region_b,
                               const std::vector<const Facet*>& orphans_b) {
  const std::set<const Facet*> orphans(orphans_b.begin(), orphans_b.end());
  for (auto& kv : mesh_.facet_sets)
    for (Facet& f : kv.second) {
      const bool side_b = f.cell >= 0 ? mesh_.cell_regions[f.cell] == region_b : orphans.count(&f);
      if (side_b) renumber(f.nodes, copy_of);
    }
  for (auto& kv : mesh_.node_sets) {
    std::vector<Index>& ids = kv.second;
    const std::size_t n = ids.size();
    for (std::size_t i = 0; i < n; ++i) {
      const auto it = copy_of.find(ids[i]);
      if (it != copy_of.end()) ids.push_back(it->second);
    }
    sort_unique(ids);
  }
}

} // namespace bipot::contact::detail
