#include "contact/interface/interface_mesh.hpp"

#include "contact/interface/coincident_nodes.hpp"
#include "contact/interface/detail/mesh_splitter.hpp"
#include "contact/interface/interface_frame.hpp"
#include "contact/interface/pair_geometry.hpp"
#include "fem/core/error.hpp"
#include "fem/core/nearest_name.hpp"
#include "fem/mesh/cell_facets.hpp"
#include "fem/mesh/merge_nodes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <map>
#include <set>

namespace bipot::contact {

namespace {

std::string prefix(const InterfaceDefinition& d) {
  return (d.where.empty() ? std::string() : d.where + ": ") + "interface '" + d.name + "': ";
}

template <class Map> std::vector<std::string> keys_of(const Map& m) {
  std::vector<std::string> out;
  for (const auto& kv : m)
    out.push_back(kv.first);
  return out;
}

/// "no region named 'x' in the mesh (did you mean 'y'?); regions: a, b".
std::string unknown(const std::string& kind, const std::string& name,
                    const std::vector<std::string>& known) {
  std::string msg = "no " + kind + " named '" + name + "' in the mesh";
  const std::string near = nearest_name(name, known);
  if (!near.empty()) msg += " (did you mean '" + near + "'?)";
  return msg + "; " + kind + "s: " + (known.empty() ? std::string("none") : join_names(known));
}

/// Validation of one definition's names; fills the region-mode facets (original ids).
void check_definition(const Mesh& mesh, const InterfaceDefinition& d, std::vector<Facet>& facets,
                      std::vector<std::string>& problems) {
  const std::string p = prefix(d);
  if (d.obstacle) {
    if (!d.region_a.empty() || !d.region_b.empty() || d.facet_set_a.empty() ||
        !d.facet_set_b.empty()) {
      problems.push_back(p + "an obstacle is paired with one facet set of the body");
      return;
    }
    const auto known = keys_of(mesh.facet_sets);
    if (!mesh.facet_sets.count(d.facet_set_a))
      problems.push_back(p + unknown("facet set", d.facet_set_a, known));
    return;
  }
  const bool regions = !d.region_a.empty() || !d.region_b.empty();
  const bool sets = !d.facet_set_a.empty() || !d.facet_set_b.empty();
  if (regions && sets) {
    problems.push_back(p + "give either two regions (between) or two facet sets, not both");
    return;
  }
  if (!regions && !sets) {
    problems.push_back(p + "give two regions (between: [a, b]) or two facet sets");
    return;
  }
  const std::string kind = regions ? "region" : "facet set";
  const std::string a = regions ? d.region_a : d.facet_set_a;
  const std::string b = regions ? d.region_b : d.facet_set_b;
  if (a.empty() || b.empty()) {
    problems.push_back(p + "needs two " + kind + "s, got only '" + (a.empty() ? b : a) + "'");
    return;
  }
  const auto known = regions ? keys_of(mesh.regions) : keys_of(mesh.facet_sets);
  bool ok = true;
  for (const std::string& name : {a, b})
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      problems.push_back(p + unknown(kind, name, known));
      ok = false;
    }
  if (!ok) return;
  if (a == b) {
    problems.push_back(p + "the two " + kind + "s are both '" + a + "'");
    return;
  }
  if (!regions) return;
  facets = region_interface_facets(mesh, mesh.regions.at(a), mesh.regions.at(b));
  if (facets.empty()) problems.push_back(p + "regions '" + a + "' and '" + b + "' do not touch");
}

/// Reverses a facet's orientation (mid-nodes follow their edges).
void flip(Facet& f) {
  std::vector<Index>& n = f.nodes;
  switch (f.type) {
  case CellType::Line2:
  case CellType::Line3:
    std::swap(n[0], n[1]);
    break;
  case CellType::Tri3:
    std::swap(n[1], n[2]);
    break;
  case CellType::Tri6: // 0 2 1 | edges 02 21 10
    n = {n[0], n[2], n[1], n[5], n[4], n[3]};
    break;
  case CellType::Quad4:
    std::swap(n[1], n[3]);
    break;
  case CellType::Quad8: // 0 3 2 1 | edges 03 32 21 10
    n = {n[0], n[3], n[2], n[1], n[7], n[6], n[5], n[4]};
    break;
  default:
    break;
  }
}

/// Cells using each node.
std::vector<std::vector<Index>> cells_of_nodes(const Mesh& mesh) {
  std::vector<std::vector<Index>> out(mesh.nodes.size());
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_num_nodes(c); ++k)
      out[mesh.cell(c)[k]].push_back(c);
  return out;
}

/// Gives a facet without a cell the cell holding its corners and orients it outward of it.
/// Returns false if no cell holds it.
bool orient_orphan(const Mesh& mesh, const std::vector<std::vector<Index>>& cells_of_node,
                   Facet& f) {
  const int corners = num_corners(f.type);
  for (Index c : cells_of_node[f.nodes[0]]) {
    const Index* begin = mesh.cell(c);
    const Index* end = begin + mesh.cell_num_nodes(c);
    bool all = true;
    for (int i = 0; i < corners && all; ++i)
      all = std::find(begin, end, f.nodes[i]) != end;
    if (!all) continue;
    std::array<double, 3> d{0, 0, 0};
    const int cc = num_corners(mesh.cell_types[c]);
    for (int k = 0; k < cc; ++k)
      for (int i = 0; i < 3; ++i)
        d[i] -= mesh.nodes[begin[k]][i] / cc;
    for (int k = 0; k < corners; ++k)
      for (int i = 0; i < 3; ++i)
        d[i] += mesh.nodes[f.nodes[k]][i] / corners;
    const auto n = facet_normal(mesh, f);
    if (n[0] * d[0] + n[1] * d[1] + n[2] * d[2] < 0) flip(f);
    f.cell = c;
    return true;
  }
  return false;
}

/// Sets iface.facets_a from facet set a, giving facets without a cell the cell holding them
/// (oriented outward of it). Returns false, with a problem recorded, for a facet of no cell.
bool take_facets_a(const Mesh& mesh, const InterfaceDefinition& d, Interface& iface,
                   std::vector<std::string>& problems) {
  iface.facets_a = mesh.facet_sets.at(d.facet_set_a);
  std::vector<std::vector<Index>> cells_of_node; // built on the first facet without a cell
  for (Facet& f : iface.facets_a) {
    if (f.cell >= 0) continue;
    if (cells_of_node.empty()) cells_of_node = cells_of_nodes(mesh);
    if (!orient_orphan(mesh, cells_of_node, f)) {
      problems.push_back(prefix(d) + "a facet of set '" + d.facet_set_a + "' (corner " +
                         mesh.describe_node(f.nodes[0]) + ") is not a facet of any cell");
      return false;
    }
  }
  return true;
}

std::string format_length(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

/// "<count> of <total> <what>, first: <up to 5 nodes>".
std::string node_list(const Mesh& mesh, const std::vector<Index>& nodes, std::size_t total,
                      const std::string& what, const std::vector<std::string>& notes = {}) {
  std::string msg =
      std::to_string(nodes.size()) + " of " + std::to_string(total) + " " + what + ", first: ";
  for (std::size_t i = 0; i < std::min<std::size_t>(5, nodes.size()); ++i)
    msg += (i ? ", " : "") + mesh.describe_node(nodes[i]) + (i < notes.size() ? notes[i] : "");
  return msg;
}

/// Pairing::Normal: pairs each node of set a with the node of set b on its normal line (the
/// normals compute_pair_geometry() will give the pairs), with the distance as the pair's gap.
void pair_along_normals(const Mesh& mesh, Kinematics kin, const InterfaceDefinition& d,
                        const std::vector<Index>& nodes_a, const std::vector<Index>& nodes_b,
                        Interface& iface, std::vector<std::string>& problems) {
  const std::string p = prefix(d);
  if (!take_facets_a(mesh, d, iface, problems)) return;
  for (Index a : nodes_a) {
    InterfacePair pair;
    pair.node_a = a;
    iface.pairs.push_back(pair);
  }
  compute_pair_geometry(mesh, kin, iface, p);
  std::vector<std::array<double, 3>> normals;
  for (const InterfacePair& pair : iface.pairs)
    normals.push_back(pair.normal);
  // Matching meshes put the partner on the line up to round-off; 1e-6 only forgives meshes
  // written with a few significant digits.
  const double diagonal = bounding_box_diagonal(mesh);
  const double tol = 1e-6 * (diagonal > 0 ? diagonal : 1.0);
  const auto partners = match_nodes_along_normals(mesh, nodes_a, normals, nodes_b, tol);

  std::vector<Index> lonely_a, lonely_b, shared_b;
  std::vector<std::string> misses;
  std::map<Index, int> uses;
  for (std::size_t i = 0; i < nodes_a.size(); ++i) {
    if (partners[i].node >= 0) {
      ++uses[partners[i].node];
      continue;
    }
    lonely_a.push_back(nodes_a[i]);
    misses.push_back(" (nearest node of '" + d.facet_set_b + "' " +
                     format_length(partners[i].off_line) + " m off the line)");
  }
  for (Index b : nodes_b) {
    const auto it = uses.find(b);
    if (it == uses.end())
      lonely_b.push_back(b);
    else if (it->second > 1)
      shared_b.push_back(b);
  }
  if (!lonely_a.empty() || !lonely_b.empty() || !shared_b.empty()) {
    const std::string& sa = d.facet_set_a;
    const std::string& sb = d.facet_set_b;
    std::string msg = p + "facet sets '" + sa + "' and '" + sb +
                      "' do not face each other node by node along the normals of '" + sa +
                      "' (within " + format_length(tol) + " m of the line)";
    if (!lonely_a.empty())
      msg += "; " + node_list(mesh, lonely_a, nodes_a.size(),
                              "nodes of '" + sa + "' have no node of '" + sb + "' on their normal",
                              misses);
    if (!lonely_b.empty())
      msg += "; " + node_list(mesh, lonely_b, nodes_b.size(),
                              "nodes of '" + sb + "' are no node's partner");
    if (!shared_b.empty())
      msg += "; " + node_list(mesh, shared_b, nodes_b.size(),
                              "nodes of '" + sb + "' are the partner of several nodes");
    problems.push_back(msg + "; the meshes must be designed so that the nodes face each other");
    return;
  }
  for (std::size_t i = 0; i < nodes_a.size(); ++i) {
    iface.pairs[i].node_b = partners[i].node;
    iface.pairs[i].gap = partners[i].gap;
  }
}

/// The facet-set mode: pairs the nodes of two facet sets, coincident or along the normals.
Interface pair_facet_sets(const Mesh& mesh, Kinematics kin, const InterfaceDefinition& d,
                          std::vector<std::string>& problems) {
  const std::string p = prefix(d);
  const std::string& sa = d.facet_set_a;
  const std::string& sb = d.facet_set_b;
  Interface iface;
  iface.name = d.name;
  iface.initial_gap = d.initial_gap;
  const std::vector<Index> nodes_a = mesh.facet_set_nodes(sa), nodes_b = mesh.facet_set_nodes(sb);
  std::vector<Index> common;
  std::set_intersection(nodes_a.begin(), nodes_a.end(), nodes_b.begin(), nodes_b.end(),
                        std::back_inserter(common));
  if (!common.empty()) {
    problems.push_back(p + "facet sets '" + sa + "' and '" + sb + "' share " +
                       std::to_string(common.size()) + " node(s), e.g. " +
                       mesh.describe_node(common[0]) +
                       "; their nodes must be distinct (use between: [a, b] for regions of a "
                       "conforming mesh)");
    return iface;
  }
  if (d.pairing == Pairing::Normal) {
    pair_along_normals(mesh, kin, d, nodes_a, nodes_b, iface, problems);
    return iface;
  }
  const double diagonal = bounding_box_diagonal(mesh);
  const double tol = 1e-9 * (diagonal > 0 ? diagonal : 1.0);
  const std::vector<Index> partner = match_coincident_nodes(mesh, nodes_a, nodes_b, tol);
  std::vector<Index> lonely_a, lonely_b;
  std::set<Index> used;
  for (std::size_t i = 0; i < nodes_a.size(); ++i) {
    if (partner[i] < 0)
      lonely_a.push_back(nodes_a[i]);
    else
      used.insert(partner[i]);
  }
  for (Index b : nodes_b)
    if (!used.count(b)) lonely_b.push_back(b);
  if (!lonely_a.empty() || !lonely_b.empty()) {
    std::string msg = p + "facet sets '" + sa + "' and '" + sb + "' do not match within " +
                      format_length(tol) + " m: " + std::to_string(lonely_a.size()) + " of " +
                      std::to_string(nodes_a.size()) + " nodes of '" + sa + "' and " +
                      std::to_string(lonely_b.size()) + " of " + std::to_string(nodes_b.size()) +
                      " nodes of '" + sb + "' have no coincident partner";
    const bool on_a = !lonely_a.empty();
    const std::vector<Index>& lonely = on_a ? lonely_a : lonely_b;
    msg += "; first of '" + (on_a ? sa : sb) + "': ";
    for (std::size_t i = 0; i < std::min<std::size_t>(5, lonely.size()); ++i)
      msg += (i ? ", " : "") + mesh.describe_node(lonely[i]);
    problems.push_back(msg);
    return iface;
  }
  for (std::size_t i = 0; i < nodes_a.size(); ++i) {
    InterfacePair pair;
    pair.node_a = nodes_a[i];
    pair.node_b = partner[i];
    iface.pairs.push_back(pair);
  }
  take_facets_a(mesh, d, iface, problems);
  return iface;
}

/// Obstacle mode: every node of facet set a paired with the rigid obstacle (node_b =
/// rigid_obstacle), its signed distance as the pair's gap.
Interface pair_with_obstacle(const Mesh& mesh, Kinematics kin, const InterfaceDefinition& d,
                             bool tie_only, std::vector<std::string>& problems) {
  Interface iface;
  iface.name = d.name;
  iface.initial_gap = d.initial_gap;
  iface.obstacle = true;
  if (!take_facets_a(mesh, d, iface, problems)) return iface;
  const double diagonal = bounding_box_diagonal(mesh);
  const double tol = 1e-9 * (diagonal > 0 ? diagonal : 1.0);
  std::vector<Index> centred, off;
  const int dim = spatial_dim(kin);
  for (Index a : mesh.facet_set_nodes(d.facet_set_a)) {
    const ObstacleDistance where = distance_to(*d.obstacle, mesh.nodes[a], dim);
    if (!where.defined) centred.push_back(a);
    if (tie_only && std::abs(where.distance) > tol) off.push_back(a);
    InterfacePair pair;
    pair.node_a = a;
    pair.node_b = rigid_obstacle;
    pair.gap = where.distance;
    iface.pairs.push_back(pair);
  }
  const std::string shape = to_string(d.obstacle->shape);
  if (!centred.empty())
    problems.push_back(prefix(d) +
                       node_list(mesh, centred, iface.pairs.size(),
                                 "nodes of '" + d.facet_set_a + "' are on the " + shape +
                                     "'s centre or axis, where no normal "
                                     "is defined"));
  if (!off.empty())
    problems.push_back(prefix(d) + "perfect bonding holds the nodes of '" + d.facet_set_a +
                       "' where they are on the obstacle's surface; " +
                       node_list(mesh, off, iface.pairs.size(),
                                 "nodes are off it (by more than " + format_length(tol) + " m)"));
  return iface;
}

/// The frame of obstacle pairs: the obstacle's normal at the closest point, reversed so that
/// it points from body 1 into the obstacle (docs/formulation.md §1), not the facets' normal
/// (node-to-surface: a cylinder pressed on a plane is pushed along the plane's normal).
void set_obstacle_frames(const Mesh& mesh, Kinematics kin, const RigidObstacle& obstacle,
                         Interface& iface) {
  const int dim = spatial_dim(kin);
  for (InterfacePair& p : iface.pairs) {
    const ObstacleDistance where = distance_to(obstacle, mesh.nodes[p.node_a], dim);
    for (int i = 0; i < 3; ++i)
      p.normal[i] = -where.normal[i];
    complete_frame(p.normal, dim, p.tangent1, p.tangent2);
  }
}

// Perfect bonding between separately meshed bodies: the pairs of facet-set interfaces become
// shared nodes, exactly as a region interface that is not split, so the bodies are one mesh
// and no constraint is needed. A pair's nodes must then be at one place (a normal pairing
// across a gap cannot be glued without moving a node).
void glue_facet_set_pairs(Mesh& mesh, const std::vector<InterfaceDefinition>& defs,
                          std::vector<Interface>& out) {
  std::array<double, 3> lo = mesh.nodes.front(), hi = lo;
  for (const auto& x : mesh.nodes)
    for (int c = 0; c < 3; ++c)
      lo[c] = std::min(lo[c], x[c]), hi[c] = std::max(hi[c], x[c]);
  const double tolerance =
      1e-9 * std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                       (hi[2] - lo[2]) * (hi[2] - lo[2]));
  std::vector<std::pair<Index, Index>> glue;
  std::vector<std::string> problems;
  for (std::size_t i = 0; i < defs.size(); ++i) {
    if (!defs[i].region_a.empty() || defs[i].obstacle) continue; // obstacles: held by the caller
    for (const InterfacePair& p : out[i].pairs) {
      if (std::abs(p.gap) > tolerance) {
        problems.push_back(prefix(defs[i]) + "perfect bonding joins coincident nodes, but " +
                           mesh.describe_node(p.node_a) + " and " + mesh.describe_node(p.node_b) +
                           " are " + format_length(std::abs(p.gap)) +
                           " apart along the normal; mesh the bodies to meet, or use pairing: "
                           "coincident");
        break;
      }
      glue.emplace_back(p.node_a, p.node_b);
    }
  }
  if (!problems.empty()) throw InputError(problems);
  if (glue.empty()) return;
  const std::vector<Index> new_id = merge_nodes(mesh, glue);
  for (Interface& iface : out) {
    for (InterfacePair& p : iface.pairs)
      p.node_a = new_id[p.node_a], p.node_b = p.node_b < 0 ? p.node_b : new_id[p.node_b];
    for (Facet& f : iface.facets_a)
      for (Index& v : f.nodes)
        v = new_id[v];
  }
}

} // namespace

std::vector<Interface> split_interfaces(Mesh& mesh, Kinematics kin,
                                        const std::vector<InterfaceDefinition>& defs,
                                        bool tie_only) {
  if (spatial_dim(kin) != mesh.dim)
    throw Error("split_interfaces: " + to_string(kin) + " kinematics on a " +
                std::to_string(mesh.dim) + "D mesh");
  std::vector<std::string> problems;
  std::vector<std::vector<Facet>> facets(defs.size());
  std::set<std::string> names;
  for (std::size_t i = 0; i < defs.size(); ++i) {
    if (!names.insert(defs[i].name).second)
      problems.push_back(prefix(defs[i]) + "another interface has the same name");
    check_definition(mesh, defs[i], facets[i], problems);
  }
  if (!problems.empty()) throw InputError(problems);

  // Work on a copy so that `mesh` is unchanged if a later problem throws.
  Mesh work = mesh;
  std::vector<Interface> out(defs.size());
  detail::MeshSplitter splitter(work);
  for (std::size_t i = 0; i < defs.size(); ++i) {
    const InterfaceDefinition& d = defs[i];
    if (d.region_a.empty()) continue;
    out[i].name = d.name;
    out[i].initial_gap = d.initial_gap;
    splitter.split(facets[i], work.regions.at(d.region_a), work.regions.at(d.region_b), tie_only,
                   out[i]);
  }
  // Facet-set interfaces last, on the final node ids.
  for (std::size_t i = 0; i < defs.size(); ++i)
    if (defs[i].obstacle)
      out[i] = pair_with_obstacle(work, kin, defs[i], tie_only, problems);
    else if (defs[i].region_a.empty())
      out[i] = pair_facet_sets(work, kin, defs[i], problems);
  if (!problems.empty()) throw InputError(problems);
  if (tie_only) glue_facet_set_pairs(work, defs, out);

  for (std::size_t i = 0; i < defs.size(); ++i) {
    Interface& iface = out[i];
    std::sort(iface.pairs.begin(), iface.pairs.end(),
              [](const InterfacePair& x, const InterfacePair& y) { return x.node_a < y.node_a; });
    compute_pair_geometry(work, kin, iface, prefix(defs[i]));
    if (defs[i].obstacle) set_obstacle_frames(work, kin, *defs[i].obstacle, iface);
  }
  // The split appended nodes one by one, leaving up to twice the capacity (11 MB at 1M DOFs,
  // held all run).
  work.nodes.shrink_to_fit();
  mesh = std::move(work);
  return out;
}

} // namespace bipot::contact
