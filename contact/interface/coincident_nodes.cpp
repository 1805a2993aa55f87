#include "contact/interface/coincident_nodes.hpp"

#include "fem/mesh/node_grid.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>

namespace bipot::contact {

namespace {

double distance(const std::array<double, 3>& x, const std::array<double, 3>& y) {
  return std::sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                   (x[2] - y[2]) * (x[2] - y[2]));
}

} // namespace

double bounding_box_diagonal(const Mesh& mesh) {
  if (mesh.nodes.empty()) return 0.0;
  std::array<double, 3> lo = mesh.nodes[0], hi = mesh.nodes[0];
  for (const auto& x : mesh.nodes)
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], x[i]);
      hi[i] = std::max(hi[i], x[i]);
    }
  return distance(lo, hi);
}

std::vector<Index> match_coincident_nodes(const Mesh& mesh, const std::vector<Index>& nodes_a,
                                          const std::vector<Index>& nodes_b, double tol) {
  assert(tol > 0);
  const NodeGrid grid(mesh, nodes_b, tol);
  std::vector<char> used(mesh.nodes.size(), 0);
  std::vector<Index> partner(nodes_a.size(), -1);
  for (std::size_t i = 0; i < nodes_a.size(); ++i) {
    const auto& xa = mesh.nodes[nodes_a[i]];
    double best = std::numeric_limits<double>::infinity();
    Index best_b = -1;
    grid.for_each_near(xa, [&](Index b) {
      const double d = distance(xa, mesh.nodes[b]);
      if (d <= tol && d < best && !used[b]) {
        best = d;
        best_b = b;
      }
    });
    if (best_b >= 0) {
      used[best_b] = 1;
      partner[i] = best_b;
    }
  }
  return partner;
}

std::vector<NormalPartner>
match_nodes_along_normals(const Mesh& mesh, const std::vector<Index>& nodes_a,
                          const std::vector<std::array<double, 3>>& normals,
                          const std::vector<Index>& nodes_b, double tol) {
  assert(tol > 0 && normals.size() == nodes_a.size());
  std::vector<NormalPartner> out(nodes_a.size());
  for (std::size_t i = 0; i < nodes_a.size(); ++i) {
    const auto& xa = mesh.nodes[nodes_a[i]];
    const auto& n = normals[i];
    NormalPartner& best = out[i];
    for (Index b : nodes_b) {
      const auto& xb = mesh.nodes[b];
      const std::array<double, 3> d{xb[0] - xa[0], xb[1] - xa[1], xb[2] - xa[2]};
      const double s = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
      const std::array<double, 3> perp{d[0] - s * n[0], d[1] - s * n[1], d[2] - s * n[2]};
      const double off = distance(perp, {0, 0, 0});
      if (off <= tol) {
        if (best.node < 0 || std::abs(s) < std::abs(best.gap)) best = {b, off, s};
      } else if (best.node < 0 && off < best.off_line) {
        best.off_line = off;
      }
    }
  }
  return out;
}

} // namespace bipot::contact
