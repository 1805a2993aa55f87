// An elastic block on an elastic foundation, plane strain: pressed down, sheared until it
// slides, then lifted. Node-to-node interface between the two regions.
// - gross sliding: the tangential interface force equals mu times the normal one;
// - before sliding the interface sticks and carries less than mu N;
// - lifted, the interface is open and carries nothing;
// - both contact solvers reach the same solution; RCCM with beta0 = 0 is Coulomb-Signorini;
// - perfect bonding equals the same mesh without any interface.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "apps/catalogue/contact_module.hpp"
#include "fem/analysis/model.hpp"
#include "fem/analysis/result_writer.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/input/problem_reader.hpp"
#include "fem/linalg/communicator.hpp"
#include "tests/support/model_from_text.hpp"

#include "tests/support/block_stage.hpp"
#include "tests/support/serial_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace bipot {
namespace {

std::string block_input(const std::string& interface, const std::string& solver,
                        const std::string& stages) {
  return "kinematics: plane_strain\n" + test::block_on_base_mesh +
         "materials:\n"
         "  base: {type: linear_elastic, youngs_modulus: 1.0e5, poissons_ratio: 0.3}\n"
         "  block: {type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.25}\n"
         "linear_solver: {method: direct}\n" +
         interface + solver + "stages:\n" + stages;
}

const std::string press_shear_lift =
    "  - name: press\n    increments: 2\n    boundary_conditions:\n"
    "      - {set: bottom, component: x, value: 0}\n"
    "      - {set: bottom, component: y, value: 0}\n"
    "      - {set: top, component: x, value: 0}\n"
    "      - {set: top, component: y, value: -1.0e-3}\n"
    "  - name: shear\n    increments: 4\n    boundary_conditions:\n"
    "      - {set: bottom, component: x, value: 0}\n"
    "      - {set: bottom, component: y, value: 0}\n"
    "      - {set: top, component: x, value: 4.0e-3}\n"
    "      - {set: top, component: y, value: -1.0e-3}\n"
    "  - name: lift\n    increments: 2\n    boundary_conditions:\n"
    "      - {set: bottom, component: x, value: 0}\n"
    "      - {set: bottom, component: y, value: 0}\n"
    "      - {set: top, component: x, value: 4.0e-3}\n"
    "      - {set: top, component: y, value: 1.0e-3}\n";

std::string coulomb(double mu) {
  return "interfaces:\n  - name: joint\n    between: [base, block]\n    law: coulomb_signorini\n"
         "    parameters: {friction_coefficient: " +
         std::to_string(mu) + "}\n";
}

std::string solver(const std::string& type) {
  return "contact_solver: {type: " + type + ", tolerance: 1.0e-11}\n";
}

struct StageForces {
  std::vector<std::array<double, 3>> resultant; ///< interface force after each increment
  std::vector<int> sticking;                    ///< pairs in stick after each increment
  std::vector<double> cone_error; ///< max over slipping pairs of | |r_t| - mu_bar r_n | / r_n
  std::vector<double> u;          ///< final displacement
};

StageForces run(const std::string& text) {
  const Model model = bipot::test::model_from_text(text, "block.yaml");
  StaticAnalysis analysis(model);
  StageForces out;
  analysis.run([&](const StepReport&) {
    if (analysis.interfaces().empty()) return;
    const auto& ia = *analysis.interfaces()[0];
    out.resultant.push_back(ia.resultant());
    int stick = 0;
    double cone = 0;
    for (const auto& r : ia.results()) {
      stick += r.status == contact::ContactStatus::Stick;
      if (r.status == contact::ContactStatus::Slip)
        cone =
            std::max(cone, std::abs(r.r.tail(r.r.size() - 1).norm() -
                                    interface_law(model, 0).friction_coefficient(r.beta) * r.r(0)) /
                               r.r(0));
    }
    out.sticking.push_back(stick);
    out.cone_error.push_back(cone);
  });
  out.u = analysis.displacement();
  return out;
}

// The increment predictor (u and the multipliers extrapolated along the last increment) is
// exact under proportional loading of a sticking interface: every increment after the first
// converges with one linear solve and no multiplier update, where the first needs updates
// (the augmented Lagrangian converging from the committed multipliers).
TEST(ContactBlock, PredictorMakesProportionalIncrementsExact) {
  const std::string press = "  - name: press\n    increments: 4\n    boundary_conditions:\n"
                            "      - {set: bottom, component: x, value: 0}\n"
                            "      - {set: bottom, component: y, value: 0}\n"
                            "      - {set: top, component: x, value: 0}\n"
                            "      - {set: top, component: y, value: -1.0e-3}\n";
  for (const std::string type : {"semismooth_newton", "bipotential_uzawa"}) {
    const Model model =
        bipot::test::model_from_text(block_input(coulomb(0.3), solver(type), press), "b.yaml");
    StaticAnalysis analysis(model);
    std::vector<StepReport> steps;
    analysis.run([&](const StepReport& r) { steps.push_back(r); });
    ASSERT_EQ(steps.size(), 4u) << type;
    EXPECT_GT(steps[0].uzawa_updates, 0) << type;
    for (std::size_t k = 1; k < steps.size(); ++k) {
      EXPECT_EQ(steps[k].uzawa_updates, 0) << type << " increment " << k + 1;
      EXPECT_EQ(steps[k].iterations, 1) << type << " increment " << k + 1;
    }
    int sticking = 0;
    for (const auto& r : analysis.interfaces()[0]->results())
      sticking += r.status == contact::ContactStatus::Stick;
    EXPECT_EQ(sticking, static_cast<int>(analysis.interfaces()[0]->num_pairs())) << type;
  }
}

TEST(ContactBlock, SlidesAtMuTimesNormalForceAndOpensWhenLifted) {
  const double mu = 0.3;
  const auto res = run(block_input(coulomb(mu), solver("semismooth_newton"), press_shear_lift));
  ASSERT_EQ(res.resultant.size(), 8u);
  // Pressed: compression across the joint (force on the block points up), no shear.
  EXPECT_GT(res.resultant[1][1], 0.0);
  // Last shear increment: 4 mm of shear over 1 mm of compression makes the block slide.
  const auto& f = res.resultant[5];
  EXPECT_NEAR(std::abs(f[0]), mu * f[1], 1e-8 * mu * f[1]);
  EXPECT_EQ(res.sticking[5], 0);
  // Lifted: the joint is open and carries nothing.
  EXPECT_EQ(res.resultant[7][0], 0.0);
  EXPECT_EQ(res.resultant[7][1], 0.0);
}

TEST(ContactBlock, SticksBeforeSliding) {
  const double mu = 0.3;
  const std::string small_shear = "  - name: press\n    boundary_conditions:\n"
                                  "      - {set: bottom, component: x, value: 0}\n"
                                  "      - {set: bottom, component: y, value: 0}\n"
                                  "      - {set: top, component: x, value: 0}\n"
                                  "      - {set: top, component: y, value: -1.0e-3}\n"
                                  "  - name: nudge\n    boundary_conditions:\n"
                                  "      - {set: bottom, component: x, value: 0}\n"
                                  "      - {set: bottom, component: y, value: 0}\n"
                                  "      - {set: top, component: x, value: 1.0e-5}\n"
                                  "      - {set: top, component: y, value: -1.0e-3}\n";
  const auto res = run(block_input(coulomb(mu), solver("semismooth_newton"), small_shear));
  const auto& f = res.resultant.back();
  EXPECT_GT(std::abs(f[0]), 0.0);
  EXPECT_LT(std::abs(f[0]), 0.5 * mu * f[1]);
}

TEST(ContactBlock, UzawaAndNewtonAgree) {
  const auto newton = run(block_input(coulomb(0.3), solver("semismooth_newton"), press_shear_lift));
  const auto uzawa = run(block_input(coulomb(0.3), solver("bipotential_uzawa"), press_shear_lift));
  EXPECT_LT(test::relative_difference(uzawa.u, newton.u), 1e-8);
}

// The exact generalized Newton reaches the same solution as the two augmented-Lagrangian
// solvers (all stop at 1e-11 relative; 1e-8 leaves room for the conditioning) with far fewer
// linear solves: the multipliers are unknowns of its Newton step.
TEST(ContactBlock, GeneralizedNewtonAgreesWithBothSolvers) {
  const auto exact = run(block_input(coulomb(0.3), solver("generalized_newton"), press_shear_lift));
  const auto newton = run(block_input(coulomb(0.3), solver("semismooth_newton"), press_shear_lift));
  const auto uzawa = run(block_input(coulomb(0.3), solver("bipotential_uzawa"), press_shear_lift));
  const double d_newton = test::relative_difference(exact.u, newton.u);
  const double d_uzawa = test::relative_difference(exact.u, uzawa.u);
  std::printf("[block] generalized_newton vs semismooth_newton %.2e, vs bipotential_uzawa %.2e\n",
              d_newton, d_uzawa);
  EXPECT_LT(d_newton, 1e-8);
  EXPECT_LT(d_uzawa, 1e-8);
  ASSERT_EQ(exact.resultant.size(), newton.resultant.size());
  for (std::size_t k = 0; k < exact.resultant.size(); ++k)
    for (int c = 0; c < 2; ++c)
      EXPECT_NEAR(exact.resultant[k][c], newton.resultant[k][c],
                  1e-8 * std::abs(newton.resultant[1][1]))
          << "increment " << k + 1;
}

// Locally quadratic convergence of generalized_newton on a smooth branch: a viscous RCCM joint
// (β evolves smoothly) pulled and sheared, in the bonded and then debonding regime. Where the
// residual is in the asymptotic range (below 1e-2) and above round-off, each iteration's
// relative residual is at most C times the previous one squared; C = 10 bounds the constants
// (‖J⁻¹‖‖J″‖ in these units) with room, and a linear rate (r_k+1 ≈ 0.1–0.9 r_k, as the
// augmented Lagrangian's) fails it as soon as r_k < 1e-2.
TEST(ContactBlock, GeneralizedNewtonConvergesQuadratically) {
  const std::string rccm =
      "interfaces:\n  - name: joint\n    between: [base, block]\n    law: rccm\n"
      "    parameters: {normal_stiffness: 1.0e5, tangential_stiffness: 1.0e5, "
      "decohesion_energy: 0.005, friction_coefficient: 0.3, adhesion_viscosity: 0.02}\n";
  const std::string pull = "  - name: pull\n    increments: 6\n    boundary_conditions:\n"
                           "      - {set: bottom, component: x, value: 0}\n"
                           "      - {set: bottom, component: y, value: 0}\n"
                           "      - {set: top, component: x, value: 2.0e-3}\n"
                           "      - {set: top, component: y, value: 3.0e-3}\n";
  const Model model = bipot::test::model_from_text(
      block_input(rccm, "contact_solver: {type: generalized_newton, tolerance: 1.0e-13}\n", pull),
      "b.yaml");
  StaticAnalysis analysis(model);
  int checked = 0;
  double min_beta = 1;
  analysis.run([&](const StepReport& r) {
    std::printf("[quadratic] step %d:", r.step);
    for (double h : r.residual_history)
      std::printf(" %.3e", h);
    std::printf("\n");
    for (std::size_t k = 1; k < r.residual_history.size(); ++k) {
      const double prev = r.residual_history[k - 1], next = r.residual_history[k];
      if (prev > 1e-2 || 10 * prev * prev < 1e-13) continue;
      EXPECT_LE(next, 10 * prev * prev) << "step " << r.step << " iteration " << k;
      ++checked;
    }
    for (const auto& p : analysis.interfaces()[0]->results())
      min_beta = std::min(min_beta, p.beta);
  });
  EXPECT_GT(checked, 0);    // the test must have seen the asymptotic range
  EXPECT_LT(min_beta, 0.9); // and the debonding (softening) branch
}

TEST(ContactBlock, RccmWithoutAdhesionIsCoulombSignorini) {
  const std::string rccm =
      "interfaces:\n  - name: joint\n    between: [base, block]\n    law: rccm\n"
      "    parameters: {normal_stiffness: 1.0e6, tangential_stiffness: 1.0e6, "
      "decohesion_energy: 0.01, friction_coefficient: 0.3, initial_adhesion: 0.0}\n";
  const auto a = run(block_input(rccm, solver("semismooth_newton"), press_shear_lift));
  const auto b = run(block_input(coulomb(0.3), solver("semismooth_newton"), press_shear_lift));
  EXPECT_LT(test::relative_difference(a.u, b.u), 1e-10);
}

TEST(ContactBlock, PerfectBondingEqualsNoInterface) {
  const std::string bonded =
      "interfaces:\n  - name: joint\n    between: [base, block]\n    law: perfect_bonding\n";
  const std::string press = "  - name: press\n    boundary_conditions:\n"
                            "      - {set: bottom, component: x, value: 0}\n"
                            "      - {set: bottom, component: y, value: 0}\n"
                            "      - {set: top, component: x, value: 2.0e-3}\n"
                            "      - {set: top, component: y, value: 1.0e-3}\n";
  const auto a = run(block_input(bonded, "", press));
  const auto b = run(block_input("", "", press));
  ASSERT_EQ(a.u.size(), b.u.size());
  EXPECT_LT(test::relative_difference(a.u, b.u), 1e-10);
}

TEST(ContactBlock, StiffStrongRccmApproachesPerfectBonding) {
  const std::string press = "  - name: press\n    boundary_conditions:\n"
                            "      - {set: bottom, component: x, value: 0}\n"
                            "      - {set: bottom, component: y, value: 0}\n"
                            "      - {set: top, component: x, value: 2.0e-3}\n"
                            "      - {set: top, component: y, value: 1.0e-3}\n";
  const auto bonded = run(block_input(
      "interfaces:\n  - name: joint\n    between: [base, block]\n    law: perfect_bonding\n", "",
      press));
  // Interface springs C against the bulk's ~E/h: the jump, hence the difference from the
  // bonded solution, scales as E/(C h). Two stiffnesses show the convergence.
  std::vector<double> differences;
  for (const char* c : {"1.0e8", "1.0e10"}) {
    const std::string rccm = std::string("interfaces:\n  - name: joint\n    between: [base, "
                                         "block]\n    law: rccm\n    parameters: "
                                         "{normal_stiffness: ") +
                             c + ", tangential_stiffness: " + c +
                             ", decohesion_energy: 1.0e6, friction_coefficient: 0.3}\n";
    const auto a = run(block_input(rccm, solver("semismooth_newton"), press));
    // The split mesh has extra nodes at the end: compare the shared numbering only.
    std::vector<double> u(a.u.begin(), a.u.begin() + bonded.u.size());
    differences.push_back(test::relative_difference(u, bonded.u));
  }
  EXPECT_LT(differences[0], 1e-2);
  EXPECT_LT(differences[1], 1e-4);
  EXPECT_LT(differences[1], 0.02 * differences[0]); // ~100x stiffer, ~100x closer
}

TEST(ContactBlock3d, SlidesAtMuTimesNormalForce) {
  // A hex8 block on a base, sheared diagonally in x and z: the slip is a 2-vector and the
  // tangential force must lie on the full Coulomb cone, |F_t| = mu F_n.
  const double mu = 0.4;
  const std::string text =
      "kinematics: three_d\n"
      "mesh:\n  blocks:\n    cell: hex8\n"
      "    x: {breaks: [0, 1.0], cells: [2]}\n"
      "    y: {breaks: [-0.5, 0, 0.5], cells: [1, 2]}\n"
      "    z: {breaks: [0, 1.0], cells: [2]}\n"
      "    regions: [base, block]\n"
      "materials:\n"
      "  base: {type: linear_elastic, youngs_modulus: 1.0e5, poissons_ratio: 0.3}\n"
      "  block: {type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.25}\n"
      "linear_solver: {method: direct}\n" +
      coulomb(mu) + solver("semismooth_newton") +
      "stages:\n"
      "  - name: press\n    boundary_conditions:\n"
      "      - {set: bottom, component: x, value: 0}\n"
      "      - {set: bottom, component: y, value: 0}\n"
      "      - {set: bottom, component: z, value: 0}\n"
      "      - {set: top, component: x, value: 0}\n"
      "      - {set: top, component: y, value: -1.0e-3}\n"
      "      - {set: top, component: z, value: 0}\n"
      "  - name: shear\n    increments: 3\n    boundary_conditions:\n"
      "      - {set: bottom, component: x, value: 0}\n"
      "      - {set: bottom, component: y, value: 0}\n"
      "      - {set: bottom, component: z, value: 0}\n"
      "      - {set: top, component: x, value: 3.0e-3}\n"
      "      - {set: top, component: y, value: -1.0e-3}\n"
      "      - {set: top, component: z, value: 4.0e-3}\n";
  const auto res = run(text);
  const auto& f = res.resultant.back();
  const double tangential = std::hypot(f[0], f[2]);
  EXPECT_GT(f[1], 0.0);
  // Every pair slips and sits on the cone: |r_t| = mu r_n to the solver tolerance.
  EXPECT_EQ(res.sticking.back(), 0);
  EXPECT_LT(res.cone_error.back(), 1e-8);
  // The pairs' slip directions differ slightly (elastic deformation of the block), so the
  // resultant is a little inside the cone: |F_t| <= mu F_n, within a fraction of a percent.
  EXPECT_LE(tangential, mu * f[1] * (1 + 1e-12));
  EXPECT_GT(tangential, 0.999 * mu * f[1]);
  // The friction force opposes the block's sliding direction (3, 4)/5 of the top.
  EXPECT_NEAR(f[0] / tangential, -0.6, 0.05);
  EXPECT_NEAR(f[2] / tangential, -0.8, 0.05);
}

TEST(ContactBlock, InterfaceOutputFilesHoldTheResultant) {
  // The CSV written per interface carries the same resultant as the solver: at gross
  // sliding |F_x| = mu F_y (1e-8, the CSV keeps 17 digits); the VTK series exists.
  const double mu = 0.3;
  std::string text = block_input(coulomb(mu), solver("semismooth_newton"), press_shear_lift);
  const std::string dir = "contact_block_output";
  if (mpi_rank() == 0) std::filesystem::remove_all(dir);
  barrier();
  text += "output: {directory: " + dir + "}\n";
  const Model model = bipot::test::model_from_text(text, "block.yaml");
  ResultWriter writer(model, mpi_rank(), mpi_size());
  StaticAnalysis analysis(model, {}, &writer);
  analysis.run();
  std::ifstream csv(dir + "/interface_joint.csv");
  ASSERT_TRUE(csv.good());
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "stage,step,time,load_factor,force_x,force_y,cutbacks,staggered,unstable,traced");
  std::vector<std::vector<double>> rows;
  while (std::getline(csv, line)) {
    std::vector<double> row;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');)
      row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  ASSERT_EQ(rows.size(), 8u);
  const auto& sliding = rows[5]; // last shear increment
  EXPECT_NEAR(std::abs(sliding[4]), mu * sliding[5], 1e-8 * mu * sliding[5]);
  EXPECT_EQ(rows[7][4], 0.0); // lifted: open
  EXPECT_TRUE(std::filesystem::exists(dir + "/interface_joint.pvd"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/interface_joint_0007_0.vtu"));
  barrier(); // every rank has read before the next test may clean up
}

// Cut-backs keep the plan: with at most 1 Newton iteration per attempt the shear stage
// (press and shear only: opening takes 3) needs cut-backs, and the sub-increments that follow end
// exactly on the next planned load level, so every planned level k/n of every stage has its result,
// flagged as such.
TEST(ContactBlock, CutBacksKeepThePlannedLoadLevels) {
  const std::string press_shear =
      press_shear_lift.substr(0, press_shear_lift.find("  - name: lift"));
  const Model model = bipot::test::model_from_text(
      block_input(coulomb(0.3),
                  "contact_solver: {type: generalized_newton, max_iterations: 1, "
                  "tolerance: 1.0e-10}\n",
                  press_shear),
      "b.yaml");
  StaticAnalysis analysis(model);
  std::map<int, std::vector<StepReport>> by_stage;
  const RunSummary summary =
      analysis.run([&](const StepReport& r) { by_stage[r.stage_index].push_back(r); });
  EXPECT_GT(summary.cutbacks, 0); // the test must exercise a cut-back
  EXPECT_GT(summary.sub_increments, 0);
  int sub = 0;
  for (const auto& [stage, reports] : by_stage) {
    const int n = reports.front().steps;
    int next = 1;
    for (const StepReport& r : reports) {
      if (r.planned_step == 0) {
        ++sub;
        EXPECT_GT(r.load_factor, static_cast<double>(next - 1) / n) << "stage " << stage;
        EXPECT_LT(r.load_factor, static_cast<double>(next) / n) << "stage " << stage;
        continue;
      }
      EXPECT_EQ(r.planned_step, next) << "stage " << stage;
      EXPECT_EQ(r.load_factor, next == n ? 1.0 : static_cast<double>(next) / n);
      EXPECT_EQ(r.stage_end, next == n);
      ++next;
    }
    EXPECT_EQ(next, n + 1) << "stage " << stage << ": a planned level has no result";
  }
  EXPECT_EQ(sub, summary.sub_increments);
}

// The energy balance (energy.csv) of pressing, shearing to full sliding and lifting a block
// on a Coulomb joint: external work = bulk elastic energy + contact work at every step. Each
// term is a trapezoidal rule, exact here (linear bulk, friction at constant force while it
// slides, unilateral contact), so the balance holds to round-off; friction dissipates
// (contact work > 0 once the block has slid).
TEST(ContactBlock, EnergyBalancesAtEveryStep) {
  const Model model = bipot::test::model_from_text(
      block_input(coulomb(0.3), solver("generalized_newton"), press_shear_lift), "b.yaml");
  StaticAnalysis analysis(model);
  EnergyTotals last;
  analysis.run([&](const StepReport& r) {
    const EnergyTotals& e = r.energy;
    EXPECT_LT(std::abs(e.balance_error()), 1e-10 * std::abs(e.external_work))
        << "stage " << r.stage << " step " << r.step;
    last = e;
  });
  EXPECT_GT(last.contact_work, 0.0); // the sliding dissipated
  EXPECT_EQ(last.adhesion_dissipation, 0.0);
}

// `output_at` asks for results at load factors between the planned levels: the ramp stops
// exactly on each (flagged requested_output, not counted as sub-increments), the planned levels
// keep theirs, and the VTK series gets those steps although `output.every` skips the others.
TEST(ContactBlock, OutputAtAddsExactStops) {
  const std::string stage = "  - name: press\n    increments: 2\n    output_at: [0.1, 0.5, 0.75]\n"
                            "    boundary_conditions:\n"
                            "      - {set: bottom, component: x, value: 0}\n"
                            "      - {set: bottom, component: y, value: 0}\n"
                            "      - {set: top, component: y, value: -1.0e-3}\n";
  const std::string dir = "contact_block_output_at";
  if (mpi_rank() == 0) std::filesystem::remove_all(dir);
  barrier();
  const Model model = bipot::test::model_from_text(
      block_input("", "", stage) + "output: {directory: " + dir + ", every: 100}\n", "b.yaml");
  ResultWriter writer(model, mpi_rank(), mpi_size());
  StaticAnalysis analysis(model, {}, &writer);
  std::vector<double> factors, requested;
  std::vector<int> planned;
  const RunSummary summary = analysis.run([&](const StepReport& r) {
    factors.push_back(r.load_factor);
    planned.push_back(r.planned_step);
    if (r.requested_output) requested.push_back(r.load_factor);
  });
  EXPECT_EQ(factors, (std::vector<double>{0.1, 0.5, 0.75, 1.0}));
  EXPECT_EQ(planned, (std::vector<int>{0, 1, 0, 2}));
  EXPECT_EQ(requested, (std::vector<double>{0.1, 0.5, 0.75}));
  EXPECT_EQ(summary.sub_increments, 0);
  // VTK at the three asked levels and the stage's end, although every: 100 skips the rest.
  int vtk_files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    vtk_files += name.rfind("solution_", 0) == 0 && name.size() > 6 &&
                 name.compare(name.size() - 6, 6, "_0.vtu") == 0;
  }
  EXPECT_EQ(vtk_files, 4);
  barrier(); // every rank has counted before the next test may clean up
  // Out of range or decreasing factors are refused with their place.
  for (const std::string bad : {"[0.5, 0.2]", "[0, 0.5]", "[1.5]"}) {
    std::string text = block_input("", "", stage);
    text.replace(text.find("[0.1, 0.5, 0.75]"), 16, bad);
    EXPECT_THROW(read_problem_text(text, "b.yaml", bipot::builtin_catalogue()), InputError) << bad;
  }
}

// A linear model without interfaces, loaded in 3 increments: the predictor solves increments
// 2 and 3 exactly, and their residual must be judged against the model's forces (the last
// reactions), not against its own round-off (which stalled them at 'relative residual 1').
// The result equals the one-increment solve to round-off.
TEST(ContactBlock, LinearModelInSeveralIncrementsEqualsOne) {
  auto solve = [](int increments) {
    const std::string stage = "  - name: press\n    increments: " + std::to_string(increments) +
                              "\n    boundary_conditions:\n"
                              "      - {set: bottom, component: x, value: 0}\n"
                              "      - {set: bottom, component: y, value: 0}\n"
                              "      - {set: top, component: y, value: -1.0e-3}\n";
    const Model model = bipot::test::model_from_text(block_input("", "", stage), "b.yaml");
    StaticAnalysis analysis(model);
    analysis.run();
    return analysis.displacement();
  };
  EXPECT_LT(test::relative_difference(solve(3), solve(1)), 1e-12);
}

// reactions.csv has a column only for the (set, component) pairs some stage constrains, and
// each set sums the reactions of its own nodes: the corner node shared by `left` and `bottom`
// counts in both.
TEST(ContactBlock, ReactionsHoldOnlyConstrainedComponents) {
  const std::string stages = "  - name: press\n    increments: 1\n    boundary_conditions:\n"
                             "      - {set: bottom, component: x, value: 0}\n"
                             "      - {set: bottom, component: y, value: 0}\n"
                             "      - {set: top, component: y, value: -1.0e-3}\n"
                             "  - name: hold\n    increments: 1\n    boundary_conditions:\n"
                             "      - {set: bottom, component: y, value: 0}\n"
                             "      - {set: left, component: x, value: 0}\n"
                             "      - {set: top, component: y, value: -1.0e-3}\n";
  const std::string dir = "contact_block_reactions";
  if (mpi_rank() == 0) std::filesystem::remove_all(dir);
  barrier();
  // No interface: one conforming body of two regions.
  const std::string text = block_input("", "", stages) + "output: {directory: " + dir + "}\n";
  const Model model = bipot::test::model_from_text(text, "block.yaml");
  std::vector<double> bottom, left, top;
  {
    ResultWriter writer(model, mpi_rank(), mpi_size());
    StaticAnalysis analysis(model, {}, &writer);
    analysis.run();
    bottom = analysis.reaction("bottom");
    left = analysis.reaction("left");
    top = analysis.reaction("top");
  }
  barrier();
  std::ifstream csv(dir + "/reactions.csv");
  ASSERT_TRUE(csv.good());
  std::string line;
  std::getline(csv, line);
  // Sets in name order, then components; top_fx, left_fy and the free `right` are absent;
  // then the step's flags.
  EXPECT_EQ(line, "stage,step,time,load_factor,bottom_fx,bottom_fy,left_fx,top_fy,cutbacks,"
                  "staggered,unstable,traced");
  std::vector<double> last;
  int rows = 0;
  while (std::getline(csv, line)) {
    last.clear();
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');)
      last.push_back(std::stod(cell));
    ++rows;
  }
  ASSERT_EQ(rows, 2);
  ASSERT_EQ(last.size(), 12u);
  EXPECT_EQ(last[8], 0.0);  // converged without a cut-back
  EXPECT_EQ(last[11], 0.0); // ramped, not traced
  // The CSV keeps 17 digits: the values are the analysis's, exactly.
  EXPECT_EQ(last[4], bottom[0]);
  EXPECT_EQ(last[5], bottom[1]);
  EXPECT_EQ(last[6], left[0]);
  EXPECT_EQ(last[7], top[1]);
  // Pressed: the top pushes down, the bottom holds it up, to the solver tolerance.
  EXPECT_LT(last[7], 0.0);
  EXPECT_NEAR(last[5] + last[7], 0.0, 1e-8 * std::abs(last[7]));
  // In the hold stage only `left` holds x and nothing else acts along x, so its x reactions
  // sum to zero. Its bottom corner is also a node of `bottom`, whose x column is that node's
  // reaction alone (its other nodes are free in x): not zero, because the shared node counts
  // in both sets.
  EXPECT_NEAR(last[6], 0.0, 1e-8 * std::abs(last[7]));
  EXPECT_GT(std::abs(last[4]), 1e-3 * std::abs(last[7]));
  barrier(); // every rank has read before the next test may clean up
}

// The interface VTK series follows `output.vtk` and `output.every` like the solution series
// (it used to write every step whatever they said); its CSV keeps every step.
TEST(ContactBlock, InterfaceSeriesFollowsTheOutputSettings) {
  namespace fs = std::filesystem;
  for (const std::string output : {"{vtk: false}", "{every: 3}"}) {
    const std::string dir = "contact_block_output_every";
    if (mpi_rank() == 0) fs::remove_all(dir);
    barrier();
    const std::string text =
        block_input(coulomb(0.3), solver("generalized_newton"), press_shear_lift) +
        "output: {directory: " + dir + ", " + output.substr(1);
    const Model model = bipot::test::model_from_text(text, "block.yaml");
    {
      ResultWriter writer(model, mpi_rank(), mpi_size());
      StaticAnalysis analysis(model, {}, &writer);
      analysis.run();
    }
    barrier();
    int interface_steps = 0, solution_steps = 0, csv_rows = -1;
    for (const auto& e : fs::directory_iterator(dir)) {
      const std::string name = e.path().filename().string();
      if (name.rfind("interface_joint_", 0) == 0) ++interface_steps;
      if (name.rfind("solution_", 0) == 0 && name.find("_0.vtu") != std::string::npos)
        ++solution_steps;
    }
    std::ifstream csv(dir + "/interface_joint.csv");
    for (std::string line; std::getline(csv, line);)
      ++csv_rows;
    EXPECT_EQ(csv_rows, 8) << output;
    if (output == "{vtk: false}") {
      EXPECT_EQ(interface_steps, 0);
      EXPECT_FALSE(fs::exists(dir + "/interface_joint.pvd"));
    } else {
      // Steps 3 and 6 of the run, and the last of each of the three stages: 2, 6, 8.
      EXPECT_EQ(solution_steps, 4);
      EXPECT_EQ(interface_steps, solution_steps);
    }
    barrier();
    if (mpi_rank() == 0) fs::remove_all(dir);
  }
}

} // namespace
} // namespace bipot
