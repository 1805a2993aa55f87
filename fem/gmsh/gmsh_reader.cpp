#include "fem/gmsh/gmsh_reader.hpp"

#include "fem/core/error.hpp"
#include "fem/mesh/cell_facets.hpp"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <mutex>
#include <optional>
#include <sstream>
#include <unordered_map>

namespace bipot {

namespace {

/// One Gmsh session, serialised by a process-wide mutex. The flag guards against initialising
/// twice should the reader ever be re-entered on the same thread.
class GmshSession {
public:
  GmshSession() : lock_(mutex()) {
    if (active()) throw Error("read_gmsh: Gmsh session already open (re-entered)");
    gmsh::initialize(0, nullptr, false); // no user gmshrc: reproducible, silent
    gmsh::option::setNumber("General.Terminal", 0);
    active() = true;
  }
  ~GmshSession() {
    gmsh::finalize();
    active() = false;
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static bool& active() {
    static bool a = false;
    return a;
  }
  std::lock_guard<std::mutex> lock_;
};

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

/// Gmsh opens a missing file as an empty model without an error, and reads MSH 2 as well:
/// check both from the file's first lines before handing it to Gmsh.
void check_msh4_header(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the Gmsh mesh file (missing or unreadable)");
  std::string tag;
  double version = 0.0;
  in >> tag >> version;
  if (tag != "$MeshFormat")
    throw InputError(path + ": not a Gmsh MSH file (it does not start with $MeshFormat)");
  if (!(version >= 4.0 && version < 5.0)) {
    std::ostringstream os;
    os << path << ": MSH format version " << version
       << " is not supported; re-export it with 'gmsh -format msh4'";
    throw InputError(os.str());
  }
}

/// Elements of one physical group, flattened over its entities.
struct Group {
  int dim = 0;
  int tag = 0;
  std::string name;
  std::vector<int> types;                      ///< Gmsh type per element
  std::vector<std::size_t> element_tags;       ///< per element
  std::vector<std::vector<std::size_t>> nodes; ///< Gmsh node tags per element
};

std::vector<Group> read_groups() {
  gmsh::vectorpair dim_tags;
  gmsh::model::getPhysicalGroups(dim_tags);
  std::vector<Group> groups;
  for (const auto& [dim, tag] : dim_tags) {
    Group g;
    g.dim = dim;
    g.tag = tag;
    gmsh::model::getPhysicalName(dim, tag, g.name);
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, entities);
    for (int entity : entities) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> element_tags, node_tags;
      gmsh::model::mesh::getElements(types, element_tags, node_tags, dim, entity);
      for (std::size_t t = 0; t < types.size(); ++t) {
        const std::size_t n = element_tags[t].size();
        const std::size_t per = n ? node_tags[t].size() / n : 0;
        for (std::size_t e = 0; e < n; ++e) {
          g.types.push_back(types[t]);
          g.element_tags.push_back(element_tags[t][e]);
          g.nodes.emplace_back(node_tags[t].begin() + e * per,
                               node_tags[t].begin() + (e + 1) * per);
        }
      }
    }
    groups.push_back(std::move(g));
  }
  return groups;
}

std::string gmsh_type_name(int gmsh_type) {
  std::string name;
  int dim = 0, order = 0, num_nodes = 0, num_primary = 0;
  std::vector<double> local;
  try {
    gmsh::model::mesh::getElementProperties(gmsh_type, name, dim, order, num_nodes, local,
                                            num_primary);
  } catch (...) {
    name = "unknown";
  }
  return name;
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

Mesh build_mesh(const std::string& path, const std::vector<Group>& groups) {
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
        throw InputError(path + ": physical group '" + name + "' contains elements of type '" +
                         gmsh_type_name(g.types[e]) + "' (Gmsh type " + std::to_string(g.types[e]) +
                         "), which bipot does not support (supported: tri3, tri6, quad4, "
                         "quad8, tet4, hex8 cells)");
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

  std::vector<std::size_t> node_tags;
  std::vector<double> coord, parametric;
  gmsh::model::mesh::getNodes(node_tags, coord, parametric, -1, -1, false, false);
  mesh.nodes.assign(used.size(), {0.0, 0.0, 0.0});
  std::vector<char> found(used.size(), 0);
  for (std::size_t i = 0; i < node_tags.size(); ++i) {
    auto it = new_id.find(node_tags[i]);
    if (it == new_id.end()) continue;
    mesh.nodes[it->second] = {coord[3 * i], coord[3 * i + 1], coord[3 * i + 2]};
    found[it->second] = 1;
  }
  if (std::find(found.begin(), found.end(), 0) != found.end())
    throw InputError(path + ": a cell references a node that the file does not define");
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

} // namespace

Mesh read_gmsh(const std::string& path) {
  check_msh4_header(path);
  GmshSession session;
  try {
    gmsh::open(path);
    return build_mesh(path, read_groups());
  } catch (const Error&) {
    throw;
  } catch (const std::string& message) { // Gmsh 4.8 throws its error text as std::string
    throw InputError(path + ": Gmsh: " + message);
  } catch (const std::exception& e) {
    throw InputError(path + ": Gmsh: " + e.what());
  }
}

} // namespace bipot
