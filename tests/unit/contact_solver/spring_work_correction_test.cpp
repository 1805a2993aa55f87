// The three-point correction of a pair's springs' work (contact/solver/spring_work_correction.*)
// on the column's rate-independent RCCM pair (tests/support/bonded_column.hpp): β =
// min(1, w/(C g²)), adhesive traction a = −β² C g, so the springs' work from g1 to g2 on the
// softening branch is w²/(2C) (1/g1² − 1/g2²). On that branch the corrected trapezoid is the
// three-point rule; where β starts falling within the stencil it is the trapezoid. The law is
// RCCM without its closed form of that work (test::RccmByRule), which the account otherwise
// takes instead of the rule: exact along the whole path (last test).
#include "contact/laws/rccm.hpp"
#include "contact/solver/interface_assembler.hpp"
#include "contact/solver/spring_work_correction.hpp"
#include "fem/linalg/dof_distribution.hpp"

#include "fem/core/interface_point.hpp"
#include "tests/support/rccm_by_rule.hpp"

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

// Through InterfaceAssembler's energy account (interface_energy.cpp): one RCCM pair (no
// friction) opened along its normal in equal steps h from 0 to 2.5 g*, g* = √(w/C) = 0.01 m
// a node of every refinement (the onset on a state). The springs' work: w/2 up to g*, then
// w²/(2C) (1/g*² − 1/g²). The account's correction added to the trapezoid of −a·dg makes it
// third order over the path (halving h divides the error by ≥ 6, 8 nominally; the trapezoid's
// by 4), the rule held back for regime_steps_needed steps after the onset. A checkpoint of the
// account written before the rule (no stencil) loads, and the rule starts again.
struct OpeningRun {
  double error = 0;           ///< trapezoid + the account's corrections − closed form
  double trapezoid_error = 0; ///< the trapezoid alone
  int corrected = 0;          ///< steps the account corrected
};

// n steps; with `old_checkpoint_at` > 0 the account is saved after that step, cut to the
// layout before the rule and loaded back.
OpeningRun open_pair(int n, int old_checkpoint_at = 0, bool closed_form = false) {
  const Rccm::Parameters parameters{C, C, w, 0.0};
  const Rccm rccm(parameters);
  const test::RccmByRule by_rule(parameters);
  const InterfaceLaw& law = closed_form ? static_cast<const InterfaceLaw&>(rccm) : by_rule;
  Interface iface;
  iface.name = "bond";
  InterfacePair pair;
  pair.node_a = 0;
  pair.node_b = 1;
  pair.weight = 1.0;
  pair.normal = {0, 1, 0};
  pair.tangent1 = {-1, 0, 0};
  iface.pairs.push_back(pair);
  const DofMap dofs(2, 2);
  const DofDistribution dist(2, 2);
  InterfaceAssembler ia(iface, law, dofs, dist);
  ia.start_energy_account();
  const double g_end = 2.5 * g_star, h = g_end / n;
  OpeningRun run;
  double work = 0, correction = 0;
  Eigen::VectorXd a_old = Eigen::VectorXd::Zero(2), g_old = Eigen::VectorXd::Zero(2);
  for (int k = 1; k <= n; ++k) {
    ia.begin_increment();
    ia.evaluate({0, 0, 0, k * h}, 0.1);
    const PairResult& res = ia.results()[0];
    const Eigen::VectorXd a = res.traction - res.r, g = res.jump;
    work += -0.5 * (a_old + a).dot(g - g_old);
    InterfaceEnergy e;
    // The ledger's rule for equal steps (its chord lengths); the trapezoid on the first.
    e.rule = k == 1 ? ThreePointRule::trapezoid() : ThreePointRule::quadratic(h, h);
    ia.record_energy(e);
    EXPECT_FALSE(e.kinked && e.external_work_correction != 0.0);
    if (!e.kinked) correction += e.external_work_correction;
    correction += e.exact_work_correction;
    if (e.external_work_correction != 0.0) ++run.corrected;
    ia.commit();
    if (k == old_checkpoint_at) {
      std::vector<double> v = ia.save_energy_account();
      // Before the rule: 6 head values, then β, jump, traction and r per pair.
      std::vector<double> old(v.begin(), v.begin() + 6);
      old.insert(old.end(), v.begin() + 7, v.begin() + 7 + 1 + 3 * 2);
      ia.load_energy_account(old);
    }
    a_old = a;
    g_old = g;
  }
  const double exact = w / 2 + w * w / (2 * C) * (1 / (g_star * g_star) - 1 / (g_end * g_end));
  run.trapezoid_error = work - exact;
  run.error = work + correction - exact;
  return run;
}

TEST(SpringWorkCorrection, MakesTheAccountThirdOrderAlongADebondingOpening) {
  const OpeningRun coarse = open_pair(50), fine = open_pair(100);
  std::printf("opening to 2.5 g*: error %.3g (50 steps), %.3g (100); trapezoid %.3g, %.3g; "
              "%d and %d steps corrected\n",
              coarse.error, fine.error, coarse.trapezoid_error, fine.trapezoid_error,
              coarse.corrected, fine.corrected);
  EXPECT_GE(coarse.error / fine.error, 6.0);
  EXPECT_LT(coarse.trapezoid_error / fine.trapezoid_error, 6.0);
  // Softening over 30 and 60 steps; the rule waits regime_steps_needed − 1 of them.
  EXPECT_EQ(coarse.corrected, 30 - (regime_steps_needed - 1));
  EXPECT_EQ(fine.corrected, 60 - (regime_steps_needed - 1));
}

TEST(SpringWorkCorrection, AnAccountWithoutStencilLoadsAndTheRuleRestarts) {
  // Loaded at step 70 of 100, on the softening branch (onset at step 40).
  const OpeningRun whole = open_pair(100), restarted = open_pair(100, 70);
  // After the load the pair's regime is unknown: it must hold regime_steps_needed steps
  // again (the stencil's three states come within them), the first of them uncorrected.
  EXPECT_EQ(restarted.corrected, whole.corrected - (regime_steps_needed - 1));
  EXPECT_NEAR(restarted.trapezoid_error, whole.trapezoid_error, 1e-15);
  EXPECT_LT(std::abs(restarted.error), 0.5 * std::abs(restarted.trapezoid_error));
}

// RCCM's own closed form (Rccm::spring_work) integrates the springs' work exactly along the
// whole opening, the onset included and from the first step: the account is exact to
// round-off at any step length, and the rule is never needed.
TEST(SpringWorkCorrection, TheLawsClosedFormMakesTheAccountExact) {
  for (int n : {7, 50}) {
    const OpeningRun run = open_pair(n, 0, true);
    std::printf("opening to 2.5 g* in %d steps: error %.3g with the closed form, trapezoid %.3g\n",
                n, run.error, run.trapezoid_error);
    EXPECT_LT(std::abs(run.error), 1e-14 * w) << n << " steps";
    EXPECT_GT(std::abs(run.trapezoid_error), 1e-5 * w) << n << " steps";
    EXPECT_EQ(run.corrected, 0) << "the rule's corrections are not used";
  }
}

} // namespace
} // namespace bipot::contact
