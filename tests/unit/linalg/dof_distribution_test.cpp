#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"
#include "fem/linalg/dof_distribution.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace bipot {
namespace {

// Integer arithmetic only: every comparison below is exact.
TEST(DofDistribution, BlocksTileTheNodesEvenlyInRankOrder) {
  for (Index num_nodes : {0, 1, 5, 10, 11, 1000003})
    for (int size : {1, 2, 3, 4, 7}) {
      const DofDistribution d(num_nodes, 3, 0, size);
      EXPECT_EQ(d.first_node_of(0), 0);
      EXPECT_EQ(d.first_node_of(size), num_nodes);
      Index smallest = num_nodes, largest = 0;
      for (int r = 0; r < size; ++r) {
        const Index n = d.first_node_of(r + 1) - d.first_node_of(r);
        smallest = std::min(smallest, n);
        largest = std::max(largest, n);
        if (r > 0) {
          EXPECT_LE(n, d.first_node_of(r) - d.first_node_of(r - 1)); // larger first
        }
      }
      EXPECT_LE(largest - smallest, 1) << num_nodes << " nodes on " << size << " ranks";
    }
}

TEST(DofDistribution, OwnerAgreesWithTheBlocks) {
  const Index num_nodes = 23;
  for (int size : {1, 2, 3, 5, 30}) // 30 ranks > 23 nodes: some ranks own nothing
    for (int rank = 0; rank < size; ++rank) {
      const DofDistribution d(num_nodes, 2, rank, size);
      for (Index n = 0; n < num_nodes; ++n) {
        const bool mine =
            n >= d.first_owned_node() && n < d.first_owned_node() + d.num_owned_nodes();
        EXPECT_EQ(d.owner_of_node(n) == rank, mine) << "node " << n << ", rank " << rank;
        EXPECT_EQ(d.owner_of_dof(2 * n + 1), d.owner_of_node(n));
        EXPECT_EQ(d.owns_dof(2 * n), mine);
      }
      EXPECT_EQ(d.first_owned_dof(), 2 * d.first_owned_node());
      EXPECT_EQ(d.num_owned_dofs(), 2 * d.num_owned_nodes());
      EXPECT_EQ(d.num_global_dofs(), 46);
    }
}

TEST(DofDistribution, DefaultsToTheCallingRank) {
  const DofDistribution d(100, 2);
  EXPECT_EQ(d.rank(), mpi_rank());
  EXPECT_EQ(d.size(), mpi_size());
  // The owned blocks of all ranks add up to the whole.
  EXPECT_EQ(sum_all(d.num_owned_dofs()), 200);
}

TEST(DofDistribution, RejectsInvalidArguments) {
  EXPECT_THROW(DofDistribution(10, 0, 0, 1), Error);
  EXPECT_THROW(DofDistribution(10, 1, 2, 2), Error);
  EXPECT_THROW(DofDistribution(10, 1, 0, 1).owner_of_node(10), Error);
}

} // namespace
} // namespace bipot
