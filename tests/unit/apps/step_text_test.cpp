// How the apps tell what the stepping did. The closing summary's account of the energy step
// control: the worst balance error it prints is energy.csv's (every error counted); when
// increments were kept over the budget, the controlled worst (their own errors left out) is
// given beside it, never instead of it.
#include "apps/common/step_text.hpp"

#include <gtest/gtest.h>

#include <string>

namespace bipot::app {
namespace {

RunSummary controlled_run(int kept_over) {
  RunSummary s;
  s.steps = 2311;
  s.sub_increments = 2228;
  s.energy_halvings = 14;
  s.over_energy_budget = kept_over;
  s.worst_energy_error = 1.56e-6;
  s.worst_controlled_energy_error = 6.8e-7;
  return s;
}

TEST(SteppingSummary, EnergyControlPrintsTheWorstErrorOfEnergyCsv) {
  const std::string kept = stepping_summary(controlled_run(363), "app");
  EXPECT_NE(kept.find("363 increments kept over it"), std::string::npos) << kept;
  EXPECT_NE(kept.find("worst balance error 1.6e-06 (6.8e-07 leaving out"), std::string::npos)
      << kept;
  EXPECT_NE(kept.find("a larger contact_solver.max_cutbacks"), std::string::npos) << kept;
  const std::string none = stepping_summary(controlled_run(0), "app");
  EXPECT_NE(none.find("worst balance error 1.6e-06 of the work put in"), std::string::npos) << none;
  EXPECT_EQ(none.find("6.8e-07"), std::string::npos) << none;
  EXPECT_EQ(none.find("max_cutbacks"), std::string::npos) << none;
  // A run without the control says nothing of it; nor does one it never halved (the control
  // is on by default; the energy balance line gives that run's worst error).
  EXPECT_EQ(stepping_summary(RunSummary{}, "app").find("energy_tolerance"), std::string::npos);
  RunSummary untouched;
  untouched.worst_energy_error = untouched.worst_controlled_energy_error = 3.4e-14;
  EXPECT_EQ(stepping_summary(untouched, "app").find("energy_tolerance"), std::string::npos);
}

// A stage whose path-following gave up (a traced step failed at every halving) and ramped on
// is counted at the end; a run without says nothing of it.
TEST(SteppingSummary, CountsStagesWherePathFollowingGaveUp) {
  RunSummary s;
  s.steps = 13;
  s.traced_increments = 2;
  EXPECT_EQ(stepping_summary(s, "app").find("gave up"), std::string::npos);
  s.abandoned_paths = 1;
  const std::string text = stepping_summary(s, "app");
  EXPECT_NE(text.find("path-following gave up in 1 stage (a traced step failed at every "
                      "halving) and ramped on"),
            std::string::npos)
      << text;
}

// Every run closes with its energy balance's worst error and where it was; above 1e-6 it says
// what makes such an error and what reduces it.
TEST(EnergyBalanceSummary, NamesTheWorstStepAndAdvisesAboveOneInAMillion) {
  RunSummary s;
  EXPECT_EQ(energy_balance_summary(s, "app"), "") << "no step, nothing to say";
  s.worst_balance_error = 9.54e-4;
  s.worst_balance_stage = "pullout";
  s.worst_balance_step = 80;
  const std::string large = energy_balance_summary(s, "app");
  EXPECT_EQ(large.rfind("app: energy balance: worst error 0.00095 of the work put in (stage "
                        "pullout, step 80; energy.csv); ",
                        0),
            0u)
      << large;
  EXPECT_NE(large.find("energy_tolerance"), std::string::npos) << large;
  s.worst_balance_error = 6.1e-15;
  EXPECT_EQ(energy_balance_summary(s, "app"),
            "app: energy balance: worst error 6.1e-15 of the work put in (stage pullout, step "
            "80; energy.csv)");
}

// A progress line says how short the step was and how much of that the energy budget asked
// for: a convergence cut-back alone, the energy alone, or both.
TEST(StepFlags, TellEnergyHalvingsFromCutBacks) {
  StepReport r;
  r.planned_step = 1;
  r.cutbacks = 2;
  EXPECT_EQ(step_flags(r), "  (1/4 step)");
  r.cutbacks = 0;
  r.energy_cutbacks = 2;
  r.energy_halvings = 1;
  EXPECT_EQ(step_flags(r), "  (1/4 step for the energy, energy: 1 halving)");
  r.cutbacks = 1;
  r.energy_halvings = 0;
  EXPECT_EQ(step_flags(r), "  (1/8 step, 2 of its 3 halvings for the energy)");
}

// The increment on which path-following gave up says so (the rest of its stage is ramped).
TEST(StepFlags, FlagTheIncrementWherePathFollowingGaveUp) {
  StepReport r;
  r.planned_step = 2;
  r.path_abandoned = true;
  r.failed_seconds = 0.5;
  EXPECT_EQ(step_flags(r), "  (path-following gave up: ramped, 0.50 s in failed attempts)");
}

} // namespace
} // namespace bipot::app
