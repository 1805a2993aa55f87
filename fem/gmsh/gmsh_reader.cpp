#include "fem/gmsh/gmsh_reader.hpp"

#include "fem/core/error.hpp"
#include "fem/mesh/cell_facets.hpp"

#include "fem/gmsh/msh_cursor.hpp"
#include "fem/gmsh/msh_element_types.hpp"
#include "fem/gmsh/msh_file.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <unordered_map>

namespace bipot {

namespace {

std::optional<CellType> cell_type_of(int gmsh_type) {
  switch (gmsh_type) {
  case 15:
    return CellType::Point1;
  case 1:
    return CellType::Line2;
  case 8:
    return CellType::Line3;
  case 2:
    return CellType::Tri3;
  case 9:
    return CellType::Tri6;
  case 3:
    return CellType::Quad4;
  case 16:
    return CellType::Quad8;
  case 4:
    return CellType::Tet4;
  case 5:
    return CellType::Hex8;
  default:
    return std::nullopt;
  }
}

/// Element families in the order Gmsh lists an entity's elements (triangles before
/// quadrangles, tetrahedra before hexahedra, ...): the order cells had when libgmsh read the
/// files, kept so that cell numbers (and messages naming them) do not change.
int family_rank(int gmsh_type) {
  const msh::ElementType* t = msh::element_type(gmsh_type);
  const std::string name = t ? t->name : "";
  static const char* const order[] = {"Triangle",   "Quadrilateral", "Tetrahedron",
                                      "Hexahedron", "Prism",         "Pyramid"};
  for (int r = 0; r < 6; ++r)
    if (name.rfind(order[r], 0) == 0) return r;
  return 6;
}

/// Elements of one physical group, flattened over its entities.
struct Group {
  int dim = 0;
  int tag = 0;
  std::string name;
  std::vector<int> types;                      ///< Gmsh type per element
  std::vector<std::size_t> element_tags;       ///< per element
  std::vector<std::vector<std::size_t>> nodes; ///< Gmsh node tags per element
  std::vector<std::size_t> block_pos;          ///< file offset of the element's block
};

/// Physical groups in increasing (dimension, tag), each over its entities in increasing tag,
/// each entity's elements by family then in file order. A group exists if an entity carries
/// its tag, even without elements (a region without cells, an empty set).
std::vector<Group> groups_of(const msh::File& file) {
  std::map<msh::DimTag, std::vector<int>> entities_of; // group -> entity tags, increasing
  for (const auto& [entity, physicals] : file.entity_physicals)
    for (int p : physicals)
      entities_of[{entity.first, p}].push_back(entity.second);
  std::map<msh::DimTag, std::vector<const msh::ElementBlock*>> blocks_of; // entity -> blocks
  for (const msh::ElementBlock& b : file.element_blocks)
    blocks_of[{b.dim, b.entity}].push_back(&b);
  for (auto& [entity, blocks] : blocks_of)
    std::stable_sort(blocks.begin(), blocks.end(), [](const auto* a, const auto* b) {
      return family_rank(a->type) < family_rank(b->type);
    });

  std::vector<Group> groups;
  for (const auto& [dim_tag, entities] : entities_of) {
    Group g;
    g.dim = dim_tag.first;
    g.tag = dim_tag.second;
    auto name = file.physical_names.find(dim_tag);
    if (name != file.physical_names.end()) g.name = name->second;
    for (int entity : entities) {
      auto blocks = blocks_of.find({g.dim, entity});
      if (blocks == blocks_of.end()) continue;
      for (const msh::ElementBlock* b : blocks->second)
        for (std::size_t e = 0; e < b->tags.size(); ++e) {
          const auto per = std::size_t(b->nodes_per_element);
          g.types.push_back(b->type);
          g.element_tags.push_back(b->tags[e]);
          g.nodes.emplace_back(b->nodes.begin() + std::ptrdiff_t(e * per),
                               b->nodes.begin() + std::ptrdiff_t((e + 1) * per));
          g.block_pos.push_back(b->pos);
        }
    }
    groups.push_back(std::move(g));
  }
  return groups;
}

/// Signed measure of a cell's orientation: 2D twice the corner polygon's area (shoelace),
/// 3D the triple product of three edges at node 0. Positive = Gmsh's positive orientation.
double orientation(const Mesh& m, CellType type, const std::vector<Index>& n) {
  auto x = [&](int a, int d) { return m.nodes[n[a]][d]; };
  if (cell_dim(type) == 2) {
    const int nc = num_corners(type);
    double s = 0.0;
    for (int a = 0; a < nc; ++a) {
      const int b = (a + 1) % nc;
      s += x(a, 0) * x(b, 1) - x(b, 0) * x(a, 1);
    }
    return s;
  }
  if (cell_dim(type) != 3) return 1.0;
  const int i1 = 1, i2 = type == CellType::Hex8 ? 3 : 2, i3 = type == CellType::Hex8 ? 4 : 3;
  double e[3][3];
  for (int d = 0; d < 3; ++d) {
    e[0][d] = x(i1, d) - x(0, d);
    e[1][d] = x(i2, d) - x(0, d);
    e[2][d] = x(i3, d) - x(0, d);
  }
  return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
         e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
         e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}

/// Node permutation that mirrors a cell (reverses its orientation), mid-nodes following
/// their edges.
std::vector<int> mirror_permutation(CellType type) {
  switch (type) {
  case CellType::Tri3:
    return {0, 2, 1};
  case CellType::Tri6:
    return {0, 2, 1, 5, 4, 3};
  case CellType::Quad4:
    return {0, 3, 2, 1};
  case CellType::Quad8:
    return {0, 3, 2, 1, 7, 6, 5, 4};
  case CellType::Tet4:
    return {0, 2, 1, 3};
  case CellType::Hex8:
    return {0, 3, 2, 1, 4, 7, 6, 5};
  default:
    return {};
  }
}

FacetKey corner_key(const std::vector<Index>& corners) {
  return facet_key(corners.data(), static_cast<int>(corners.size()));
}

std::string group_name(const Group& g, int mesh_dim) {
  if (!g.name.empty()) return g.name;
  if (g.dim == mesh_dim) return "region_" + std::to_string(g.tag);
  return "physical_" + std::to_string(g.dim) + "_" + std::to_string(g.tag);
}

Mesh build_mesh(const msh::Cursor& at, const msh::File& file, const std::vector<Group>& groups) {
  const std::string& path = at.path();
  int dim = -1;
  for (const Group& g : groups)
    if (!g.types.empty()) dim = std::max(dim, g.dim);
  if (dim < 2)
    throw InputError(path + ": no physical surface or volume with elements (the reader needs "
                            "physical groups of dimension 2 or 3)");

  Mesh mesh;
  mesh.dim = dim;
  // Cells with Gmsh node tags first; nodes are renumbered once all cells are known.
  std::vector<CellType> types;
  std::vector<std::vector<std::size_t>> cells;
  std::vector<int> cell_region;
  std::unordered_map<std::size_t, std::string> owner; // element tag -> group name
  for (const Group& g : groups) {
    if (g.dim != dim) continue;
    const std::string name = group_name(g, dim);
    const int region = mesh.region_id(name);
    for (std::size_t e = 0; e < g.types.size(); ++e) {
      const auto type = cell_type_of(g.types[e]);
      if (!type || cell_dim(*type) != dim)
        at.fail_at(g.block_pos[e], "physical group '" + name + "' contains elements of type '" +
                                       msh::element_type(g.types[e])->name + "' (Gmsh type " +
                                       std::to_string(g.types[e]) +
                                       "), which bipot does not support (supported: tri3, tri6, "
                                       "quad4, quad8, tet4, hex8 cells)");
      auto [it, inserted] = owner.emplace(g.element_tags[e], name);
      if (!inserted)
        throw InputError(path + ": element " + std::to_string(g.element_tags[e]) +
                         " belongs to two physical groups, '" + it->second + "' and '" + name +
                         "'");
      types.push_back(*type);
      cells.push_back(g.nodes[e]);
      cell_region.push_back(region);
    }
  }

  std::vector<std::size_t> used;
  for (const auto& c : cells)
    used.insert(used.end(), c.begin(), c.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::unordered_map<std::size_t, Index> new_id;
  for (std::size_t i = 0; i < used.size(); ++i)
    new_id[used[i]] = Index(i);

  // Every element's nodes are defined: the parser checked each reference.
  mesh.nodes.resize(used.size());
  for (std::size_t i = 0; i < used.size(); ++i)
    mesh.nodes[i] = file.node_coords[file.node_of.at(used[i])];
  if (dim == 2) {
    double size = 0.0;
    for (const auto& x : mesh.nodes)
      size = std::max({size, std::abs(x[0]), std::abs(x[1])});
    for (const auto& x : mesh.nodes)
      if (std::abs(x[2]) > 1e-12 * size)
        throw InputError(path + ": a 2D mesh must lie in the plane z = 0");
  }

  std::vector<Index> ids;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    ids.clear();
    for (std::size_t tag : cells[c])
      ids.push_back(new_id.at(tag));
    if (orientation(mesh, types[c], ids) < 0.0) {
      const std::vector<Index> original = ids;
      const std::vector<int> perm = mirror_permutation(types[c]);
      for (std::size_t a = 0; a < perm.size(); ++a)
        ids[a] = original[perm[a]];
    }
    mesh.add_cell(types[c], ids, cell_region[c]);
  }

  // Facets of all cells by sorted corners, to orient the boundary elements.
  std::unordered_map<FacetKey, std::vector<std::pair<Index, int>>, FacetKeyHash> facets;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto local = cell_facets(mesh.cell_types[c]);
    const int nc = num_corners(facet_type(mesh.cell_types[c]));
    for (int f = 0; f < int(local.size()); ++f) {
      std::vector<Index> corners;
      for (int i = 0; i < nc; ++i)
        corners.push_back(mesh.cell(c)[local[f][i]]);
      facets[corner_key(corners)].push_back({c, f});
    }
  }

  for (const Group& g : groups) {
    if (g.dim >= dim) continue;
    const std::string name = group_name(g, dim);
    std::vector<Index>& node_set = mesh.node_sets[name];
    for (std::size_t e = 0; e < g.types.size(); ++e) {
      std::vector<Index> element_nodes;
      for (std::size_t tag : g.nodes[e]) {
        auto it = new_id.find(tag);
        if (it == new_id.end())
          throw InputError(path + ": node " + std::to_string(tag) + " of physical group '" + name +
                           "' is not a node of any cell");
        element_nodes.push_back(it->second);
      }
      node_set.insert(node_set.end(), element_nodes.begin(), element_nodes.end());
      if (g.dim != dim - 1) continue;
      const auto type = cell_type_of(g.types[e]);
      const int nc = type ? num_corners(*type) : 0;
      auto it = facets.end();
      if (nc > 0 && nc <= int(element_nodes.size()))
        it = facets.find(
            corner_key(std::vector<Index>(element_nodes.begin(), element_nodes.begin() + nc)));
      if (it == facets.end())
        throw InputError(path + ": element " + std::to_string(g.element_tags[e]) +
                         " of physical group '" + name + "' is not a facet of any cell");
      const auto [cell, f] = *std::min_element(
          it->second.begin(), it->second.end(), [&](const auto& a, const auto& b) {
            return std::make_pair(mesh.cell_regions[a.first], a.first) <
                   std::make_pair(mesh.cell_regions[b.first], b.first);
          });
      Facet facet;
      facet.type = facet_type(mesh.cell_types[cell]);
      facet.cell = cell;
      const auto local = cell_facets(mesh.cell_types[cell]); // keep alive: indexed below
      for (int i : local[f])
        facet.nodes.push_back(mesh.cell(cell)[i]);
      mesh.facet_sets[name].push_back(std::move(facet));
    }
    std::sort(node_set.begin(), node_set.end());
    node_set.erase(std::unique(node_set.begin(), node_set.end()), node_set.end());
  }
  mesh.check_consistency();
  return mesh;
}

/// The file's bytes. Its start is checked before the rest is read, so that a file that is
/// not a mesh (/dev/zero, a YAML file given by mistake) is refused at once, and its size is
/// bounded before it is read into memory.
std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the Gmsh mesh file (missing or unreadable)");
  const std::string magic = "$MeshFormat";
  std::string text(magic.size(), '\0');
  in.read(text.data(), std::streamsize(text.size()));
  text.resize(std::size_t(in.gcount()));
  if (text != magic)
    throw InputError(path + ": not a Gmsh MSH file (it does not start with $MeshFormat)");
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, std::size_t(in.gcount()));
    if (text.size() > kMaxMshBytes)
      throw InputError(path + ": larger than " + std::to_string(kMaxMshBytes >> 20) +
                       " MiB, the largest mesh file bipot reads");
  }
  if (in.bad()) throw InputError(path + ": read error in the Gmsh mesh file");
  return text;
}

} // namespace

Mesh read_gmsh(const std::string& path) {
  const std::string text = read_bytes(path);
  const msh::File file = msh::parse(path, text);
  return build_mesh(msh::Cursor(path, text), file, groups_of(file));
}

} // namespace bipot
