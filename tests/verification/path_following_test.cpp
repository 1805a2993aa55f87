// Path-following through a debonding snap-back (stage `control:` dissipation and arc_length),
// on the column of tests/support/bonded_column.hpp. Every equilibrium lies on the curve
// δ(g) = g + t(g)/k, parametrised by the opening g, which only grows. Past the limit point
// (g*, δ*) δ(g) falls steeply down to δ_min at g = (3w²/(Ck))^¼, then rises again: the
// snap-back a displacement ramp jumps over. Traced, every step must lie on that curve and the
// unstable branch (λ falling) must be followed with no staggered fallback.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/core/error.hpp"
#include "fem/input/problem_reader.hpp"
#include "tests/support/bonded_column.hpp"
#include "tests/support/model_from_text.hpp"
#include "tests/support/rccm_by_rule.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace bipot {
namespace {

using namespace test::column;

const double g_min = std::pow(3.0 * w * w / (C * k), 0.25); // the lowest point of δ(g)

double delta_of(double g) {
  return g + t_of(g) / k;
}

// The column with a stage control; generalized_newton unless another solver is named.
std::string input(const std::string& control, const std::string& solver = "generalized_newton") {
  return test::column::input(solver, control);
}

// The column's bulk as a von Mises material that never yields: the same closed form, but the
// increments take the nonlinear bulk's path (the outer loop re-condenses the bulk at each
// state, and the path's Δλ and constraint are carried across those outer iterations).
std::string with_nonlinear_bulk(std::string text) {
  const std::string elastic = "column: {type: linear_elastic,";
  text.replace(text.find(elastic), elastic.size(),
               "column: {type: von_mises, yield_stress: 1.0e9,");
  return text;
}

// The column cut at mid-height into two bodies tied by a `perfect_bonding` joint: the third
// law in a traced model. The tie adds no compliance, so the closed form is unchanged;
// interfaces()[0] stays the RCCM bond, now between the base and the lower half.
std::string with_bonded_joint(std::string text) {
  const auto swap = [&](const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
  };
  swap("y: {breaks: [-0.1, 0, 1.0], cells: [1, 2]}\n    regions: [base, column]",
       "y: {breaks: [-0.1, 0, 0.5, 1.0], cells: [1, 1, 1]}\n    regions: [base, lower, column]");
  swap("  column: {", "  lower: {type: linear_elastic, youngs_modulus: 1.0e3, poissons_ratio: "
                      "0.0}\n  column: {");
  swap("between: [base, column]", "between: [base, lower]");
  swap("contact_solver:",
       "  - name: tie\n    between: [lower, column]\n    law: perfect_bonding\ncontact_solver:");
  return text;
}

// (control, nonlinear bulk, bonded joint)
class TracedSnapBack : public ::testing::TestWithParam<std::tuple<const char*, bool, bool>> {};

TEST_P(TracedSnapBack, EveryStepLiesOnTheClosedFormCurve) {
  const auto [control, nonlinear, bonded] = GetParam();
  std::string text = input(control);
  if (bonded) text = with_bonded_joint(text);
  if (nonlinear) text = with_nonlinear_bulk(text);
  const Model model = bipot::test::model_from_text(text, "traced.yaml");
  StaticAnalysis analysis(model);
  double previous_g = 0, largest_stress = 0, smallest_delta_after_peak = top;
  int traced = 0, falling = 0;
  const RunSummary summary = analysis.run([&](const StepReport& r) {
    const auto& ia = *analysis.interfaces()[0];
    const double delta = top * r.load_factor;
    const double g = ia.results()[0].jump(0);
    const double stress = -ia.resultant()[1] / width; // the base pulls the column down
    // On the curve: δ(g) and t(g) to 1e-8 of their scales (the solver converges to 1e-10;
    // the issue asks for 1e-3).
    EXPECT_NEAR(delta, delta_of(g), 1e-8 * top) << "step " << r.global_step;
    EXPECT_NEAR(stress, t_of(g), 1e-8 * peak) << "step " << r.global_step;
    EXPECT_GT(g, previous_g - 1e-12) << "the opening parametrises the path: it never closes";
    EXPECT_EQ(r.staggered, 0) << "no staggered fallback on a traced path";
    if (r.traced) {
      ++traced;
      // The target: at most 5 linear solves (Newton iterations) per traced increment.
      EXPECT_LE(r.iterations, 5) << "step " << r.global_step;
    }
    if (r.traced && r.unstable) ++falling;
    if (g > g_star) smallest_delta_after_peak = std::min(smallest_delta_after_peak, delta);
    largest_stress = std::max(largest_stress, stress);
    previous_g = g;
  });
  if (std::string(control) == "dissipation") {
    // The ramp runs up to the limit point (a planned level here: δ* = 0.11 = 11/12 × 0.12)
    // before dissipation control takes over: the peak within 1e-3.
    EXPECT_NEAR(largest_stress, peak, 1e-3 * peak);
  } else {
    // Arc-length steps do not land on the limit point; they pass it: stresses on both sides.
    EXPECT_GT(largest_stress, 0.5 * peak);
  }
  // The unstable branch was followed down towards its lowest point δ(g_min) = 0.0313 m.
  EXPECT_GE(falling, 3);
  EXPECT_LT(smallest_delta_after_peak, 0.3 * top);
  EXPECT_GT(smallest_delta_after_peak, delta_of(g_min) - 1e-8);
  EXPECT_EQ(summary.traced_increments, traced);
  EXPECT_EQ(summary.staggered_increments, 0);
  EXPECT_NEAR(previous_g + t_of(previous_g) / k, top, 1e-8 * top); // ends at λ = 1
  // The nonlinear bulk's path was taken: a condensation (factorisation) per outer
  // iteration, about two per increment (the step, then the bulk's residual at the new state
  // and its correction), where the linear bulk factorises once per constrained set.
  if (nonlinear) {
    EXPECT_GT(summary.matrix_setups, summary.steps);
  } else {
    EXPECT_LT(summary.matrix_setups, summary.steps);
  }
}

INSTANTIATE_TEST_SUITE_P(BothControlsBothBulkPaths, TracedSnapBack,
                         ::testing::Combine(::testing::Values("dissipation", "arc_length"),
                                            ::testing::Bool(), ::testing::Bool()));

// The column in frictional contact (coulomb_signorini) with its base, pressed: the law that
// does not soften, traced. The base is elastic and held at its bottom only, so that the
// interface moves and arc length has a path to measure. In 1D (ν = 0) the stress is
// E δ / (L + h), h = 0.1 the base's height, at every step.
std::string pressed_on_coulomb(const std::string& control, bool nonlinear) {
  std::string text = input(control);
  const auto swap = [&](const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
  };
  const std::size_t at = text.find("law: rccm");
  text.replace(at, text.find('}', at) + 1 - at,
               "law: coulomb_signorini\n    parameters: {friction_coefficient: 0.3}");
  swap("{set: base_nodes, component: x", "{set: bottom, component: x");
  swap("{set: base_nodes, component: y", "{set: bottom, component: y");
  swap("value: 0.12", "value: -0.12");
  return nonlinear ? with_nonlinear_bulk(text) : text;
}

// Bulk linear or not (the two paths of the contact solver).
class TracedContact : public ::testing::TestWithParam<bool> {};

TEST_P(TracedContact, EveryArcLengthStepLiesOnTheElasticLine) {
  const bool nonlinear = GetParam();
  const Model model =
      bipot::test::model_from_text(pressed_on_coulomb("arc_length", nonlinear), "traced.yaml");
  StaticAnalysis analysis(model);
  double last_lambda = 0, worst = 0;
  int traced = 0;
  const RunSummary summary = analysis.run([&](const StepReport& r) {
    const double delta = -top * r.load_factor;
    const double stress = -analysis.interfaces()[0]->resultant()[1] / width;
    EXPECT_NEAR(stress, E * delta / (L + 0.1), 1e-8 * E * top) << "step " << r.global_step;
    EXPECT_EQ(r.staggered, 0);
    EXPECT_FALSE(r.unstable) << "nothing softens: λ never falls";
    // Elastic and in full contact: the predictor along the last step is the solution.
    if (r.traced) {
      ++traced;
      EXPECT_LE(r.iterations, 1) << "step " << r.global_step;
    }
    worst = std::max(worst, std::abs(r.energy.relative_error()));
    last_lambda = r.load_factor;
  });
  std::printf("coulomb_signorini, arc_length, %s bulk: %d increments, %d traced, worst balance "
              "%.3g\n",
              nonlinear ? "nonlinear" : "linear", summary.steps, traced, worst);
  EXPECT_DOUBLE_EQ(last_lambda, 1.0);
  EXPECT_GT(traced, 0) << "arc length traces the stage after its first (ramp) step";
  EXPECT_EQ(summary.traced_increments, traced);
  EXPECT_LT(worst, 1e-10);
}

INSTANTIATE_TEST_SUITE_P(BothBulkPaths, TracedContact, ::testing::Bool());

// Dissipation control follows the energy adhesion loss releases: without adhesion the stage
// stops at its start, naming it and the control that can trace it.
TEST(TracedContactInput, DissipationControlWithoutAdhesionSaysWhy) {
  const Model model =
      bipot::test::model_from_text(pressed_on_coulomb("dissipation", false), "traced.yaml");
  StaticAnalysis analysis(model);
  try {
    analysis.run([](const StepReport&) { ADD_FAILURE() << "no step should run"; });
    ADD_FAILURE() << "ran";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("stage 'pull': control dissipation follows the energy "
                                         "adhesion loss releases, and no interface has adhesion "
                                         "left to lose"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("use control: arc_length"), std::string::npos);
  }
}

// A hardening von Mises block on an elastic base, joined by a rate-independent RCCM joint,
// pressed, then sheared under dissipation control (inputs/examples/restart_within_stage.yaml
// at viscosity 0). The block yields: the plastic bulk dissipates what the adhesion's
// constraint does not see, and the traced shear step that follows two converged ones fails at
// every halving (Δλ runs away, the singular Jacobian). The stage gives up path-following and
// ramps on (PathControl::abandon) where the run used to stop; every step's energy balance
// (plastic and adhesion dissipation) holds to round-off, and the run ends at the shear's
// λ = 1.
TEST(PathFollowingPlasticBulk, AStageWhoseTracedStepsAllFailRampsOn) {
  const std::string text =
      "kinematics: plane_strain\n"
      "mesh:\n  blocks:\n    cell: quad4\n"
      "    x: {breaks: [0, 1.0], cells: [4]}\n"
      "    y: {breaks: [-0.5, 0, 0.5], cells: [2, 3]}\n"
      "    regions: [base, block]\n"
      "materials:\n"
      "  base: {type: linear_elastic, youngs_modulus: 1.0e5, poissons_ratio: 0.3}\n"
      "  block: {type: von_mises, youngs_modulus: 2.0e4, poissons_ratio: 0.25, yield_stress: "
      "30.0, hardening_modulus: 2.0e3}\n"
      "linear_solver: {method: direct}\n"
      "interfaces:\n  - name: joint\n    between: [base, block]\n    law: rccm\n"
      "    parameters: {normal_stiffness: 1.0e6, tangential_stiffness: 1.0e6, "
      "decohesion_energy: 1.0e-4, friction_coefficient: 0.3, adhesion_viscosity: 0.0}\n"
      "contact_solver: {type: generalized_newton, tolerance: 1.0e-13, max_iterations: 30}\n"
      "stages:\n"
      "  - name: press\n    increments: 3\n    boundary_conditions:\n"
      "      - {set: bottom, component: x, value: 0}\n"
      "      - {set: bottom, component: y, value: 0}\n"
      "      - {set: top, component: x, value: 0}\n"
      "      - {set: top, component: y, value: -2.0e-3}\n"
      "  - name: shear\n    increments: 4\n    control: dissipation\n"
      "    boundary_conditions:\n"
      "      - {set: bottom, component: x, value: 0}\n"
      "      - {set: bottom, component: y, value: 0}\n"
      "      - {set: top, component: x, value: 6.0e-3}\n"
      "      - {set: top, component: y, value: -2.0e-3}\n";
  const Model model = bipot::test::model_from_text(text, "plastic_block.yaml");
  StaticAnalysis analysis(model);
  double worst = 0, last_lambda = 0;
  std::string last_stage;
  int flagged = 0; // increments whose report says path-following gave up on them
  const RunSummary summary = analysis.run([&](const StepReport& r) {
    worst = std::max(worst, std::abs(r.energy.relative_error()));
    if (r.path_abandoned) {
      ++flagged;
      EXPECT_FALSE(r.traced);
      EXPECT_EQ(r.stage, "shear");
    }
    last_stage = r.stage, last_lambda = r.load_factor;
  });
  std::printf("%d increments, %d traced, %d stage(s) abandoned, worst balance %.3g\n",
              summary.steps, summary.traced_increments, summary.abandoned_paths, worst);
  // How many traced steps converge first is round-off's choice on this edge: 2 at 1 rank,
  // none at 2 ranks (run by hand), where the first one already fails at every halving.
  EXPECT_EQ(summary.abandoned_paths, 1);
  EXPECT_EQ(flagged, 1);
  EXPECT_EQ(summary.staggered_increments, 0);
  EXPECT_LT(worst, 1e-12);
  EXPECT_EQ(last_stage, "shear");
  EXPECT_DOUBLE_EQ(last_lambda, 1.0);
}

// The column's input with the law RCCM without its closed-form springs' work
// (tests/support/rccm_by_rule.hpp), and the catalogue that has it: the ledger then
// integrates that work by its quadrature, as for a viscous law.
std::string by_rule(std::string text) {
  const std::string law = "law: rccm\n";
  text.replace(text.find(law), law.size(), "law: rccm_by_rule\n");
  return text;
}

Catalogue catalogue_by_rule() {
  Catalogue catalogue = builtin_catalogue();
  catalogue.interface_laws.add<test::RccmByRule>();
  return catalogue;
}

// The worst |balance_error| / external work over the traced column's steps and at its end.
struct TracedBalance {
  double worst = 0, last = 0;
};

TracedBalance traced_balance(int increments, bool rule) {
  std::string text = input("dissipation");
  text.replace(text.find("increments: 12"), 14, "increments: " + std::to_string(increments));
  // The quadrature's own error on the planned steps: no energy control (on by default).
  text.replace(text.find("    control:"), 0, "    energy_tolerance: 0\n");
  const Model model =
      rule ? bipot::test::model_from_text(by_rule(text), "traced.yaml", catalogue_by_rule())
           : bipot::test::model_from_text(text, "traced.yaml");
  StaticAnalysis analysis(model);
  EnergyTotals last;
  TracedBalance out;
  analysis.run([&](const StepReport& r) {
    if (r.energy.adhesion_dissipation == 0.0) {
      EXPECT_LT(std::abs(r.energy.balance_error()), 1e-12 * r.energy.external_work);
    }
    out.worst = std::max(out.worst, std::abs(r.energy.balance_error()) / r.energy.external_work);
    last = r.energy;
  });
  // All the adhesion energy w A = 0.1 kJ goes but the little left in β = w/(C g²).
  EXPECT_NEAR(last.adhesion_dissipation, w * width, 0.01 * w * width);
  out.last = std::abs(last.balance_error()) / last.external_work;
  return out;
}

// The energy balance along the traced column. RCCM integrates its springs' work in closed form
// along each step (Rccm::spring_work), softening onset included: the balance holds to
// round-off at every step, however long (measured 1e-15; the ledger's quadrature alone left
// 1.3e-2 of the external work at 12 increments).
TEST(TracedEnergy, BalanceIsExactAtEveryStep) {
  for (int increments : {12, 48}) {
    const TracedBalance run = traced_balance(increments, false);
    std::printf("energy balance error / external work: worst %.3g (%d increments)\n", run.worst,
                increments);
    EXPECT_LT(run.worst, 1e-12) << increments << " increments";
  }
}

// Without the closed form the ledger's three-point rule on the softening springs' share of
// the external work (docs/energy_quadrature.md) leaves an error of third order in the step
// over the run (the quadrature's, not a solver error): 12 → 48 increments divides it by 64
// nominally (measured 1.3e-2 → 8.2e-5 of the external work at the end, 162 times; the
// trapezoid alone, second order, gave 1.9e-2 → 7.2e-4, 26 times, and fails both checks).
TEST(TracedEnergy, TheQuadratureIsThirdOrderWithoutTheClosedForm) {
  const double coarse = traced_balance(12, true).last, fine = traced_balance(48, true).last;
  std::printf("by the rule: energy balance error / external work: %.3g (12 increments), %.3g "
              "(48)\n",
              coarse, fine);
  EXPECT_LT(fine, 2e-4);
  EXPECT_GT(coarse / fine, 50.0); // third order: 64 for a 4 times shorter step
}

// The traced column with `energy_tolerance`, its springs' work left to the ledger's quadrature
// (rccm_by_rule, as a viscous law's is): an increment whose balance would break the budget is
// redone in halves (EnergyStepControl), so the balance holds at every step. The same number
// of increments spread evenly (control off) breaks it: the control spends its increments
// where β falls fastest.
struct ColumnRun {
  int increments = 0, halvings = 0, over_budget = 0;
  double worst = 0; // largest |balance_error| / external work after an increment
};

ColumnRun column_run(int increments, double tolerance, const std::string& control = "dissipation") {
  std::string text = input("{type: " + control + ", max_increments: 100000}");
  text.replace(text.find("increments: 12"), 14, "increments: " + std::to_string(increments));
  // The default max_cutbacks: a shorter step than the column's 1/8 for the energy as well.
  text.replace(text.find("max_cutbacks: 3"), 15, "max_cutbacks: 6");
  // 0 turns the control off (it is on by default).
  text.replace(text.find("    control:"), 0,
               "    energy_tolerance: " + std::to_string(tolerance) + "\n");
  const Model model =
      bipot::test::model_from_text(by_rule(text), "traced.yaml", catalogue_by_rule());
  StaticAnalysis analysis(model);
  ColumnRun run;
  const RunSummary summary = analysis.run([&](const StepReport& r) {
    run.worst = std::max(run.worst, std::abs(r.energy.relative_error()));
    EXPECT_EQ(r.staggered, 0);
  });
  run.increments = summary.steps;
  run.halvings = summary.energy_halvings;
  run.over_budget = summary.over_energy_budget;
  return run;
}

TEST(TracedEnergy, EnergyToleranceHoldsTheBalanceAtEveryStep) {
  for (double tolerance : {1e-4, 1e-5}) {
    const ColumnRun controlled = column_run(12, tolerance);
    // Uniform refinement: planned increments doubled until the balance holds at every step.
    ColumnRun uniform;
    for (int n = 12; n <= 12 * 64 && !(uniform.increments > 0 && uniform.worst <= tolerance);
         n *= 2)
      uniform = column_run(n, 0.0);
    std::printf("energy_tolerance %.0e: %d increments (%d halvings, %d flagged), worst balance "
                "error %.3g; uniform refinement: %d increments, worst %.3g\n",
                tolerance, controlled.increments, controlled.halvings, controlled.over_budget,
                controlled.worst, uniform.increments, uniform.worst);
    EXPECT_LE(controlled.worst, tolerance);
    // 1e-5: the first traced step from the limit point and a few ramp steps after the
    // snap-back stay over their own share at the smallest step (1/64) and are flagged; the
    // run's balance holds all the same.
    if (tolerance == 1e-4) {
      EXPECT_EQ(controlled.over_budget, 0);
    }
    EXPECT_GT(controlled.halvings, 0);
    EXPECT_LE(uniform.worst, tolerance);
    EXPECT_LT(controlled.increments + controlled.halvings, uniform.increments);
  }
}

// Arc-length steps are shortened the same way (the budget halves the arc length).
TEST(TracedEnergy, EnergyToleranceHoldsAlongArcLengthSteps) {
  const ColumnRun off = column_run(12, 0.0, "arc_length");
  const ColumnRun on = column_run(12, 1e-4, "arc_length");
  std::printf("arc_length: worst balance error %.3g in %d increments without energy_tolerance, "
              "%.3g in %d (%d halvings, %d flagged) with 1e-4\n",
              off.worst, off.increments, on.worst, on.increments, on.halvings, on.over_budget);
  EXPECT_GT(off.worst, 1e-4);
  EXPECT_LE(on.worst, 1e-4);
  EXPECT_GT(on.halvings, 0);
}

void expect_input_error(const std::string& text, const std::string& fragment) {
  try {
    read_problem_text(text, "bad.yaml", bipot::builtin_catalogue());
    ADD_FAILURE() << "accepted; expected an error containing: " << fragment;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.yaml:"), std::string::npos) << e.what();
  }
}

TEST(PathFollowingInput, BadControlsAreLocated) {
  // The messages of the stage's control schema (control_schema()).
  expect_input_error(input("arc_lenght"), "stages[0].control: value \"arc_lenght\" is not one "
                                          "of: ramp, arc_length, dissipation (did you mean "
                                          "\"arc_length\"?)");
  expect_input_error(input("{type: arc_length, arc_length: -0.1}"),
                     "stages[0].control.arc_length: value -0.1 is out of range (0, inf) m");
  expect_input_error(input("{type: dissipation, dissipation_step: 0}"),
                     "stages[0].control.dissipation_step: value 0 is out of range (0, inf) kJ");
  expect_input_error(input("{type: ramp, arc_length: 1}"),
                     "stages[0].control.arc_length: only for type: arc_length (this control is "
                     "ramp)");
  expect_input_error(input("dissipation", "semismooth_newton"),
                     "needs contact_solver.type: generalized_newton");
  std::string still = input("arc_length");
  still.replace(still.find("value: 0.12"), 11, "value: 0");
  expect_input_error(still, "nothing to scale");
  // Only ties: no interface unknowns for a constraint to measure, nothing that softens.
  std::string tied = input("arc_length");
  const std::size_t at = tied.find("law: rccm");
  tied.replace(at, tied.find('}', at) + 1 - at, "law: perfect_bonding");
  expect_input_error(tied, "no interface with a contact law (perfect_bonding only, or none)");
}

// `energy_tolerance` out of [0, 1): at its key, with the range (describe_energy_tolerance()).
TEST(PathFollowingInput, BadEnergyToleranceIsLocated) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"-1.0e-6", "-1e-06"}, {"1.0", "1"}, {"2", "2"}};
  for (const auto& [value, shown] : cases) {
    std::string text = input("dissipation");
    text.replace(text.find("    control:"), 0, "    energy_tolerance: " + value + "\n");
    expect_input_error(text, "bad.yaml:23:5: stages[0].energy_tolerance: value " + shown +
                                 " is out of range [0, 1)");
  }
}

} // namespace
} // namespace bipot
