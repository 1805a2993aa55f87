#include "contact/interface/pair_geometry.hpp"

#include "contact/interface/interface_frame.hpp"
#include "fem/core/error.hpp"
#include "fem/element/facet_values.hpp"
#include "fem/mesh/cell_facets.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <unordered_map>

namespace bipot::contact {

namespace {

double norm(const std::array<double, 3>& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

} // namespace

void compute_pair_geometry(const Mesh& mesh, Kinematics kin, Interface& iface,
                           const std::string& context) {
  const int dim = spatial_dim(kin);
  const std::size_t n = iface.pairs.size();
  std::unordered_map<Index, std::size_t> index_of;
  index_of.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    index_of[iface.pairs[i].node_a] = i;

  std::vector<std::array<double, 3>> weighted(n, {0, 0, 0}), plain(n, {0, 0, 0});
  std::vector<double> weight(n, 0.0), magnitude(n, 0.0);
  std::vector<char> touched(n, 0);
  std::map<CellType, FacetValues> values;
  for (const Facet& f : iface.facets_a) {
    auto it = values.find(f.type);
    if (it == values.end())
      it = values.emplace(f.type, FacetValues(f.type, kin, 2 * cell_order(f.type) + 1)).first;
    FacetValues& fv = it->second;
    fv.reinit(mesh, f);
    const auto nf = facet_normal(mesh, f);
    for (int a = 0; a < fv.num_nodes(); ++a) {
      const auto found = index_of.find(f.nodes[a]);
      if (found == index_of.end())
        throw Error(context + "internal: facet node " + std::to_string(f.nodes[a]) +
                    " is not paired");
      const std::size_t i = found->second;
      touched[i] = 1;
      for (int d = 0; d < 3; ++d)
        plain[i][d] += nf[d];
      for (int q = 0; q < fv.num_points(); ++q) {
        const double c = fv.shape(q, a) * fv.JxW(q);
        weight[i] += c;
        magnitude[i] += std::abs(c);
        for (int d = 0; d < 3; ++d)
          weighted[i][d] += c * fv.normal(q)[d];
      }
    }
  }

  for (std::size_t i = 0; i < n; ++i) {
    InterfacePair& p = iface.pairs[i];
    if (!touched[i])
      throw InputError(context + mesh.describe_node(p.node_a) + " is on no interface facet");
    // Relative thresholds: the weighted sum is "zero" against the size of its terms, the plain
    // sum of unit vectors against 1.
    std::array<double, 3> m = weighted[i];
    if (!(norm(m) > 1e-10 * magnitude[i])) m = plain[i];
    const double len = norm(m);
    if (!(len > 1e-10))
      throw InputError(context + "the normal is undefined at " + mesh.describe_node(p.node_a) +
                       ": the normals of its facets cancel");
    for (double& v : m)
      v /= len;
    p.weight = weight[i];
    p.normal = m;
    complete_frame(p.normal, dim, p.tangent1, p.tangent2);
  }
}

Eigen::Matrix3d pair_frame(const InterfacePair& p, int dim) {
  Eigen::Matrix3d Q = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i) {
    Q(i, 0) = p.normal[i];
    Q(i, 1) = p.tangent1[i];
    Q(i, 2) = p.tangent2[i];
  }
  if (dim == 2) Q.col(2).setZero();
  return Q;
}

} // namespace bipot::contact
