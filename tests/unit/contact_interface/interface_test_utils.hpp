#pragma once
/// Meshes and independent checks shared by the interface tests (Gmsh-free).

#include "contact/interface/interface_mesh.hpp"
#include "fem/mesh/mesh.hpp"
#include "fem/mesh/structured_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace bipot::contact::test {

constexpr double pi = 3.141592653589793238462643383279502884;
constexpr double pile_radius = 0.135; ///< m, shaft at x = 0.135
constexpr double pile_length = 2.0;   ///< m, toe at y = -2

/// The 2D pile mesh of the brief: x breaks [0, 0.135, 2], y breaks [-3, -2, 0], region "pile"
/// = [0, 0.135] x [-2, 0], "soil" the three other blocks. Cells per segment: x [2, 4], y [2, 4]
/// (shaft cells 0.5 m, toe cells 0.0675 m).
inline Mesh pile_mesh(CellType cell) {
  BlockMeshSpec spec;
  spec.x = {{0.0, pile_radius, 2.0}, {2, 4}, {}};
  spec.y = {{-3.0, -pile_length, 0.0}, {2, 4}, {}};
  spec.cell = cell;
  spec.block_regions = {"soil", "soil", "pile", "soil"};
  return make_block_mesh(spec);
}

inline InterfaceDefinition between(const std::string& name, const std::string& a,
                                   const std::string& b, const std::string& where = "") {
  InterfaceDefinition d;
  d.name = name;
  d.region_a = a;
  d.region_b = b;
  d.where = where;
  return d;
}

/// True for a point on the pile's shaft (x = 0.135, -2 <= y <= 0) or toe (y = -2,
/// 0 <= x <= 0.135); the block mesh copies the breaks, so exact comparison is safe.
inline bool on_pile_interface(const std::array<double, 3>& x) {
  return (x[0] == pile_radius && x[1] >= -pile_length) ||
         (x[1] == -pile_length && x[0] <= pile_radius);
}

/// Node ids of a mesh whose coordinates satisfy `pred`.
template <class Pred> std::vector<Index> nodes_where(const Mesh& m, Pred pred) {
  std::vector<Index> out;
  for (Index i = 0; i < m.num_nodes(); ++i)
    if (pred(m.nodes[i])) out.push_back(i);
  return out;
}

/// Sum of the pair weights.
inline double total_weight(const Interface& iface) {
  double s = 0;
  for (const auto& p : iface.pairs)
    s += p.weight;
  return s;
}

/// The pair whose body-1 node is at `x` (exact match), or nullptr.
inline const InterfacePair* pair_at(const Mesh& m, const Interface& iface,
                                    const std::array<double, 3>& x) {
  for (const auto& p : iface.pairs)
    if (m.nodes[p.node_a] == x) return &p;
  return nullptr;
}

/// The message of the bipot exception `f()` throws, "" if none.
template <class F> std::string message_of(F f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

} // namespace bipot::contact::test
