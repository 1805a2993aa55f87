// The shipped Gmsh example: uniform compression of a two-region mesh read from a .msh file
// gives the closed-form uniform strain at every node.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/input/problem_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bipot {
namespace {

TEST(GmshExample, UniformCompressionIsExact) {
  const double E = 2.0e4, nu = 0.25, p = 40.0;
  const Model model =
      build_model(read_problem_file(BIPOT_SOURCE_DIR "/inputs/examples/gmsh_two_regions.yaml",
                                    bipot::builtin_catalogue()),
                  bipot::builtin_catalogue());
  ASSERT_EQ(model.mesh.regions.size(), 2u);
  StaticAnalysis analysis(model);
  analysis.run();
  const auto& u = analysis.displacement();
  // Linear exact field: reproduced to the solver tolerance (GMRES+ILU to 1e-12).
  const double ex = p * nu * (1 + nu) / E, ey = -p * (1 - nu * nu) / E;
  for (Index n = 0; n < model.mesh.num_nodes(); ++n) {
    const auto& x = model.mesh.nodes[n];
    EXPECT_NEAR(u[analysis.dofs().dof(n, 0)], ex * x[0], 1e-9 * std::abs(ey));
    EXPECT_NEAR(u[analysis.dofs().dof(n, 1)], ey * x[1], 1e-9 * std::abs(ey));
  }
  // The bottom supports carry the applied load: p times the top length (1 m).
  EXPECT_NEAR(analysis.reaction("bottom")[1], p, 1e-8 * p);
}

} // namespace
} // namespace bipot
