// A debonding snap-back under displacement control, and the staggered fallback that gets
// through it. An elastic column (height L, modulus E, ν = 0) bonded to a rigid base by a
// quasi-static RCCM interface (α = 0) is pulled at its top by δ. With ν = 0 the problem is
// 1D: the interface stress t(g) and the column stress k(δ − g), k = E/L, are equal, with
//   t(g) = C g for g ≤ g* = √(w/C),  t(g) = w²/(C g³) beyond (β = w/(C g²)).
// The softening slope at g*, 3C, exceeds k a hundredfold here, so past the peak
// (δ* = g* + √(wC)/k) the equilibrium jumps to the far end of the softening branch. No
// load step is small enough for Newton to follow (no equilibrium near the last state):
// the analysis must find the equilibrium after the jump with its staggered fallback, flag
// the step, and go on.
#include "apps/catalogue/builtin_catalogue.hpp"
#include "fem/analysis/model.hpp"
#include "fem/analysis/static_analysis.hpp"
#include "fem/input/problem_reader.hpp"
#include "tests/support/bonded_column.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bipot {
namespace {

using namespace test::column;

// The equilibrium opening at δ on the pre-peak branch (δ ≤ δ*) or after the jump: the root
// of t(g) = k(δ − g) on the given bracket, by bisection to machine precision.
double opening(double delta, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (t_of(mid) - k * (delta - mid) > 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

class SnapBack : public ::testing::TestWithParam<const char*> {};

TEST_P(SnapBack, StaggeredFallbackFindsTheEquilibriumAfterTheJump) {
  const Model model =
      build_model(read_problem_text(input(GetParam()), "snap.yaml", bipot::builtin_catalogue()),
                  bipot::builtin_catalogue());
  StaticAnalysis analysis(model);
  int jumps = 0;
  double last_factor = 0;
  analysis.run([&](const StepReport& r) {
    const double delta = 0.12 * r.load_factor;
    const auto& ia = *analysis.interfaces()[0];
    // The base pulls the column down: the column's stress is minus the base's force on it.
    const double stress = -ia.resultant()[1] / width;
    const double g = ia.results()[0].jump(0);
    // Before the peak the opening is on the elastic branch; after it, past the jump.
    const bool before = delta <= delta_star;
    const double g_exact = before ? opening(delta, 0.0, g_star) : opening(delta, g_star, delta);
    // Converged to 1e-10 relative: 1e-8 of the scales (g*, the peak stress) is ample.
    EXPECT_NEAR(g, g_exact, 1e-8 * std::max(g_exact, g_star)) << "delta " << delta;
    EXPECT_NEAR(stress, t_of(g_exact), 1e-8 * std::sqrt(w * C)) << "delta " << delta;
    if (r.staggered > 0) {
      ++jumps;
      EXPECT_TRUE(r.unstable); // the jump is flagged in the output
      EXPECT_GT(delta, delta_star);
    }
    last_factor = r.load_factor;
  });
  EXPECT_EQ(last_factor, 1.0); // the run went on to the end
  EXPECT_GE(jumps, 1);         // the monolithic iteration alone could not cross the jump
}

INSTANTIATE_TEST_SUITE_P(BothSolvers, SnapBack,
                         ::testing::Values("semismooth_newton", "bipotential_uzawa"));

} // namespace
} // namespace bipot
