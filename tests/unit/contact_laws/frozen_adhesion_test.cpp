// FrozenAdhesion (the solvers' staggered fallback) holds β and is the wrapped law otherwise:
// compared point by point with RCCM evaluated at the same β.
#include "contact/laws/frozen_adhesion.hpp"
#include "contact/laws/rccm.hpp"
#include "local_test_utils.hpp"

#include <gtest/gtest.h>

namespace bipot::contact {
namespace {

using test::vec;

TEST(FrozenAdhesion, HoldsBetaAndForwardsEverythingElse) {
  const Rccm rccm({1e6, 4e5, 0.05, 0.5});
  const FrozenAdhesion frozen(rccm);
  // A jump far beyond the threshold: RCCM itself would drop β from 0.7 to w/E ≈ 0.0125.
  const LocalVector jump = vec({1e-3, 2e-3});
  LocalVector dbeta;
  EXPECT_EQ(frozen.update_adhesion(0.7, jump, 0.0, &dbeta), 0.7);
  EXPECT_EQ(dbeta.norm(), 0.0);
  EXPECT_LT(rccm.update_adhesion(0.7, jump, 0.0), 0.02);
  // Everything else is RCCM's, exactly (same code path).
  LocalMatrix a, b;
  EXPECT_EQ(
      (frozen.adhesive_traction(0.7, jump, &a) - rccm.adhesive_traction(0.7, jump, &b)).norm(),
      0.0);
  EXPECT_EQ((a - b).norm(), 0.0);
  EXPECT_EQ(frozen.friction_coefficient(0.7), rccm.friction_coefficient(0.7));
  EXPECT_EQ(frozen.stiffness_scale(), rccm.stiffness_scale());
  // evaluate() with the frozen law at old β = 0.7 gives RCCM's traction for β = 0.7:
  // t = Proj(τ) − β² C g with μ̄ = μ (1 − 0.7).
  InterfaceState old = initial_state(rccm, 2);
  old.beta = 0.7;
  const auto resp = evaluate(frozen, old, jump, LocalVector::Zero(2), 0.0, 1e6);
  EXPECT_EQ(resp.beta, 0.7);
  EXPECT_NEAR(resp.traction(1), -0.49 * 4e5 * 2e-3, 1e-9); // open: r = 0, adhesive part only
  EXPECT_NEAR(resp.traction(0), -0.49 * 1e6 * 1e-3, 1e-9);
}

} // namespace
} // namespace bipot::contact
