// Rccm::spring_work, the springs' work −∫ a·dg along a straight step of the jump, against an
// independent integration of the law's own functions (update_adhesion, adhesive_traction):
// 200000 midpoint sub-steps, β updated at every one. The closed form holds across the onset of
// softening, on the branch, unloading, where Ẽ dips on the way (slip reversal) and leaving
// penetration; and it closes each step's balance: W = ΔΨ + w (β_old − β_new).
#include "contact/laws/rccm.hpp"
#include "local_test_utils.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

namespace bipot::contact {
namespace {

using test::vec;

constexpr double kCn = 1e6, kCt = 4e5, kW = 0.05; // Ẽ* = w at β = 1: g_n* = 0.22, g_t* = 0.35 mm

Rccm law(double viscosity = 0.0) {
  return Rccm(Rccm::Parameters{kCn, kCt, kW, 0.3, viscosity, 1.0});
}

double midpoint_work(const Rccm& rccm, double beta_old, const LocalVector& from,
                     const LocalVector& to, int n = 200000) {
  const LocalVector step = (to - from) / n;
  double beta = beta_old, work = 0;
  for (int k = 0; k < n; ++k) {
    const LocalVector mid = from + (k + 0.5) * step;
    const double beta_mid = rccm.update_adhesion(beta, mid, 0.0);
    work -= rccm.adhesive_traction(beta_mid, mid).dot(step);
    beta = rccm.update_adhesion(beta, from + (k + 1.0) * step, 0.0);
  }
  return work;
}

double stored(const Rccm& rccm, double beta, const LocalVector& g) {
  return -0.5 * rccm.adhesive_traction(beta, g).dot(g);
}

struct Step {
  const char* what;
  double beta_old; // < 0: on the branch, w/Ẽ(from)
  LocalVector from, to;
};

TEST(RccmSpringWork, MatchesTheIntegratedPathAndClosesTheBalance) {
  const Rccm rccm = law();
  const auto on_branch = [](const LocalVector& g) {
    const double gn = std::max(g(0), 0.0);
    return kW / (kCn * gn * gn + kCt * g.tail(g.size() - 1).squaredNorm());
  };
  const Step steps[] = {
      {"below the threshold", 1.0, vec({0.0, 0.0}), vec({1e-4, 1e-4})},
      {"across the onset", 1.0, vec({1e-4, 0.5e-4}), vec({6e-4, 4e-4})},
      {"on the branch, 3D", -1, vec({3e-4, 1e-4, -2e-4}), vec({5e-4, 2e-4, -3e-4})},
      {"unloading from the branch", -1, vec({3e-4, 1e-4}), vec({1e-4, 0.5e-4})},
      {"slip reversal (Ẽ dips)", 1.0, vec({1e-4, 3e-4}), vec({1e-4, -6e-4})},
      {"leaving penetration", 1.0, vec({-2e-5, 1e-4}), vec({4e-4, 5e-4})},
  };
  for (const Step& s : steps) {
    const double beta_old = s.beta_old < 0 ? on_branch(s.from) : s.beta_old;
    const std::optional<double> exact = rccm.spring_work(beta_old, s.from, s.to);
    ASSERT_TRUE(exact.has_value()) << s.what;
    const double integrated = midpoint_work(rccm, beta_old, s.from, s.to);
    const double beta_new = rccm.update_adhesion(beta_old, s.to, 0.0);
    const double balance =
        stored(rccm, beta_new, s.to) - stored(rccm, beta_old, s.from) + kW * (beta_old - beta_new);
    std::printf("%-26s β %.4f → %.4f: closed form %.12e, integrated %.12e kJ/m²\n", s.what,
                beta_old, beta_new, *exact, integrated);
    // The midpoint sums' error across the kink is O(n⁻²) of the step's work scale.
    const double scale = std::abs(*exact) + kW * (beta_old - beta_new);
    EXPECT_NEAR(*exact, integrated, 1e-8 * scale) << s.what;
    // No other quadrature closes it: the trapezoid's error across the onset is of the order
    // of the step's work.
    EXPECT_NEAR(*exact, balance, 1e-13 * scale) << s.what;
  }
}

TEST(RccmSpringWork, ViscousOrOffTheBranchIsLeftToTheQuadrature) {
  // β then depends on the time Ẽ took to rise; from above the threshold (not a state the
  // rate-independent law reaches) the path is not the law's.
  EXPECT_FALSE(law(1e-3).spring_work(1.0, vec({1e-4, 0.0}), vec({6e-4, 0.0})).has_value());
  EXPECT_FALSE(law().spring_work(1.0, vec({6e-4, 0.0}), vec({7e-4, 0.0})).has_value());
  // The trapezoid is what a law without the closed form leaves: across the onset it is off by
  // a large fraction of the step's work.
  const Rccm rccm = law();
  const LocalVector from = vec({1e-4, 0.0}), to = vec({6e-4, 0.0});
  const double beta_new = rccm.update_adhesion(1.0, to, 0.0);
  const double trapezoid =
      -0.5 *
      (rccm.adhesive_traction(1.0, from) + rccm.adhesive_traction(beta_new, to)).dot(to - from);
  EXPECT_GT(std::abs(trapezoid - *rccm.spring_work(1.0, from, to)),
            0.1 * *rccm.spring_work(1.0, from, to));
}

} // namespace
} // namespace bipot::contact
