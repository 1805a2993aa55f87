// Uniaxial bar in 3D (Tet4 and Hex8) through the whole YAML path: rollers on three faces,
// a uniform traction on the far end. The exact solution is linear, so the discrete one
// equals it to round-off; the support reaction balances the applied force.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/input/problem_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bipot {
namespace {

class Bar3d : public testing::TestWithParam<std::string> {};

TEST_P(Bar3d, UniaxialStressIsExact) {
  const double E = 3.0e6, nu = 0.3, sigma = 250.0, L = 2.0, W = 0.5, H = 0.4;
  const std::string text =
      "kinematics: three_d\n"
      "mesh:\n  blocks:\n    cell: " +
      GetParam() +
      "\n"
      "    x: {breaks: [0, 2.0], cells: [6], grading: [1.2]}\n"
      "    y: {breaks: [0, 0.5], cells: [2]}\n"
      "    z: {breaks: [0, 0.4], cells: [2]}\n"
      "    regions: [bar]\n"
      "materials:\n  bar: {type: linear_elastic, youngs_modulus: 3.0e6, poissons_ratio: 0.3}\n"
      "linear_solver: {method: cg, preconditioner: muelu, tolerance: 1.0e-13}\n"
      "stages:\n  - name: pull\n    increments: 2\n    boundary_conditions:\n"
      "      - {set: left, component: x, value: 0}\n"
      "      - {set: bottom, component: y, value: 0}\n"
      "      - {set: back, component: z, value: 0}\n"
      "    loads:\n      - {type: traction, set: right, value: [250.0, 0, 0]}\n";
  const Model model = build_model(read_problem_text(text, "bar.yaml", bipot::builtin_catalogue()),
                                  bipot::builtin_catalogue());
  StaticAnalysis analysis(model);
  analysis.run();
  const auto& u = analysis.displacement();
  double max_err = 0;
  for (Index n = 0; n < model.mesh.num_nodes(); ++n) {
    const auto& x = model.mesh.nodes[n];
    const double exact[3] = {sigma * x[0] / E, -nu * sigma * x[1] / E, -nu * sigma * x[2] / E};
    for (int i = 0; i < 3; ++i)
      max_err = std::max(max_err, std::abs(u[analysis.dofs().dof(n, i)] - exact[i]));
  }
  // CG to 1e-13 on a well-conditioned bar: 1e-10 relative to the tip displacement.
  EXPECT_LT(max_err, 1e-10 * sigma * L / E);
  const auto reaction = analysis.reaction("left");
  EXPECT_NEAR(reaction[0], -sigma * W * H, 1e-8 * sigma * W * H);
}

INSTANTIATE_TEST_SUITE_P(Cells, Bar3d, testing::Values("hex8", "tet4"));

} // namespace
} // namespace bipot
