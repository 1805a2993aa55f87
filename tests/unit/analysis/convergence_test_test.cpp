// ConvergenceTest: the stopping rule both Newton increment solvers share (docs/theory.md,
// "Round-off floor"). Closed-form values; EXPECT_DOUBLE_EQ compares to 4 ulps.
#include "fem/analysis/detail/convergence_test.hpp"

#include <gtest/gtest.h>

namespace bipot {
namespace {

// tolerance 1e-8; first residual 3, load 5, interface force 2, last reaction 4 (kN).
ConvergenceTest example() {
  ConvergenceTest test(1e-8);
  test.set_reference(3.0, 5.0, 2.0, 4.0);
  return test;
}

TEST(ConvergenceTest, ReferenceIsTheLargestForceScale) {
  ConvergenceTest test(1e-8);
  EXPECT_FALSE(test.has_reference());
  test.set_reference(3.0, 5.0, 2.0, 4.0);
  EXPECT_TRUE(test.has_reference());
  EXPECT_DOUBLE_EQ(test.reference(), 5.0);
  EXPECT_DOUBLE_EQ(test.relative(2.5), 0.5);
  // Nothing acts: a zero reference is still set (the solvers return at once).
  ConvergenceTest idle(1e-8);
  idle.set_reference(0.0, 0.0, 0.0, 0.0);
  EXPECT_TRUE(idle.has_reference());
  EXPECT_EQ(idle.reference(), 0.0);
}

TEST(ConvergenceTest, ReferenceFollowsGrowingInterfaceForces) {
  ConvergenceTest test = example();
  test.raise_reference(10.0);
  EXPECT_DOUBLE_EQ(test.reference(), 10.0);
  test.raise_reference(7.0); // a smaller force scale later does not lower it
  EXPECT_DOUBLE_EQ(test.reference(), 10.0);
}

TEST(ConvergenceTest, ForcesMetBelowToleranceTimesReference) {
  ConvergenceTest test = example();
  test.set_roundoff(1e-10); // 10 × 1e-10 = 1e-9 < 1e-8 × 5: the tolerance decides
  EXPECT_DOUBLE_EQ(test.force_floor(), 5e-8);
  EXPECT_TRUE(test.forces_met(4.9e-8));
  EXPECT_FALSE(test.forces_met(5.1e-8));
}

TEST(ConvergenceTest, RoundoffFloorDecidesTheForcesNotTheLaw) {
  ConvergenceTest test = example();
  test.set_roundoff(1e-6); // 10 × 1e-6 = 1e-5 > 5e-8: the residual cannot go lower
  EXPECT_DOUBLE_EQ(test.force_floor(), 1e-5);
  EXPECT_TRUE(test.forces_met(9e-6));
  EXPECT_FALSE(test.forces_met(1.1e-5));
  // The interface law keeps tolerance × reference = 5e-8.
  EXPECT_TRUE(test.law_met(4.9e-8));
  EXPECT_FALSE(test.law_met(9e-6));
}

} // namespace
} // namespace bipot
