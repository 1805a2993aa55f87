#include "fem/linalg/communicator.hpp"

#include <gtest/gtest.h>

namespace bipot {
namespace {

// Small integers in doubles: sums and maxima are exact, so comparisons are exact.
TEST(Communicator, ReductionsOfSmallIntegers) {
  const int p = mpi_size(), r = mpi_rank();
  ASSERT_GE(r, 0);
  ASSERT_LT(r, p);
  EXPECT_EQ(sum_all(1.0), p);
  EXPECT_EQ(sum_all(static_cast<double>(r + 1)), p * (p + 1) / 2.0);
  EXPECT_EQ(max_all(static_cast<double>(r)), p - 1.0);
  EXPECT_EQ(min_all(static_cast<double>(r)), 0.0);
}

TEST(Communicator, IndexSumIsExactBeyondDoublePrecision) {
  // 2^55 + r is not representable in a double for odd r: a sum through double would fail.
  const Index big = Index(1) << 55;
  const Index p = mpi_size(), r = mpi_rank();
  EXPECT_EQ(sum_all(big + r), p * big + p * (p - 1) / 2);
}

TEST(Communicator, GatherAllConcatenatesInRankOrder) {
  const int p = mpi_size(), r = mpi_rank();
  std::vector<double> mine;
  for (int i = 0; i <= r; ++i)
    mine.push_back(100.0 * r + i); // rank r sends r + 1 values
  std::vector<double> expected;
  for (int q = 0; q < p; ++q)
    for (int i = 0; i <= q; ++i)
      expected.push_back(100.0 * q + i);
  EXPECT_EQ(gather_all(mine), expected);
  EXPECT_EQ(gather_all(std::vector<double>{}), std::vector<double>{});
}

TEST(Communicator, BroadcastCopiesTheRootString) {
  const int p = mpi_size(), r = mpi_rank();
  std::string text = r == p - 1 ? "from the last rank" : std::string(r + 3, 'x');
  broadcast(text, p - 1);
  EXPECT_EQ(text, "from the last rank");
  barrier();
}

} // namespace
} // namespace bipot
