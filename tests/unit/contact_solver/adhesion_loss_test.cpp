// The energy account's adhesion loss (contact/solver/adhesion_loss.hpp) on one RCCM pair
// driven along a given jump history, the law integrated as the solver does (backward Euler):
// the pair's balance, trapezoidal work of the adhesive traction − springs' energy − dissipation,
// must fall as h² (the trapezoid of the driving force; a backward-Euler end point leaves h),
// and the dissipation must converge to an independent fine-step integral of the continuous law.
#include "contact/laws/rccm.hpp"
#include "contact/solver/adhesion_loss.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace bipot::contact {
namespace {

// The shipped pile's interface (inputs/pile_pullout/rccm.yaml) with a tenfold viscosity, so
// that the steps below resolve the debonding time α/(β E) (the asymptotic range of h).
constexpr double kC = 4.0e4, kW = 0.16, kAlpha = 0.02, kT = 1.0;

/// Opening and slip growing with t: the pair debonds within [0, kT] (β E reaches w at
/// t ≈ 0.37 and β ends near 0.14).
LocalVector jump_at(double t) {
  LocalVector g(2);
  g << 0.002 * t, 0.005 * t;
  return g;
}

struct Account {
  double work = 0;     ///< trapezoidal work done on the springs, −½ (a_old + a_new)·Δg
  double stored = 0;   ///< ½ β² Ẽ at the end
  double adhesion = 0; ///< Σ adhesion_loss().adhesion
  double viscous = 0;  ///< Σ adhesion_loss().viscous
  double worst = 0;    ///< max over steps of |balance| / work
  double beta = 1;     ///< at the end
  double balance() const { return work - stored - adhesion - viscous; }
};

/// n equal steps of the law along jump_at(), accounted like interface_energy.cpp does.
Account drive(const Rccm& law, int n) {
  Account acc;
  LocalVector g_old = jump_at(0.0);
  LocalVector a_old = law.adhesive_traction(1.0, g_old);
  double beta_old = 1.0;
  const double dt = kT / n;
  for (int k = 1; k <= n; ++k) {
    const LocalVector g = jump_at(k * dt);
    const double beta = law.update_adhesion(beta_old, g, dt);
    const LocalVector a = law.adhesive_traction(beta, g);
    acc.work -= 0.5 * (a_old + a).dot(g - g_old);
    acc.stored = -0.5 * a.dot(g);
    const double drive_old = -a_old.dot(g_old) / beta_old, drive_new = -a.dot(g) / beta;
    const AdhesionLoss loss = adhesion_loss(kW, beta_old, drive_old, beta, drive_new);
    acc.adhesion += loss.adhesion;
    acc.viscous += loss.viscous;
    if (acc.work > 0) acc.worst = std::max(acc.worst, std::abs(acc.balance()) / acc.work);
    g_old = g;
    a_old = a;
    beta_old = beta;
  }
  acc.beta = beta_old;
  return acc;
}

/// The continuous law, α β̇ = −(β E − w)⁺, by classical RK4 on (β, dissipation, viscous
/// part): dD/dt = β Ẽ (−β̇), its viscous part (β Ẽ − w)(−β̇) = α β̇² (here Ẽ = E, g_n > 0).
struct Continuous {
  double beta, dissipation, viscous;
};
Continuous fine_reference(int n) {
  const auto rate = [](double t, double beta) {
    const LocalVector g = jump_at(t);
    const double e = kC * g.squaredNorm();
    const double bdot = -std::max(beta * e - kW, 0.0) / kAlpha;
    return std::array<double, 3>{bdot, -beta * e * bdot, kAlpha * bdot * bdot};
  };
  Continuous c{1.0, 0.0, 0.0};
  const double h = kT / n;
  for (int k = 0; k < n; ++k) {
    const double t = k * h;
    const auto k1 = rate(t, c.beta);
    const auto k2 = rate(t + h / 2, c.beta + h / 2 * k1[0]);
    const auto k3 = rate(t + h / 2, c.beta + h / 2 * k2[0]);
    const auto k4 = rate(t + h, c.beta + h * k3[0]);
    c.beta += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
    c.dissipation += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
    c.viscous += h / 6 * (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2]);
  }
  return c;
}

TEST(AdhesionLoss, ViscousPairBalanceFallsAsHSquared) {
  const Rccm law({kC, kC, kW, 0.0, kAlpha});
  const Account a1 = drive(law, 320), a2 = drive(law, 640), a3 = drive(law, 1280);
  ASSERT_LT(a3.beta, 0.5);                   // the pair did debond
  ASSERT_GT(a3.viscous, 0.05 * a3.adhesion); // and its viscosity did dissipate
  // Orders from the worst relative error over the history (the "at every step") and
  // from the end: 2 within 0.2 (an end-point rule gives about 1 for the worst).
  for (const auto& pair : {std::make_pair(a1, a2), std::make_pair(a2, a3)}) {
    const double order_worst = std::log2(pair.first.worst / pair.second.worst);
    const double order_end = std::log2(pair.first.balance() / pair.second.balance());
    EXPECT_NEAR(order_worst, 2.0, 0.2);
    EXPECT_NEAR(order_end, 2.0, 0.2);
  }
}

TEST(AdhesionLoss, ViscousDissipationConvergesToTheContinuousLaw) {
  const Rccm law({kC, kC, kW, 0.0, kAlpha});
  const Continuous ref = fine_reference(200000);
  // RK4's own error is far below the backward-Euler error checked against it.
  const Continuous half = fine_reference(100000);
  ASSERT_LT(std::abs(half.dissipation - ref.dissipation), 1e-8 * ref.dissipation);
  const Account a2 = drive(law, 640), a3 = drive(law, 1280);
  // The law's backward Euler is first order in β, so is every dissipation built on its
  // states: the errors halve with h (order 1 within 0.2), and are 1e-3 of D at 1280 steps.
  const double e2 = a2.adhesion + a2.viscous - ref.dissipation;
  const double e3 = a3.adhesion + a3.viscous - ref.dissipation;
  EXPECT_NEAR(std::log2(e2 / e3), 1.0, 0.2);
  EXPECT_LT(std::abs(e3), 1e-3 * ref.dissipation);
  EXPECT_NEAR(std::log2((a2.viscous - ref.viscous) / (a3.viscous - ref.viscous)), 1.0, 0.2);
  EXPECT_LT(std::abs(a3.viscous - ref.viscous), 1e-2 * ref.viscous);
  // Adhesion lost is w Δβ, exactly, whatever the quadrature.
  EXPECT_NEAR(a3.adhesion, kW * (1.0 - a3.beta), 1e-14);
}

TEST(AdhesionLoss, RateIndependentLawHasNoViscousTerm) {
  // α = 0: β E = w on the branch at both ends of every debonding step but the first, where
  // the force starts below w; (·)⁺ gives 0 there, so nothing is put in the viscous column,
  // and the adhesion lost is w (β0 − β). The balance is then the trapezoid's own error, h².
  const Rccm law({kC, kC, kW});
  const Account a1 = drive(law, 640), a2 = drive(law, 1280);
  EXPECT_LT(std::abs(a2.viscous), 1e-12 * a2.adhesion);
  EXPECT_NEAR(a2.adhesion, kW * (1.0 - a2.beta), 1e-14);
  EXPECT_NEAR(std::log2(a1.worst / a2.worst), 2.0, 0.2);
}

TEST(AdhesionLoss, NothingWhenBetaHoldsAndBelowThresholdEnds) {
  const AdhesionLoss none = adhesion_loss(0.16, 0.7, 1.0, 0.7, 2.0);
  EXPECT_EQ(none.adhesion, 0.0);
  EXPECT_EQ(none.viscous, 0.0);
  // Trapezoid of (β Ẽ − w)⁺: start below w (0), end 0.1 above: ½ · 0.1 · 0.2 = 0.01.
  const AdhesionLoss onset = adhesion_loss(0.16, 0.9, 0.1, 0.7, 0.26);
  EXPECT_NEAR(onset.adhesion, 0.16 * 0.2, 1e-15);
  EXPECT_NEAR(onset.viscous, 0.01, 1e-15);
}

} // namespace
} // namespace bipot::contact
