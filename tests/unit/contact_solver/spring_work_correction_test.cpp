// The three-point correction of a pair's springs' work (contact/solver/spring_work_correction.*)
// on the column's rate-independent RCCM pair (tests/support/bonded_column.hpp): β =
// min(1, w/(C g²)), adhesive traction a = −β² C g, so the springs' work from g1 to g2 on the
// softening branch is w²/(2C) (1/g1² − 1/g2²). On that branch the corrected trapezoid is the
// three-point rule; where β starts falling within the stencil it is the trapezoid.
#include "contact/solver/spring_work_correction.hpp"

#include "fem/core/interface_point.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace bipot::contact {
namespace {

constexpr double C = 1.0e4, w = 1.0;
const double g_star = std::sqrt(w / C);

double beta_of(double g) {
  return std::min(1.0, w / (C * g * g));
}

// Normal opening g and a slip 0.5 g: Ẽ = C (g² + g²/4), β = min(1, w/Ẽ). `steps`: how long the
// pair's regime has held (spring_regime of the last step).
SpringHistory history(const double g[3], int steps) {
  SpringHistory h;
  const auto jump = [](double gn) {
    Eigen::VectorXd j(2);
    j << gn, 0.5 * gn;
    return j;
  };
  const auto beta = [&](double gn) { return beta_of(std::sqrt(1.25) * gn); };
  for (int i = 0; i < 3; ++i) {
    h.g[i] = jump(g[i]);
    h.a[i] = -beta(g[i]) * beta(g[i]) * C * h.g[i];
  }
  h.softening = beta(g[2]) < beta(g[1]);
  h.regime_steps = steps;
  return h;
}

// Springs' work along the path from g1 to g2 (normal and slip: Ẽ = 1.25 C g², a·dg =
// −β² 1.25 C g dg), in closed form on the softening branch: w²/(2.5 C) (1/g1² − 1/g2²).
double exact_work(double g1, double g2) {
  return w * w / (2.5 * C) * (1 / (g1 * g1) - 1 / (g2 * g2));
}

double trapezoid(const SpringHistory& h) {
  return -0.5 * (h.a[1] + h.a[2]).dot(h.g[2] - h.g[1]);
}

TEST(SpringWorkCorrection, ClassifiesThePairsSteps) {
  const int open = static_cast<int>(ContactStatus::Open);
  const int slip = static_cast<int>(ContactStatus::Slip);
  // β falling, not falling, reaching 0, and the contact branch: four different regimes.
  const int falling = spring_regime(0.9, 0.8, open), steady = spring_regime(0.8, 0.8, open);
  EXPECT_NE(falling, steady);
  EXPECT_NE(spring_regime(0.1, 0.0, open), falling);
  EXPECT_NE(spring_regime(0.9, 0.8, slip), falling);
  EXPECT_EQ(spring_regime(0.5, 0.4, open), falling);
  SpringHistory h;
  h.softening = true;
  h.regime_steps = regime_steps_needed;
  EXPECT_EQ(spring_path(h), SpringPath::Softening);
  h.regime_steps = regime_steps_needed - 1; // started softening within the window
  EXPECT_EQ(spring_path(h), SpringPath::Kinked);
  h.softening = false;
  EXPECT_EQ(spring_path(h), SpringPath::Kinked); // stopped (unloading)
  h.regime_steps = regime_steps_needed;
  EXPECT_EQ(spring_path(h), SpringPath::Steady);
}

// On the softening branch (g > g*/√1.25 everywhere): trapezoid + correction is the rule, whose
// error on equal steps falls by ≥ 12 when they are halved (fourth order; the trapezoid's by 8).
TEST(SpringWorkCorrection, MakesTheSofteningSpringsWorkFourthOrder) {
  const ThreePointRule rule = ThreePointRule::quadratic(1, 1);
  double error[2], trapezoid_error[2];
  for (int level = 0; level < 2; ++level) {
    const double h = 0.002 / (1 << level), g1 = 1.5 * g_star;
    const double g[3] = {g1 - h, g1, g1 + h};
    const SpringHistory hist = history(g, regime_steps_needed);
    ASSERT_EQ(spring_path(hist), SpringPath::Softening);
    const double exact = exact_work(g1, g1 + h);
    trapezoid_error[level] = trapezoid(hist) - exact;
    error[level] = trapezoid(hist) + spring_work_correction(rule, hist) - exact;
  }
  std::printf("springs' work error, step h and h/2: corrected %.3g, %.3g; trapezoid %.3g, %.3g\n",
              error[0], error[1], trapezoid_error[0], trapezoid_error[1]);
  EXPECT_GE(error[0] / error[1], 12.0);
  EXPECT_LT(trapezoid_error[0] / trapezoid_error[1], 12.0);
  EXPECT_LT(std::abs(error[1]), 0.5 * std::abs(trapezoid_error[1]));
}

// β starts falling within the stencil: the kink of a(g) at the onset. The correction is 0
// (the trapezoid stays); the rule across the kink would be no better than second order in
// the step (halving it divides its error by less than 8), its premise of a smooth path gone.
TEST(SpringWorkCorrection, FallsBackToTheTrapezoidAtTheOnsetOfDebonding) {
  const ThreePointRule rule = ThreePointRule::quadratic(1, 1);
  const double onset = g_star / std::sqrt(1.25);
  double across[2];
  for (int level = 0; level < 2; ++level) {
    const double h = 0.001 / (1 << level);
    // The onset a third of the way into the stencil's first step.
    const double g[3] = {onset - h / 3, onset + 2 * h / 3, onset + 5 * h / 3};
    // The pair's regime started at the onset, within the stencil's first step.
    const SpringHistory hist = history(g, 2);
    EXPECT_EQ(spring_path(hist), SpringPath::Kinked);
    EXPECT_EQ(spring_work_correction(rule, hist), 0.0);
    // What the rule would book there: its own correction, computed without the kink test.
    double correction = 0;
    for (int c = 0; c < 2; ++c) {
      const double f[3] = {-hist.a[0](c), -hist.a[1](c), -hist.a[2](c)};
      const double u[3] = {hist.g[0](c), hist.g[1](c), hist.g[2](c)};
      correction += rule.correction(f, u);
    }
    across[level] = trapezoid(hist) + correction - exact_work(g[1], g[2]);
  }
  std::printf("rule across the onset: error %.3g at h, %.3g at h/2\n", across[0], across[1]);
  EXPECT_LT(std::abs(across[0] / across[1]), 8.0);
}

} // namespace
} // namespace bipot::contact
