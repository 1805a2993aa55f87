// Interface laws and parameters changed by a stage (`interfaces:` in a stage), on the elastic
// block on an elastic base of contact_block_test.cpp (plane strain):
// - the friction coefficient changed between two shear stages: at full sliding the joint's
//   tangential force is μ_stage × its normal force in each stage;
// - an interface bonded in a first stage and frictional later is split and tied on its
//   pairs: while bonded it equals the shared-node model (perfect bonding in every stage);
// - bonded installation, then RCCM: equals the RCCM model loaded the same way, since the
//   installation (uniaxial compression of a homogeneous column) leaves no jump either way;
// - RCCM stiffnesses doubled by a stage while the joint debonds (α > 0): the energy balance
//   books the springs' change at the switch, ½ A β² (ΔC_n g_n² + ΔC_t ‖g_t‖²) at the
//   recorded jumps, as interference work, and the first step's viscous dissipation is the
//   trapezoid of the new law's driving force (β E − w)⁺, E = C_n ⟨g_n⟩₊² + C_t ‖g_t‖², times
//   the loss, both computed here from the pairs' states (to 1e-12 and 1e-10 relative).
//   Before, the change was booked nowhere and the step started from the old law's force.
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/input/problem_reader.hpp"
#include "tests/support/block_stage.hpp"
#include "tests/support/model_from_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace bipot {
namespace {

std::string block(const std::string& block_material, const std::string& law,
                  const std::string& stages) {
  return "kinematics: plane_strain\n" + test::block_on_base_mesh +
         "materials:\n"
         "  base: {type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.25}\n"
         "  block: " +
         block_material +
         "\n"
         "linear_solver: {method: direct}\n"
         "interfaces:\n  - name: joint\n    between: [base, block]\n    law: " +
         law +
         "\n"
         "contact_solver: {type: generalized_newton, tolerance: 1.0e-12}\n"
         "stages:\n" +
         stages;
}

const std::string stiff_block =
    "{type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.3}";

using test::block_stage;

struct Result {
  std::vector<std::array<double, 3>> resultant; ///< interface force after each increment
  std::vector<double> top_y;                    ///< reaction of set top, y, each increment
  std::vector<std::vector<double>> u;           ///< displacement after each increment
  std::vector<double> min_beta;                 ///< smallest β after each increment
};

Result run(const std::string& text) {
  const Model model = bipot::test::model_from_text(text, "staged.yaml");
  StaticAnalysis analysis(model);
  Result out;
  analysis.run([&](const StepReport&) {
    out.resultant.push_back(analysis.interfaces()[0]->resultant());
    out.top_y.push_back(analysis.reaction("top")[1]);
    out.u.push_back(analysis.displacement());
    double beta = 1;
    for (const auto& p : analysis.interfaces()[0]->results())
      beta = std::min(beta, p.beta);
    out.min_beta.push_back(beta);
  });
  return out;
}

double max_abs(const std::vector<double>& v, std::size_t n) {
  double m = 0;
  for (std::size_t i = 0; i < n; ++i)
    m = std::max(m, std::abs(v[i]));
  return m;
}

TEST(StagedInterface, FrictionCoefficientOfEachStageAtFullSliding) {
  const std::string coulomb = "coulomb_signorini\n    parameters: {friction_coefficient: 0.3}";
  const std::string stages =
      block_stage("press", 0, -1e-3) + block_stage("shear", 4e-3, -1e-3) +
      block_stage("shear_more", 8e-3, -1e-3,
                  "    interfaces: {joint: {parameters: {friction_coefficient: 0.5}}}\n");
  const Result r = run(block(stiff_block, coulomb, stages));
  ASSERT_EQ(r.resultant.size(), 9u);
  // The last increment of each shear stage slides: |F_t| = μ F_n (F_n > 0, compression).
  for (const auto& [step, mu] : {std::pair<int, double>{5, 0.3}, {8, 0.5}}) {
    const auto& f = r.resultant[step];
    ASSERT_GT(f[1], 0.0);
    EXPECT_NEAR(std::abs(f[0]) / f[1], mu, 1e-9) << "increment " << step + 1;
  }
}

TEST(StagedInterface, BondedStageOnSplitPairsEqualsSharedNodes) {
  const std::string press = block_stage("press", 1e-3, -1e-3);
  const std::string later = block_stage(
      "shear", 4e-3, -1e-3,
      "    interfaces: {joint: {law: coulomb_signorini, parameters: {friction_coefficient: "
      "0.3}}}\n");
  const Result split = run(block(stiff_block, "perfect_bonding", press + later));
  const Result shared = run(block(stiff_block, "perfect_bonding", press));
  ASSERT_EQ(split.u.size(), 6u);
  ASSERT_EQ(shared.u.size(), 3u);
  ASSERT_GT(split.u[0].size(), shared.u[0].size()); // split: body 2's interface nodes copied
  const std::size_t n = shared.u[0].size();         // the original nodes keep their ids
  for (std::size_t k = 0; k < 3; ++k) {
    std::vector<double> diff(n);
    for (std::size_t i = 0; i < n; ++i)
      diff[i] = split.u[k][i] - shared.u[k][i];
    EXPECT_LE(max_abs(diff, n), 1e-9 * max_abs(shared.u[k], n)) << "increment " << k + 1;
    EXPECT_NEAR(split.top_y[k], shared.top_y[k], 1e-9 * std::abs(shared.top_y[k]));
    // The tie's multipliers are the bonded interface's tractions (shared nodes: from body 1's
    // unbalanced forces).
    for (int c = 0; c < 2; ++c)
      EXPECT_NEAR(split.resultant[k][c], shared.resultant[k][c],
                  1e-9 * std::abs(shared.resultant[k][1]))
          << "increment " << k + 1 << ", component " << c;
  }
  // The shear stage then slides at μ = 0.3.
  EXPECT_NEAR(std::abs(split.resultant[5][0]) / split.resultant[5][1], 0.3, 1e-9);
}

TEST(StagedInterface, BondedInstallationThenRccmEqualsRccmThroughout) {
  // Homogeneous column (block = base material), free sides, one x support: uniaxial stress,
  // no jump under either law while compressed.
  const std::string same = "{type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.25}";
  const std::string rccm =
      "{normal_stiffness: 1.0e5, tangential_stiffness: 1.0e5, decohesion_energy: 1.0e-4, "
      "friction_coefficient: 0.4, adhesion_viscosity: 0.01, initial_adhesion: 0.8}";
  // The planned increments compared one by one: no energy halvings (on by default).
  const auto column = [](const std::string& name, double y, const std::string& extra) {
    return "  - name: " + name + "\n    increments: 4\n    energy_tolerance: 0\n" + extra +
           "    boundary_conditions:\n"
           "      - {set: bottom, component: y, value: 0}\n"
           "      - {set: left, component: x, value: 0}\n"
           "      - {set: top, component: y, value: " +
           std::to_string(y) + "}\n";
  };
  const std::string pull_change =
      "    interfaces: {joint: {law: rccm, parameters: " + rccm + "}}\n";
  const Result staged = run(block(
      same, "perfect_bonding", column("install", -1e-3, "") + column("pull", 4e-4, pull_change)));
  const Result rccm_only = run(block(same, "rccm\n    parameters: " + rccm,
                                     column("install", -1e-3, "") + column("pull", 4e-4, "")));
  ASSERT_EQ(staged.u.size(), 8u);
  ASSERT_EQ(rccm_only.u.size(), 8u);
  double scale = 0;
  for (double f : rccm_only.top_y)
    scale = std::max(scale, std::abs(f));
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_NEAR(staged.top_y[k], rccm_only.top_y[k], 1e-9 * scale) << "increment " << k + 1;
    const std::size_t n = staged.u[k].size();
    std::vector<double> diff(n);
    for (std::size_t i = 0; i < n; ++i)
      diff[i] = staged.u[k][i] - rccm_only.u[k][i];
    EXPECT_LE(max_abs(diff, n), 1e-9 * max_abs(rccm_only.u[k], n)) << "increment " << k + 1;
  }
  for (std::size_t k = 4; k < 8; ++k)
    EXPECT_NEAR(staged.min_beta[k], rccm_only.min_beta[k], 1e-9) << "increment " << k + 1;
  // Installed: β0 = 0.8 from the switch on (bonded pairs report β = 1); the pull debonds.
  EXPECT_EQ(staged.min_beta[3], 1.0);
  EXPECT_EQ(rccm_only.min_beta[3], 0.8);
  EXPECT_LT(rccm_only.min_beta[7], 0.8);
}

TEST(StagedInterface, StiffnessChangeIsBookedAndTheNewLawDrivesTheDissipation) {
  const double cn = 1e6, ct = 1e6, w = 1e-4; // block_on_rccm_joint's; doubled by `stiffer`
  const std::string text =
      test::block_on_rccm_joint(stiff_block, "{type: generalized_newton, tolerance: 1.0e-12}") +
      block_stage("press", 0, -2e-3, "", 2) + block_stage("shear", 2e-3, -2e-3, "", 4) +
      block_stage("stiffer", 2.5e-3, -2e-3,
                  "    energy_tolerance: 0\n"
                  "    interfaces: {joint: {parameters: {normal_stiffness: 2.0e6, "
                  "tangential_stiffness: 2.0e6, adhesion_viscosity: 1.0}}}\n",
                  2);
  // The first step of `stiffer` whole (no energy halvings, on by default): adhesion is lost
  // in it while the new stiffness acts.
  // α = 0.01 up to the switch, 1 after it: β still falls in the first step of `stiffer`.
  const Model model = bipot::test::model_from_text(text, "stiffer.yaml");
  StaticAnalysis analysis(model);
  std::vector<std::vector<PairResult>> pairs;
  std::vector<EnergyTotals> energy;
  std::vector<std::string> stage;
  analysis.run([&](const StepReport& r) {
    pairs.push_back(analysis.interfaces()[0]->results());
    energy.push_back(r.energy);
    stage.push_back(r.stage);
  });
  const std::size_t k = std::find(stage.begin(), stage.end(), "stiffer") - stage.begin();
  ASSERT_TRUE(k > 0 && k < stage.size());
  const auto& weights = model.interfaces[0].pairs;
  double springs = 0, viscous = 0, lost = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    const PairResult &before = pairs[k - 1][i], &after = pairs[k][i];
    const auto tangential = [](const PairResult& p) { return p.jump.tail(p.jump.size() - 1); };
    springs += 0.5 * weights[i].weight * before.beta * before.beta *
               (cn * before.jump(0) * before.jump(0) + ct * tangential(before).squaredNorm());
    const auto excess = [&](const PairResult& p) {
      const double gn = std::max(p.jump(0), 0.0);
      return std::max(p.beta * (2 * cn * gn * gn + 2 * ct * tangential(p).squaredNorm()) - w, 0.0);
    };
    viscous +=
        weights[i].weight * 0.5 * (excess(before) + excess(after)) * (before.beta - after.beta);
    lost += weights[i].weight * (before.beta - after.beta);
  }
  // Something to check: the springs held energy and adhesion was lost in that step.
  EXPECT_GT(springs, 1e-6);
  EXPECT_GT(lost, 1e-4);
  EXPECT_GT(viscous, 1e-9);
  std::printf("springs %.6e viscous %.6e lost %.6e; ledger %.6e %.6e\n", springs, viscous, lost,
              energy[k].interference_work - energy[k - 1].interference_work,
              energy[k].viscous_dissipation - energy[k - 1].viscous_dissipation);
  EXPECT_NEAR(energy[k].interference_work - energy[k - 1].interference_work, springs,
              1e-12 * springs);
  EXPECT_NEAR(energy[k].viscous_dissipation - energy[k - 1].viscous_dissipation, viscous,
              1e-10 * viscous);
}

} // namespace
} // namespace bipot
