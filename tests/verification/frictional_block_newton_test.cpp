// generalized_newton's line search on the stick → slip increments of the frictional block of
// bench/frictional_block.py (an elastic block on a rigid foundation, pressed, then sheared to
// full sliding; plane strain, Q1, Coulomb–Signorini node to node), on a 24 × 24 mesh.
//
// With a linear bulk and a 2D Coulomb law, the condensed Newton residual is piecewise affine:
// the undamped generalized Newton (`line_search: false`) moves from piece to piece and lands
// exactly once it has the right branches. The line search is there to damp steps that
// overshoot a kink; it must not slow this down. The Armijo test on ‖F‖ alone did: a full step
// that takes stuck pairs past the friction limit has a larger residual (their force outside
// the cone) although the next iterate, on the slip branch, removes it exactly; halved steps
// followed (here increment 9: 4 iterations against 2 undamped; 30k DOFs: 8 and 6 against 6
// and 4). The full step is now taken when only such pairs carry the excess
// (fem/analysis/interface_newton.cpp), so the damped iteration is the undamped one here.
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "tests/support/model_from_text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace bipot {
namespace {

std::string block_input(bool line_search) {
  const std::string n = "24", base = std::to_string(-1.0 / 24);
  auto stage = [](const std::string& name, const std::string& ux) {
    return "  - name: " + name + "\n    increments: " + (name == "compress" ? "5" : "10") +
           "\n    boundary_conditions:\n"
           "      - {set: foundation_all, component: x, value: 0}\n"
           "      - {set: foundation_all, component: y, value: 0}\n"
           "      - {set: top, component: x, value: " +
           ux +
           "}\n"
           "      - {set: top, component: y, value: -1.0e-3}\n";
  };
  return "kinematics: plane_strain\n"
         "mesh:\n  blocks:\n    cell: quad4\n"
         "    x: {breaks: [0.0, 1.0], cells: [" +
         n + "]}\n    y: {breaks: [" + base + ", 0.0, 1.0], cells: [1, " + n +
         "]}\n    regions: [foundation, block]\n"
         "  sets:\n    foundation_all: {min: [0.0, " +
         base +
         "], max: [1.0, 0.0], region: foundation}\n"
         "materials:\n"
         "  foundation: {type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.25}\n"
         "  block: {type: linear_elastic, youngs_modulus: 2.0e4, poissons_ratio: 0.25}\n"
         "linear_solver: {method: direct}\n"
         "interfaces:\n  - name: contact\n    between: [foundation, block]\n"
         "    law: coulomb_signorini\n    parameters: {friction_coefficient: 0.3}\n"
         "contact_solver: {type: generalized_newton, tolerance: 1.0e-10, line_search: " +
         (line_search ? "true" : "false") + "}\nstages:\n" + stage("compress", "0") +
         stage("shear", "4.0e-3");
}

struct BlockRun {
  std::vector<int> iterations; ///< Newton iterations per increment
  std::vector<double> u;       ///< final displacement
};

BlockRun run(bool line_search) {
  const Model model = test::model_from_text(block_input(line_search), "block.yaml");
  StaticAnalysis analysis(model); // holds a reference to the model
  BlockRun out;
  analysis.run([&](const StepReport& r) { out.iterations.push_back(r.iterations); });
  out.u = analysis.displacement();
  return out;
}

TEST(FrictionalBlockNewton, LineSearchKeepsTheUndampedIterationAcrossStickToSlip) {
  const BlockRun damped = run(true), undamped = run(false);
  ASSERT_EQ(damped.iterations.size(), 15u);
  ASSERT_EQ(undamped.iterations.size(), 15u);
  std::printf("[block 24x24] Newton iterations per increment, line search / undamped:\n");
  int total_damped = 0, total_undamped = 0;
  for (std::size_t k = 0; k < damped.iterations.size(); ++k) {
    std::printf("  %2zu: %d / %d\n", k + 1, damped.iterations[k], undamped.iterations[k]);
    EXPECT_LE(damped.iterations[k], undamped.iterations[k]) << "increment " << k + 1;
    total_damped += damped.iterations[k];
    total_undamped += undamped.iterations[k];
  }
  // The sliding steps are reached: the undamped iteration has work to do on them.
  EXPECT_GT(total_undamped, 6);
  EXPECT_LE(total_damped, total_undamped);
  // Both solve the same problem to the tolerance.
  double diff = 0, scale = 0;
  for (std::size_t i = 0; i < damped.u.size(); ++i) {
    diff = std::max(diff, std::abs(damped.u[i] - undamped.u[i]));
    scale = std::max(scale, std::abs(undamped.u[i]));
  }
  EXPECT_LT(diff, 1e-8 * scale);
}

// The shear stage's first increment starts with the edge pairs sliding outward, their forces
// exactly on the cone (to round-off) and Δg_t = 0: stick and slip are both elements of the
// generalized Jacobian, and the solution has one edge stuck (its friction reverses under the
// shear) and the other sliding on. With no predictor at a stage's start, the branch is taken
// from the direction in which the residual pushes each pair (InterfaceNewtonSystem::
// set_tie_hints); the first step then has the right branches and lands (the residual is
// piecewise affine). With round-off deciding (before) it took 2 here, and at 2k, 10k and 30k
// DOFs in bench/frictional_block.py (GetFEM 1, 2, 2 there).
TEST(FrictionalBlockNewton, StageStartOnTheConeTakesTheBranchOfTheComingStep) {
  const BlockRun damped = run(true);
  ASSERT_EQ(damped.iterations.size(), 15u);
  EXPECT_EQ(damped.iterations[5], 1);
}

} // namespace
} // namespace bipot
