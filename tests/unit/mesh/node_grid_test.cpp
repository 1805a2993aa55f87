// NodeGrid: every node within the tolerance of a point is visited, whatever the bucket
// boundaries, also far from the origin and with a zero tolerance.
#include "fem/mesh/node_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace bipot {
namespace {

std::set<Index> near(const NodeGrid& grid, const std::array<double, 3>& x) {
  std::set<Index> out;
  grid.for_each_near(x, [&](Index n) { out.insert(n); });
  return out;
}

TEST(NodeGrid, VisitsEveryNodeWithinTheTolerance) {
  for (double origin : {0.0, 1e6, -3e9}) {
    Mesh mesh;
    const double tol = 1e-3;
    // Around a bucket boundary of any size: just below, on, and just above the point.
    for (double dx : {-0.999e-3, 0.0, 0.999e-3, 5e-3})
      mesh.nodes.push_back({origin + 0.25 + dx, -1.0, 2.0});
    const NodeGrid grid(mesh, {0, 1, 2, 3}, tol);
    const auto found = near(grid, {origin + 0.25, -1.0, 2.0});
    for (Index n : {0, 1, 2})
      EXPECT_TRUE(found.count(n)) << "origin " << origin << ", node " << n;
  }
}

TEST(NodeGrid, ZeroToleranceFindsExactCopiesOnly) {
  Mesh mesh;
  mesh.nodes = {{1.0, 2.0, 0.0}, {1.0, 2.0, 0.0}, {1.5, 2.0, 0.0}};
  const NodeGrid grid(mesh, {0, 1, 2}, 0.0);
  const auto found = near(grid, mesh.nodes[0]);
  EXPECT_TRUE(found.count(0) && found.count(1));
  EXPECT_FALSE(found.count(2));
}

} // namespace
} // namespace bipot
