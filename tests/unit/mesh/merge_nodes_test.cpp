// merge_nodes: survivors, renumbering, sets and chains.
#include "fem/mesh/merge_nodes.hpp"

#include "fem/core/error.hpp"

#include <gtest/gtest.h>

namespace bipot {
namespace {

// Two triangles that touch along x = 1 through separate nodes (1~3, 2~4), plus node 5 unused
// by the glue: 0-1-2 | 3-5-4.
Mesh two_triangles() {
  Mesh m;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 0, 0}, {1, 1, 0}, {2, 0, 0}};
  m.add_cell(CellType::Tri3, {0, 1, 2}, 0);
  m.add_cell(CellType::Tri3, {3, 5, 4}, 1);
  m.node_sets["right_of_a"] = {1, 2};
  m.node_sets["b"] = {3, 4, 5};
  m.facet_sets["edge_b"] = {Facet{CellType::Line2, {3, 4}, 1}};
  return m;
}

TEST(MergeNodes, ReplacesAndRenumbersEverywhere) {
  Mesh m = two_triangles();
  const std::vector<Index> id = merge_nodes(m, {{1, 3}, {2, 4}});
  EXPECT_EQ(id, (std::vector<Index>{0, 1, 2, 1, 2, 3}));
  ASSERT_EQ(m.num_nodes(), 4);
  EXPECT_EQ(m.nodes[3][0], 2.0); // node 5 moved down to 3 with its coordinates
  EXPECT_EQ(std::vector<Index>(m.cell(1), m.cell(1) + 3), (std::vector<Index>{1, 3, 2}));
  EXPECT_EQ(m.node_sets.at("b"), (std::vector<Index>{1, 2, 3}));
  EXPECT_EQ(m.node_sets.at("right_of_a"), (std::vector<Index>{1, 2}));
  EXPECT_EQ(m.facet_sets.at("edge_b")[0].nodes, (std::vector<Index>{1, 2}));
  m.check_consistency();
}

TEST(MergeNodes, ChainsMergeIntoTheSmallestId) {
  Mesh m = two_triangles();
  // 4 ~ 2 and 3 ~ 4 (given in that order) make one group {2, 3, 4}, whose survivor is 2.
  const std::vector<Index> id = merge_nodes(m, {{4, 2}, {3, 4}});
  EXPECT_EQ(id, (std::vector<Index>{0, 1, 2, 2, 2, 3}));
  EXPECT_EQ(m.num_nodes(), 4);
}

TEST(MergeNodes, OutOfRangeIsAnError) {
  Mesh m = two_triangles();
  EXPECT_THROW(merge_nodes(m, {{0, 6}}), Error);
}

} // namespace
} // namespace bipot
