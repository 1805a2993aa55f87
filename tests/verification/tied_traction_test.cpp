// Tractions of a perfect-bonding interface (shared nodes, no jump), recovered for output from
// body 1's cells: a weightless column (ν = 0) bonded to a heavy base and pulled at its top
// carries a uniform stress σ, so every pair must report the traction the base exerts on the
// column, t_n = −σ (tension), t_t = 0, and the resultant −σ × width. The base's weight at the
// interface nodes (γ = 200 kN/m³ over 0.5 m: 100 kPa, of the order of σ) is what body 1's
// internal force holds besides the interface force; forgetting to remove it fails the test.
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/input/problem_reader.hpp"
#include "tests/support/model_from_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace bipot {
namespace {

// The rest of both inputs after mesh and materials: a direct solver, the bonded interface
// `glue` between `bodies` and a stage `pull` of 2 increments with `stage` (its conditions).
std::string bonded_pull(const std::string& bodies, const std::string& stage) {
  return "linear_solver: {method: direct}\n"
         "interfaces:\n"
         "  - {name: glue, between: [" +
         bodies +
         "], law: perfect_bonding}\n"
         "stages:\n"
         "  - name: pull\n"
         "    increments: 2\n" +
         stage;
}

const std::string kInput = std::string(R"(kinematics: plane_strain
mesh:
  blocks:
    cell: quad4
    x: {breaks: [0, 0.4], cells: [4]}
    y: {breaks: [-0.5, 0, 1.0], cells: [3, 4]}
    regions: [base, column]
materials:
  base: {type: linear_elastic, youngs_modulus: 2.0e5, poissons_ratio: 0.0, unit_weight: 200}
  column: {type: linear_elastic, youngs_modulus: 1.0e5, poissons_ratio: 0.0}
)") + bonded_pull("base, column", R"(    boundary_conditions:
      - {set: bottom, component: x, value: 0}
      - {set: bottom, component: y, value: 0}
      - {set: top, component: x, value: 0}
      - {set: top, component: y, value: 1.0e-3}
    loads:
      - {type: gravity}
)");

TEST(TiedInterface, TractionsEqualTheColumnStress) {
  const Model model = bipot::test::model_from_text(kInput, "tied.yaml");
  StaticAnalysis analysis(model);
  int checked = 0;
  analysis.run([&](const StepReport&) {
    // The column's stress from its strain: σ = E (u_top − u_interface) / L, uniform.
    const auto& u = analysis.displacement();
    const auto& pairs = model.interfaces[0].pairs;
    const auto& top = model.mesh.node_sets.at("top");
    const double u_top = u[analysis.dofs().dof(top[0], 1)];
    const double u_if = u[analysis.dofs().dof(pairs[0].node_a, 1)];
    const double sigma = 1.0e5 * (u_top - u_if) / 1.0;
    const auto& ia = *analysis.interfaces()[0];
    ASSERT_FALSE(ia.acts_on_system()); // tied by shared nodes: exact
    for (const auto& r : ia.results()) {
      // Direct solve, so the equilibrium is exact to rounding: 1e-9 of σ.
      EXPECT_NEAR(r.traction(0), -sigma, 1e-9 * sigma);
      EXPECT_NEAR(r.traction(1), 0.0, 1e-9 * sigma);
    }
    EXPECT_NEAR(ia.resultant()[1], -sigma * 0.4, 1e-9 * sigma);
    ++checked;
  });
  EXPECT_EQ(checked, 2);
}

// A weightless pile (0.2 m wide, 1 m long, plane strain) bonded to the soil along its shaft
// and toe, pulled up at its head, as in the pile app. The head's corner node is shared with
// the soil and carries the prescribed displacement, so its force from the pile's cells also
// holds the support's reaction: the interface takes it as acting on body 1 (the pile) and
// reports the rest. Then the pile's equilibrium is exact: the resultant the pile exerts on
// the soil equals the head reaction, every pair finite. Reporting the supported pair as NaN
// (or leaving it out) fails.
const std::string kPile = std::string(R"(kinematics: plane_strain
mesh:
  blocks:
    cell: quad4
    x: {breaks: [0, 0.2, 1.0], cells: [2, 4]}
    y: {breaks: [-1.5, -1.0, 0], cells: [2, 5]}
    regions: [soil, soil, pile, soil]
  sets:
    head: {min: [0, 0], max: [0.2, 0], region: pile}
materials:
  pile: {type: linear_elastic, youngs_modulus: 3.0e6, poissons_ratio: 0.3}
  soil: {type: linear_elastic, youngs_modulus: 3.0e4, poissons_ratio: 0.33}
)") + bonded_pull("pile, soil", R"(    boundary_conditions:
      - {set: left, component: x, value: 0}
      - {set: right, component: x, value: 0}
      - {set: bottom, component: x, value: 0}
      - {set: bottom, component: y, value: 0}
      - {set: head, component: y, value: 1.0e-3}
)");

TEST(TiedInterface, SupportedSharedNodeKeepsThePileInEquilibrium) {
  const Model model = bipot::test::model_from_text(kPile, "pile.yaml");
  StaticAnalysis analysis(model);
  int checked = 0;
  analysis.run([&](const StepReport&) {
    const double head = analysis.reaction("head")[1];
    ASSERT_GT(head, 0.0);
    const auto& ia = *analysis.interfaces()[0];
    for (const auto& r : ia.results())
      for (int c = 0; c < 2; ++c)
        EXPECT_TRUE(std::isfinite(r.traction(c)));
    // Direct solve: the pile's equilibrium holds to rounding, 1e-9 of the head force.
    EXPECT_NEAR(ia.resultant()[1], head, 1e-9 * head);
    ++checked;
  });
  EXPECT_EQ(checked, 2);
}

} // namespace
} // namespace bipot
