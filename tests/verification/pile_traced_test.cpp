// The shipped traced pull-out (inputs/pile_pullout/rccm_traced.yaml: RCCM at viscosity 0,
// `control: dissipation`) against the same input ramped (`control: ramp`), which can only jump
// over the snap-back with its staggered fallback. The traced run must
//   - follow the snap-back: steps on which head force and head displacement both fall,
//   - need no staggered fallback and at most a few Newton iterations per traced step,
//   - pass through the ramp's equilibria wherever both runs have one (same head displacement).
#include "apps/catalogue/builtin_catalogue.hpp"
#include "apps/pile_pullout/pile_input.hpp"
#include "apps/pile_pullout/pile_problem.hpp"
#include "apps/pile_pullout/pile_results.hpp"

#include "fem/analysis/model.hpp"
#include "fem/analysis/path_control.hpp"
#include "fem/analysis/static_analysis.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace bipot {
namespace {

struct Point {
  double force = 0; // kN
  bool traced = false, unstable = false;
  int iterations = 0, staggered = 0;
  int order = 0;           // the step's place in its run
  double energy_error = 0; // |balance_error| / work put in after the step
};

// What a run spent in failed attempts: its linear solves less those of the converged
// increments (one per generalized Newton iteration), and how many attempts failed (a failed
// ramp increment handing over to dissipation control, or a cut-back).
struct Attempts {
  int failed_solves = 0, failed = 0;
};

// Pull-out steps by head displacement (rounded to 1e-9 mm, well below the step sizes), solved
// to `tolerance` (0: the input's).
std::map<long long, Point> pull_out(pile::PileSpec spec, const std::string& control,
                                    double tolerance, Attempts* attempts = nullptr,
                                    RunSummary* run = nullptr) {
  spec.pullout.control = control;
  if (tolerance > 0) spec.contact_solver.parameters.set("tolerance", tolerance);
  const Model model = build_model(pile::make_problem(spec), bipot::builtin_catalogue());
  StaticAnalysis analysis(model);
  std::map<long long, Point> out;
  int converged_solves = 0, failed = 0;
  const RunSummary summary = analysis.run([&](const StepReport& r) {
    converged_solves += r.iterations;
    // Each cut-back is a failed attempt; time in failed attempts without one, a hand-over.
    failed += r.cutbacks > 0 ? r.cutbacks : r.failed_seconds > 0 ? 1 : 0;
    if (r.stage != "pullout") return;
    const pile::HeadState head = pile::head_state(model, analysis);
    out[std::llround(head.displacement * 1e12)] = {head.force,
                                                   r.traced,
                                                   r.unstable,
                                                   r.iterations,
                                                   r.staggered,
                                                   static_cast<int>(out.size()),
                                                   std::abs(r.energy.relative_error())};
  });
  if (attempts) *attempts = {summary.linear_solves - converged_solves, failed};
  if (run) *run = summary;
  return out;
}

TEST(PileTraced, FollowsTheSnapBackThroughTheRampsEquilibria) {
  const pile::PileSpec spec =
      pile::read_pile_file(std::string(BIPOT_SOURCE_DIR) + "/inputs/pile_pullout/rccm_traced.yaml",
                           bipot::builtin_catalogue());
  // Both runs to 1e-10 rather than the shipped 1e-8: at viscosity 0, β's history carries the
  // solver's tolerance from step to step (two solves of the same increments that differ
  // only within 1e-8 end 2.4e-6 apart in force at 6 mm), so 1e-6 agreement needs a tighter
  // solve.
  const auto traced = pull_out(spec, "dissipation", 1e-10);
  const auto ramped = pull_out(spec, "ramp", 1e-10);

  int falling = 0, traced_steps = 0, iterations = 0, most = 0;
  double peak = 0, peak_at = 0, lowest_after_peak = 1e9;
  int peak_order = 0;
  for (const auto& [key, p] : traced) {
    EXPECT_EQ(p.staggered, 0) << "no staggered fallback on the traced path";
    if (p.force > peak) peak = p.force, peak_at = key * 1e-12, peak_order = p.order;
    if (!p.traced) continue;
    ++traced_steps;
    iterations += p.iterations;
    most = std::max(most, p.iterations);
    if (p.unstable) ++falling;
  }
  // The branch after the peak: the lowest force at a head displacement below the peak's.
  for (const auto& [key, p] : traced)
    if (key * 1e-12 < peak_at && p.unstable)
      lowest_after_peak = std::min(lowest_after_peak, p.force);
  std::printf("traced: %d steps, %.2f Newton iterations per traced step (most %d), peak %.2f kN "
              "at %.3f mm, %d steps on the falling branch, lowest %.2f kN\n",
              traced_steps, double(iterations) / traced_steps, most, peak, 1e3 * peak_at, falling,
              lowest_after_peak);
  EXPECT_GE(falling, 3);                     // the falling branch is followed, step by step
  EXPECT_LT(lowest_after_peak, 0.85 * peak); // and far down (336 of 446 kN when written)
  EXPECT_LE(double(iterations) / traced_steps, 5.0);

  // The ramp jumps over the snap-back; both runs share the equilibria before it, and after it
  // wherever they meet the same head displacement. Before (in the traced run's order): the
  // same path, 1e-6. After: the paths differ (jump vs traced), and the frictional history
  // with them: 1e-5 (3.5e-6 measured at the first point after the snap-back, below 5e-7
  // elsewhere). A traced point after the peak may sit at a head displacement short of it
  // (back on the ramp after the snap-back): at 26.01 mm the traced run's 421.4 kN and the
  // ramp's 445.3 kN are both equilibria, on the lower and the upper branch; not compared.
  int common = 0, other_branch = 0;
  for (const auto& [key, r] : ramped) {
    const auto it = traced.find(key);
    if (it == traced.end()) continue;
    const bool before_peak = it->second.order < peak_order;
    if (!before_peak && key * 1e-12 < peak_at) {
      ++other_branch;
      continue;
    }
    ++common;
    const double tolerance = before_peak ? 1e-6 : 1e-5;
    EXPECT_NEAR(it->second.force, r.force, tolerance * std::abs(r.force))
        << "head displacement " << key * 1e-9 << " mm";
  }
  std::printf("ramp: %d points compared, %d on the other side of the snap-back\n", common,
              other_branch);
  EXPECT_GE(common, 20);
}

// The shipped input (80 increments) and shorter dissipation steps, at the shipped tolerance:
// each traced step converges in at most 5 Newton iterations (issue 11's target for the
// unstable branch), not only on average. With the constraint held to the solver tolerance and
// weighted like a force in the line search's merit, single steps took 17 (100 increments) and
// 20 (120) iterations; 5 with the constraint held to √tolerance and weighted by it
// (docs/path_following.md), but 6 at 80, where the step after the snap-back's turn
// kept the length of the turn's 4-iteration step; halved, it takes 5. A ramp increment that
// fails into dissipation control costs at most PathControl::slow_iterations solves (it took
// the contact solver's 50 before).
TEST(PileTraced, NoTracedStepNeedsManyIterationsWhateverTheStepLength) {
  pile::PileSpec spec =
      pile::read_pile_file(std::string(BIPOT_SOURCE_DIR) + "/inputs/pile_pullout/rccm_traced.yaml",
                           bipot::builtin_catalogue());
  for (int increments : {80, 100, 120}) {
    spec.pullout.increments = increments;
    int most = 0, falling = 0;
    Attempts attempts;
    for (const auto& [key, p] : pull_out(spec, "dissipation", 0.0, &attempts)) {
      EXPECT_EQ(p.staggered, 0) << "no staggered fallback on the traced path";
      if (!p.traced) continue;
      most = std::max(most, p.iterations);
      if (p.unstable) ++falling;
    }
    std::printf("%d increments: at most %d Newton iterations per traced step, %d steps on the "
                "falling branch, %d linear solves in %d failed attempts\n",
                increments, most, falling, attempts.failed_solves, attempts.failed);
    EXPECT_GE(falling, 3) << increments << " increments";
    EXPECT_LE(most, 5) << increments << " increments";
    EXPECT_GE(attempts.failed, 1) << increments << " increments";
    EXPECT_LE(attempts.failed_solves, PathControl::slow_iterations * attempts.failed)
        << increments << " increments";
  }
}

// The traced pull-out's energy balance, on a coarser mesh than the shipped input's to keep
// the test short: with RCCM's springs' work in closed form along each step (Rccm::spring_work)
// it holds at every pull-out step to round-off, without `energy_tolerance`. (The ledger's
// quadrature alone left 3.5e-5 of the work put in on the shipped mesh, and the option needed
// 2265 increments there to bring it within 1e-6.)
TEST(PileTraced, BalanceHoldsAtEveryStep) {
  pile::PileSpec spec =
      pile::read_pile_file(std::string(BIPOT_SOURCE_DIR) + "/inputs/pile_pullout/rccm_traced.yaml",
                           bipot::builtin_catalogue());
  spec.mesh.shaft_cells = 26;
  spec.mesh.soil_radial_cells = 15;
  spec.mesh.below_toe_cells = 10;
  RunSummary summary;
  const auto traced = pull_out(spec, "dissipation", 1e-10, nullptr, &summary);
  double worst = 0;
  int softening = 0;
  for (const auto& [key, p] : traced) {
    worst = std::max(worst, p.energy_error);
    softening += p.traced ? 1 : 0;
  }
  std::printf("energy balance error / work put in, worst of %zu pull-out steps (%d traced): "
              "%.3g\n",
              traced.size(), softening, worst);
  EXPECT_LT(worst, 1e-10);
  EXPECT_GE(softening, 3);
  EXPECT_EQ(summary.staggered_increments, 0);
  EXPECT_EQ(summary.energy_halvings, 0);
}

// The pile in Mohr-Coulomb soil (rccm_mohr_coulomb.yaml: viscosity 0, dissipation control as
// shipped), to 25 mm: its ramp fails repeatedly for the soil's sake (at 21.5 mm first)
// before any pair softens. The traced step it hands over to finds no pair softening
// (IncrementLog::nothing_softens), so the ramp takes the increment back and cuts back
// (PathControl::decline) with the solver's own iteration limit, as the ramp alone does;
// before, the traced step failed as singular at every halving and the run stopped at 21.5 mm. The
// run must pass through the same equilibria as the ramp alone (the same increments solved the same
// way: 1e-6), with the energy balance at round-off at every step (plastic dissipation in closed
// form, rate-independent adhesion).
TEST(PileTraced, PlasticSoilRampFailuresGoBackToTheRamp) {
  pile::PileSpec spec = pile::read_pile_file(std::string(BIPOT_SOURCE_DIR) +
                                                 "/inputs/pile_pullout/rccm_mohr_coulomb.yaml",
                                             bipot::builtin_catalogue());
  spec.law_parameters.set("adhesion_viscosity", 0.0);
  spec.pullout.head_displacement = 0.025; // the shipped 0.5 mm steps
  spec.pullout.increments = 50;
  RunSummary declined, ramp_only;
  const auto controlled = pull_out(spec, "dissipation", 0.0, nullptr, &declined);
  const auto ramped = pull_out(spec, "ramp", 0.0, nullptr, &ramp_only);
  std::printf("dissipation control: %d increments, %d cut-backs, %d traced; ramp: %d increments, "
              "%d cut-backs\n",
              declined.steps, declined.cutbacks, declined.traced_increments, ramp_only.steps,
              ramp_only.cutbacks);
  EXPECT_GE(declined.cutbacks, 1);
  EXPECT_EQ(declined.cutbacks, ramp_only.cutbacks); // no attempt lost to the hand-over
  EXPECT_EQ(declined.staggered_increments, 0);
  int common = 0;
  for (const auto& [key, p] : controlled) {
    EXPECT_LT(p.energy_error, 1e-10) << "head displacement " << key * 1e-9 << " mm";
    const auto it = ramped.find(key);
    if (it == ramped.end()) continue;
    ++common;
    EXPECT_NEAR(p.force, it->second.force, 1e-6 * std::abs(it->second.force))
        << "head displacement " << key * 1e-9 << " mm";
  }
  EXPECT_GE(common, 40);
  EXPECT_NEAR(controlled.rbegin()->first * 1e-12, 0.025, 1e-9); // it reached 25 mm
}

} // namespace
} // namespace bipot
