#include "fem/core/error.hpp"
#include "fem/linalg/communicator.hpp"
#include "fem/linalg/distributed_vector.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bipot {
namespace {

// Values below are small integers or their sums: exact in doubles, compared exactly unless
// a square root is involved.

TEST(DistributedVector, OffRankAdditionsReachTheirOwners) {
  const int p = mpi_size(), r = mpi_rank();
  const DofDistribution dist(7, 2); // 14 entries, split unevenly on 3+ ranks
  DistributedVector v(dist);
  for (Index i = 0; i < v.num_global(); ++i) {
    v.add(i, 1.0); // every rank hits every entry
    v.add(i, static_cast<double>(r));
  }
  v.add(-1, 1e30); // eliminated DOF: skipped
  v.finish_assembly();
  const double expected = p + p * (p - 1) / 2.0;
  for (Index i = 0; i < v.num_owned(); ++i)
    EXPECT_EQ(v.owned_values()[i], expected);
  EXPECT_THROW(v.add(v.num_global(), 1.0), Error);
}

TEST(DistributedVector, GatherAllIsTheSameGlobalVectorOnEveryRank) {
  const DofDistribution dist(11, 1);
  DistributedVector v(dist);
  for (Index i = v.first_owned(); i < v.first_owned() + v.num_owned(); ++i)
    v.set_owned(i, static_cast<double>(i * i));
  const auto all = v.gather_all();
  ASSERT_EQ(all.size(), 11u);
  for (Index i = 0; i < 11; ++i)
    EXPECT_EQ(all[i], static_cast<double>(i * i));
  // Independent cross-rank check: each rank's copy summed entry-wise over ranks.
  for (Index i = 0; i < 11; ++i)
    EXPECT_EQ(sum_all(all[i]), mpi_size() * all[i]);
}

TEST(DistributedVector, OwnedAccessRejectsOtherRanksEntries) {
  const DofDistribution dist(6, 1);
  DistributedVector v(dist);
  const Index not_mine = dist.rank() == 0 ? 5 : 0;
  if (dist.size() > 1) {
    EXPECT_THROW(v.set_owned(not_mine, 1.0), Error);
    EXPECT_THROW((void)v.get_owned(not_mine), Error);
  }
  EXPECT_THROW(v.set_owned(6, 1.0), Error); // beyond the end: owned by nobody
  v.set_owned(v.first_owned(), 3.0);
  EXPECT_EQ(v.get_owned(v.first_owned()), 3.0);
}

TEST(DistributedVector, NormDotAxpyScaleCopy) {
  const Index n = 40;
  const DofDistribution dist(n, 1);
  DistributedVector x(dist), ones(dist);
  for (Index i = x.first_owned(); i < x.first_owned() + x.num_owned(); ++i) {
    x.set_owned(i, static_cast<double>(i));
    ones.set_owned(i, 1.0);
  }
  // sum i^2 = (n-1) n (2n-1) / 6, sum i = n (n-1) / 2, exact integers.
  const double sum_sq = (n - 1) * n * (2 * n - 1) / 6.0;
  EXPECT_NEAR(x.norm2(), std::sqrt(sum_sq), 1e-12 * std::sqrt(sum_sq)); // sqrt rounding only
  EXPECT_EQ(x.dot(ones), n * (n - 1) / 2.0);
  DistributedVector y(dist);
  y.copy(x);
  y.axpy(2.0, ones); // y_i = i + 2
  y.scale(0.5);      // y_i = i/2 + 1
  EXPECT_EQ(y.dot(ones), n * (n - 1) / 4.0 + n);
  EXPECT_EQ(x.dot(ones), n * (n - 1) / 2.0); // copy() was deep
  DistributedVector other(DofDistribution(n + 1, 1));
  EXPECT_THROW(x.axpy(1.0, other), Error);
}

} // namespace
} // namespace bipot
