// Tractions of a perfect-bonding interface (shared nodes, no jump), recovered for output from
// body 1's cells: a weightless column (ν = 0) bonded to a heavy base and pulled at its top
// carries a uniform stress σ, so every pair must report the traction the base exerts on the
// column, t_n = −σ (tension), t_t = 0, and the resultant −σ × width. The base's weight at the
// interface nodes (γ = 200 kN/m³ over 0.5 m: 100 kPa, of the order of σ) is what body 1's
// internal force holds besides the interface force; forgetting to remove it fails the test.
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/input/problem_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bipot {
namespace {

const char* kInput = R"(kinematics: plane_strain
mesh:
  blocks:
    cell: quad4
    x: {breaks: [0, 0.4], cells: [4]}
    y: {breaks: [-0.5, 0, 1.0], cells: [3, 4]}
    regions: [base, column]
materials:
  base: {type: linear_elastic, youngs_modulus: 2.0e5, poissons_ratio: 0.0, unit_weight: 200}
  column: {type: linear_elastic, youngs_modulus: 1.0e5, poissons_ratio: 0.0}
linear_solver: {method: direct}
interfaces:
  - {name: glue, between: [base, column], law: perfect_bonding}
stages:
  - name: pull
    increments: 2
    boundary_conditions:
      - {set: bottom, component: x, value: 0}
      - {set: bottom, component: y, value: 0}
      - {set: top, component: x, value: 0}
      - {set: top, component: y, value: 1.0e-3}
    loads:
      - {type: gravity}
)";

TEST(TiedInterface, TractionsEqualTheColumnStress) {
  const Model model = build_model(read_problem_text(kInput, "tied.yaml"));
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
    ASSERT_TRUE(ia.tied());
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

} // namespace
} // namespace bipot
