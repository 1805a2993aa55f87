#include "fem/mesh/interface_mesh.hpp"

#include <algorithm>

namespace bipot {

bool shares_nodes(const InterfaceMesh& iface) {
  return std::all_of(iface.pairs.begin(), iface.pairs.end(),
                     [](const InterfacePair& p) { return p.node_a == p.node_b; });
}

} // namespace bipot
