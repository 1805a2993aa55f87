// Plastic models on 1 and 2 MPI ranks give the same displacements to 1e-10 relative (the
// 1-rank run, a CTest fixture set-up, writes its solutions; the 2-rank run compares), with
// the plain Newton and with generalized_newton; and a plastic material that never yields
// gives the linear_elastic solution to 1e-12 (von_mises and mohr_coulomb).
#include "apps/catalogue/builtin_catalogue.hpp"
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/input/problem_reader.hpp"
#include "fem/linalg/communicator.hpp"

#include "tests/support/serial_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace bipot {
namespace {

// Plane strain soil in two layers under a rough rigid footing (x ≤ 0.5, symmetry at x = 0),
// pushed down `settlement` in 4 increments.
std::string footing(const std::string& material, const std::string& interface, double settlement) {
  return "kinematics: plane_strain\nmesh:\n  blocks:\n    cell: tri6\n"
         "    x: {breaks: [0.0, 0.5, 2.0], cells: [4, 6]}\n"
         "    y: {breaks: [0.0, 0.5, 1.0], cells: [3, 4]}\n"
         "    regions: [lower, lower, upper, upper]\n"
         "  sets:\n    footing: {min: [0.0, 1.0], max: [0.5, 1.0]}\n"
         "materials:\n  lower: " +
         material + "\n  upper: " + material + "\nlinear_solver: {method: direct}\n" + interface +
         "stages:\n  - name: load\n    increments: 4\n    boundary_conditions:\n"
         "      - {set: bottom, component: x, value: 0}\n"
         "      - {set: bottom, component: y, value: 0}\n"
         "      - {set: left, component: x, value: 0}\n"
         "      - {set: right, component: x, value: 0}\n"
         "      - {set: footing, component: x, value: 0}\n"
         "      - {set: footing, component: y, value: " +
         std::to_string(-settlement) + "}\n";
}

const std::string plastic =
    "{type: von_mises, youngs_modulus: 1.0e4, poissons_ratio: 0.3, yield_stress: 20.0, "
    "hardening_modulus: 100.0}";
const std::string joint =
    "interfaces:\n  - name: joint\n    between: [lower, upper]\n    law: coulomb_signorini\n"
    "    parameters: {friction_coefficient: 0.5}\n"
    "contact_solver: {type: generalized_newton, tolerance: 1.0e-12}\n";

std::vector<double> solve(const std::string& text) {
  const Model model =
      build_model(read_problem_text(text, "footing.yaml", bipot::builtin_catalogue()),
                  bipot::builtin_catalogue());
  StaticAnalysis analysis(model);
  analysis.run();
  return analysis.displacement();
}

void compare_or_write(const std::string& name, const std::vector<double>& u) {
  const auto ref = test::serial_reference("plastic_parallel_" + name + ".txt", u);
  if (mpi_size() == 1) return;
  ASSERT_EQ(ref.size(), u.size());
  const double d = test::relative_difference(u, ref);
  std::printf("%s: 1 and 2 ranks differ by %.3e\n", name.c_str(), d);
  EXPECT_LT(d, 1e-10);
}

TEST(PlasticParallel, Newton) {
  compare_or_write("newton", solve(footing(plastic, "", 0.02)));
}

TEST(PlasticParallel, GeneralizedNewton) {
  compare_or_write("generalized_newton", solve(footing(plastic, joint, 0.02)));
}

TEST(PlasticParallel, MohrCoulombNewton) {
  compare_or_write("mohr_coulomb",
                   solve(footing("{type: mohr_coulomb, youngs_modulus: 1.0e4, poissons_ratio: "
                                 "0.3, cohesion: 10.0, friction_angle: 30.0, dilatancy_angle: "
                                 "10.0}",
                                 "", 0.02)));
}

// A strength far above any stress of the problem: the elastic branch everywhere, and the
// solution of linear_elastic (assembled once, one solve per increment) to 1e-12.
TEST(PlasticParallel, NeverYieldingEqualsLinearElastic) {
  const std::string elastic = "{type: linear_elastic, youngs_modulus: 1.0e4, poissons_ratio: 0.3}";
  const auto ref = solve(footing(elastic, "", 0.02));
  for (const std::string strong :
       {"{type: von_mises, youngs_modulus: 1.0e4, poissons_ratio: 0.3, yield_stress: 1.0e12}",
        "{type: mohr_coulomb, youngs_modulus: 1.0e4, poissons_ratio: 0.3, cohesion: 1.0e12, "
        "friction_angle: 30.0, dilatancy_angle: 10.0}"}) {
    const double d = test::relative_difference(solve(footing(strong, "", 0.02)), ref);
    std::printf("%s against linear_elastic: %.3e\n", strong.c_str(), d);
    EXPECT_LT(d, 1e-12) << strong;
  }
}

} // namespace
} // namespace bipot
