// RCCM debonding under displacement control: an elastic column bonded to an elastic base by
// an RCCM interface is pulled off. With nu = 0 the stress is uniaxial and uniform, so the
// opening g is the same at every pair and the problem is 1D:
//   sigma = t_n(g) = C beta^2 g,  beta = min(1, w / (C g^2))  (quasi-static, beta0 = 1),
//   delta = g + sigma (L_column / E_column + L_base / E_base).
// Both contact solvers must reproduce the law, equilibrium and beta at every increment,
// and agree with each other.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/input/problem_reader.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bipot {
namespace {

// Stiff bodies: with compliance c = L/E summed, the softening branch is stable under
// displacement control when c < 1/(3 C) (no snap-back); here c 3C = 0.375.
constexpr double C = 1.0e5, w = 0.02, E_col = 1.0e6, E_base = 2.0e6, L_col = 1.0, L_base = 0.5,
                 width = 1.0;

std::string pull_input(const std::string& solver) {
  return "kinematics: plane_strain\n"
         "mesh:\n  blocks:\n    cell: quad4\n"
         "    x: {breaks: [0, 1.0], cells: [3]}\n"
         "    y: {breaks: [-0.5, 0, 1.0], cells: [2, 3]}\n"
         "    regions: [base, column]\n"
         "materials:\n"
         "  base: {type: linear_elastic, youngs_modulus: 2.0e6, poissons_ratio: 0.0}\n"
         "  column: {type: linear_elastic, youngs_modulus: 1.0e6, poissons_ratio: 0.0}\n"
         "linear_solver: {method: direct}\n"
         "interfaces:\n  - name: bond\n    between: [base, column]\n    law: rccm\n"
         "    parameters: {normal_stiffness: 1.0e5, tangential_stiffness: 1.0e5, "
         "decohesion_energy: 0.02, friction_coefficient: 0.5}\n"
         "contact_solver: {type: " +
         solver +
         ", tolerance: 1.0e-12}\n"
         "stages:\n  - name: pull\n    increments: 12\n    boundary_conditions:\n"
         "      - {set: bottom, component: x, value: 0}\n"
         "      - {set: bottom, component: y, value: 0}\n"
         "      - {set: top, component: x, value: 0}\n"
         "      - {set: top, component: y, value: 3.0e-3}\n";
}

struct PullHistory {
  std::vector<double> delta, sigma, g, beta;
  std::vector<double> u;
};

PullHistory pull(const std::string& solver) {
  const Model model =
      build_model(read_problem_text(pull_input(solver), "pull.yaml", bipot::builtin_catalogue()),
                  bipot::builtin_catalogue());
  StaticAnalysis analysis(model);
  PullHistory h;
  analysis.run([&](const StepReport& r) {
    const auto& ia = *analysis.interfaces()[0];
    h.delta.push_back(3.0e-3 * r.load_factor);
    h.sigma.push_back(ia.resultant()[1] / width); // force on the column, per width
    h.g.push_back(ia.results()[0].jump(0));
    h.beta.push_back(ia.results()[0].beta);
    for (const auto& p : ia.results()) { // uniform opening and adhesion
      EXPECT_NEAR(p.jump(0), h.g.back(), 1e-9 * std::abs(h.g.back()) + 1e-15);
      EXPECT_NEAR(p.beta, h.beta.back(), 1e-9);
    }
  });
  h.u = analysis.displacement();
  return h;
}

class RccmPull : public testing::TestWithParam<std::string> {};

TEST_P(RccmPull, FollowsTheClosedForm) {
  const PullHistory h = pull(GetParam());
  ASSERT_EQ(h.delta.size(), 12u);
  const double g_star = std::sqrt(w / C); // 4.47e-4 m: end of the elastic branch
  int softening = 0;
  for (std::size_t k = 0; k < h.delta.size(); ++k) {
    const double g = h.g[k];
    const double beta = std::min(1.0, w / (C * g * g));
    // The opening pulls the column back: the force on it is -t_n = C beta^2 g (downwards).
    const double sigma_law = -C * beta * beta * g;
    // Tolerances: the solvers stop at 1e-12 relative; 1e-8 leaves room for the conditioning.
    EXPECT_NEAR(h.beta[k], beta, 1e-8) << "increment " << k;
    EXPECT_NEAR(h.sigma[k], sigma_law, 1e-8 * std::sqrt(w * C)) << "increment " << k;
    const double stretch = -h.sigma[k] * (L_col / E_col + L_base / E_base);
    EXPECT_NEAR(h.delta[k], g + stretch, 1e-8 * h.delta.back()) << "increment " << k;
    softening += g > g_star;
  }
  // The pull reaches the softening branch and the peak is bounded by sqrt(w C).
  EXPECT_GT(softening, 3);
  for (double s : h.sigma)
    EXPECT_LE(std::abs(s), std::sqrt(w * C) * (1 + 1e-12));
}

INSTANTIATE_TEST_SUITE_P(Solvers, RccmPull,
                         testing::Values("semismooth_newton", "bipotential_uzawa"));

TEST(RccmPull, SolversAgree) {
  const PullHistory a = pull("semismooth_newton"), b = pull("bipotential_uzawa");
  double d = 0, n = 0;
  for (std::size_t i = 0; i < a.u.size(); ++i) {
    d += (a.u[i] - b.u[i]) * (a.u[i] - b.u[i]);
    n += b.u[i] * b.u[i];
  }
  EXPECT_LT(std::sqrt(d / n), 1e-8);
}

} // namespace
} // namespace bipot
