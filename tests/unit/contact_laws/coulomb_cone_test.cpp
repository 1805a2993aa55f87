// Coulomb-cone projection and bipotential predictor (docs/formulation.md §4): closed forms on every
// branch, the variational characterisation of a projection, and Jacobians vs finite differences.
#include "contact/laws/coulomb_cone.hpp"
#include "local_test_utils.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace bipot::contact {
namespace {

using test::fd_derivative;
using test::fd_jacobian;
using test::relative_error;
using test::vec;

// Hand-computed results are O(1) numbers formed by a few roundings: 1e-14 is ~50 ulps.
constexpr double kClosedFormTol = 1e-14;

void expect_vec_near(const LocalVector& a, const LocalVector& b, double tol) {
  ASSERT_EQ(a.size(), b.size());
  for (Eigen::Index i = 0; i < a.size(); ++i)
    EXPECT_NEAR(a(i), b(i), tol) << "component " << i;
}

TEST(ProjectOntoCone, StickReturnsTau2D3D) {
  for (const LocalVector& tau : {vec({2.0, 0.6}), vec({3.0, 0.3, 0.4}), vec({2.0, -1.0})}) {
    const auto p = project_onto_cone(tau, 0.5); // ‖τ_t‖ ≤ 0.5 τ_n in all three (boundary last)
    EXPECT_EQ(p.status, ContactStatus::Stick);
    expect_vec_near(p.r, tau, kClosedFormTol);
  }
}

TEST(ProjectOntoCone, SeparationReturnsZero2D3D) {
  for (const LocalVector& tau : {vec({-1.0, 0.5}), vec({-2.0, 1.2, 1.6}), vec({-1.0, 2.0})}) {
    const auto p = project_onto_cone(tau, 0.5); // 0.5 ‖τ_t‖ ≤ −τ_n (equality last)
    EXPECT_EQ(p.status, ContactStatus::Open);
    expect_vec_near(p.r, LocalVector::Zero(tau.size()), 0.0);
  }
}

TEST(ProjectOntoCone, SlipClosedForm2D3D) {
  // μ̄ = 0.5, 1 + μ̄² = 1.25.
  // τ = (1, 2): r_n = (1 + 1)/1.25 = 1.6, r_t = 0.5·1.6 = 0.8.
  // τ = (−0.5, 3): r_n = (−0.5 + 1.5)/1.25 = 0.8, r_t = 0.4 (slip with τ_n < 0).
  // τ = (1, 1.2, −1.6): ‖τ_t‖ = 2, e = (0.6, −0.8), r_n = 1.6, r_t = 0.8 e = (0.48, −0.64).
  struct Case {
    LocalVector tau, r;
  };
  const std::vector<Case> cases = {{vec({1.0, 2.0}), vec({1.6, 0.8})},
                                   {vec({-0.5, 3.0}), vec({0.8, 0.4})},
                                   {vec({1.0, 1.2, -1.6}), vec({1.6, 0.48, -0.64})}};
  for (const auto& c : cases) {
    const auto p = project_onto_cone(c.tau, 0.5);
    EXPECT_EQ(p.status, ContactStatus::Slip);
    expect_vec_near(p.r, c.r, kClosedFormTol);
  }
}

TEST(ProjectOntoCone, FrictionlessIsSignorini) {
  // μ̄ = 0: r = (max(τ_n, 0), 0). No rounding happens on this branch (1/(1+0) = 1, r_t = 0·…),
  // so the comparison is exact.
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int d = 2; d <= 3; ++d) {
    for (int k = 0; k < 50; ++k) {
      LocalVector tau(d);
      for (int i = 0; i < d; ++i)
        tau(i) = u(gen);
      const auto p = project_onto_cone(tau, 0.0);
      EXPECT_EQ(p.r(0), std::max(tau(0), 0.0));
      for (int i = 1; i < d; ++i)
        EXPECT_EQ(p.r(i), 0.0);
      EXPECT_EQ(p.status, tau(0) > 0.0 ? ContactStatus::Slip : ContactStatus::Open);
    }
  }
}

TEST(ProjectOntoCone, ZeroTangentialPartHasNoDivisionByZero) {
  for (double mu : {0.0, 0.5}) {
    for (int d = 2; d <= 3; ++d) {
      LocalVector tau = LocalVector::Zero(d);
      tau(0) = 1.5;
      auto p = project_onto_cone(tau, mu);
      EXPECT_EQ(p.status, ContactStatus::Stick);
      EXPECT_TRUE(p.r.allFinite() && p.dr_dtau.allFinite() && p.dr_dmu.allFinite());
      expect_vec_near(p.r, tau, 0.0);
      tau(0) = -1.5;
      p = project_onto_cone(tau, mu);
      EXPECT_EQ(p.status, ContactStatus::Open);
      expect_vec_near(p.r, LocalVector::Zero(d), 0.0);
      tau(0) = 0.0; // apex
      p = project_onto_cone(tau, mu);
      EXPECT_TRUE(p.r.allFinite() && p.dr_dtau.allFinite() && p.dr_dmu.allFinite());
      expect_vec_near(p.r, LocalVector::Zero(d), 0.0);
    }
  }
  // Tiny components whose squares underflow (‖τ_t‖ may evaluate to 0 or a denormal): the
  // result stays finite whatever branch rounding selects.
  for (const LocalVector& tau : {vec({1e-320, 1e-315}), vec({1e-300, 1e-170}),
                                 vec({-1e-320, 1e-200, 1e-310}), vec({1e-170, 1e-160, 0.0})}) {
    const auto p = project_onto_cone(tau, 1e-3);
    EXPECT_TRUE(p.r.allFinite() && p.dr_dtau.allFinite() && p.dr_dmu.allFinite()) << tau;
  }
}

// Random τ and cone points s for the characterisation tests.
struct Samples {
  std::vector<LocalVector> tau, cone_points;
};

Samples make_samples(int d, double mu, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Samples s;
  for (int k = 0; k < 200; ++k) {
    LocalVector tau(d);
    for (int i = 0; i < d; ++i)
      tau(i) = 3.0 * u(gen);
    s.tau.push_back(tau);
    // s_n ≥ 0, ‖s_t‖ ≤ μ̄ s_n: a random tangential direction scaled into the cone.
    LocalVector c(d);
    c(0) = 2.0 * (u(gen) + 1.0);
    LocalVector dir(d - 1);
    for (int i = 0; i < d - 1; ++i)
      dir(i) = u(gen);
    const double frac = 0.5 * (u(gen) + 1.0);
    c.tail(d - 1) = dir.norm() > 0 ? LocalVector(dir / dir.norm() * frac * mu * c(0))
                                   : LocalVector(LocalVector::Zero(d - 1));
    s.cone_points.push_back(c);
  }
  return s;
}

TEST(ProjectOntoCone, ProjectionCharacterisation) {
  // Rounding of O(1) values through a handful of operations: 1e-13 absolute (τ, r ≤ ~5).
  const double tol = 1e-13;
  for (int d = 2; d <= 3; ++d) {
    for (double mu : {0.0, 0.3, 1.0, 2.5}) {
      const Samples s = make_samples(d, mu, 11u + static_cast<unsigned>(d));
      for (const auto& tau : s.tau) {
        const auto p = project_onto_cone(tau, mu);
        const LocalVector& r = p.r;
        // r ∈ K_μ̄.
        EXPECT_GE(r(0), -tol);
        EXPECT_LE(r.tail(d - 1).norm(), mu * r(0) + tol);
        // Idempotent.
        expect_vec_near(project_onto_cone(r, mu).r, r, tol);
        // Orthogonality (K_μ̄ is a cone): (τ − r)·r = 0.
        EXPECT_NEAR((tau - r).dot(r), 0.0, tol);
        // Variational inequality: (τ − r)·(s − r) ≤ 0 for all s ∈ K_μ̄.
        for (const auto& c : s.cone_points)
          EXPECT_LE((tau - r).dot(c - r), tol);
      }
    }
  }
}

// Jacobians vs central differences well inside each branch: h = 1e-6 gives truncation error
// ~1e-12 and rounding ~1e-10 on O(1) values, so rel 1e-6 has a wide margin.
TEST(ProjectOntoCone, JacobianMatchesFiniteDifferencesInEachBranch) {
  const double h = 1e-6;
  const double mu = 0.5;
  struct Case {
    LocalVector tau;
    ContactStatus status;
  };
  const std::vector<Case> cases = {
      {vec({2.0, 0.6}), ContactStatus::Stick},      {vec({3.0, 0.3, 0.4}), ContactStatus::Stick},
      {vec({-1.0, 0.5}), ContactStatus::Open},      {vec({-2.0, 1.2, 1.6}), ContactStatus::Open},
      {vec({1.0, 2.0}), ContactStatus::Slip},       {vec({-0.5, -3.0}), ContactStatus::Slip},
      {vec({1.0, 1.2, -1.6}), ContactStatus::Slip}, {vec({-0.3, 0.7, 2.1}), ContactStatus::Slip}};
  for (const auto& c : cases) {
    const auto p = project_onto_cone(c.tau, mu);
    ASSERT_EQ(p.status, c.status);
    const LocalMatrix J =
        fd_jacobian([&](const LocalVector& t) { return project_onto_cone(t, mu).r; }, c.tau, h);
    if (c.status == ContactStatus::Open) {
      EXPECT_EQ(p.dr_dtau.norm(), 0.0);
    } else {
      EXPECT_LE(relative_error(p.dr_dtau, J), 1e-6) << p.dr_dtau << "\nvs\n" << J;
    }
    const LocalVector dmu =
        fd_derivative([&](double m) { return project_onto_cone(c.tau, m).r; }, mu, h);
    if (c.status == ContactStatus::Slip) {
      EXPECT_LE(relative_error(p.dr_dmu, dmu), 1e-6);
    } else {
      EXPECT_EQ(p.dr_dmu.norm(), 0.0);
    }
    EXPECT_EQ(dmu.norm() == 0.0, c.status != ContactStatus::Slip);
  }
}

TEST(ProjectOntoCone, JacobianOnBranchBoundariesIsAOneSidedLimit) {
  // Stick/slip boundary ‖τ_t‖ = μ̄ τ_n: identity (limit from the stick side).
  auto p = project_onto_cone(vec({2.0, -1.0}), 0.5);
  EXPECT_EQ(p.status, ContactStatus::Stick);
  EXPECT_EQ((p.dr_dtau - LocalMatrix::Identity(2, 2)).norm(), 0.0);
  // Separation/slip boundary μ̄‖τ_t‖ = −τ_n: zero (limit from the separation side).
  p = project_onto_cone(vec({-1.0, 2.0}), 0.5);
  EXPECT_EQ(p.status, ContactStatus::Open);
  EXPECT_EQ(p.dr_dtau.norm(), 0.0);
  // Frictionless slip: dr/dτ = diag(1, 0, 0) exactly.
  p = project_onto_cone(vec({1.0, 0.2, -0.3}), 0.0);
  LocalMatrix expected = LocalMatrix::Zero(3, 3);
  expected(0, 0) = 1.0;
  EXPECT_EQ((p.dr_dtau - expected).norm(), 0.0);
}

// On the stick/slip boundary to within round-off both branches give r = τ, and a tie hint
// picks the Jacobian: the identity (stick) or the slip branch's, its limit from outside the
// cone. Off the band the values decide, whatever the hint.
TEST(ProjectOntoCone, TieTakesTheBranchAsked) {
  const double mu = 0.5;
  for (const LocalVector& tau : {vec({2.0, 1.0}), vec({2.0, 0.6, -0.8})}) { // ‖τ_t‖ = μ τ_n
    const Eigen::Index d = tau.size();
    LocalVector outside = tau;
    outside.tail(d - 1) *= 1.0 + 1e-9; // just outside: slip by value
    const auto slip_limit = project_onto_cone(outside, mu);
    ASSERT_EQ(slip_limit.status, ContactStatus::Slip);
    for (const double nudge : {0.0, 3e-16, -3e-16}) {
      LocalVector t = tau;
      t.tail(d - 1) *= 1.0 + nudge;
      const auto by_value = project_onto_cone(t, mu);
      const auto stick = project_onto_cone(t, mu, ConeTie::Stick);
      const auto slip = project_onto_cone(t, mu, ConeTie::Slip);
      EXPECT_TRUE(by_value.tie && stick.tie && slip.tie);
      EXPECT_EQ(by_value.status, nudge > 0 ? ContactStatus::Slip : ContactStatus::Stick);
      EXPECT_EQ(stick.status, ContactStatus::Stick);
      EXPECT_EQ(slip.status, ContactStatus::Slip);
      expect_vec_near(stick.r, t, 0.0);
      expect_vec_near(slip.r, t, kClosedFormTol);
      EXPECT_EQ((stick.dr_dtau - LocalMatrix::Identity(d, d)).norm(), 0.0);
      EXPECT_LE(relative_error(slip.dr_dtau, slip_limit.dr_dtau), 1e-8);
    }
    const auto off = project_onto_cone(outside, mu, ConeTie::Stick);
    EXPECT_FALSE(off.tie);
    EXPECT_EQ(off.status, ContactStatus::Slip);
  }
  // Frictionless, or τ_n = 0: no tie (no cone to be on the boundary of).
  EXPECT_FALSE(project_onto_cone(vec({2.0, 0.0}), 0.0, ConeTie::Slip).tie);
  EXPECT_FALSE(project_onto_cone(vec({0.0, 0.0}), 0.5, ConeTie::Slip).tie);
}

TEST(BipotentialPredictor, ClosedFormAndDerivatives) {
  // r = (1, 0.2), g_n = 0.01, Δg_t = −0.003, μ̄ = 0.4, ρ = 100:
  // τ_n = 1 − 100 (0.01 + 0.4·0.003) = −0.12, τ_t = 0.2 + 0.3 = 0.5.
  PredictorDerivatives d;
  LocalVector tau = bipotential_predictor(vec({1.0, 0.2}), 0.01, vec({-0.003}), 0.4, 100.0, &d);
  expect_vec_near(tau, vec({-0.12, 0.5}), kClosedFormTol);
  // 3D: Δg_t = (0.003, −0.004), ‖Δg_t‖ = 0.005; r = (2, 0, 1), g_n = 0, μ̄ = 0.5, ρ = 10:
  // τ_n = 2 − 10·0.0025 = 1.975, τ_t = (−0.03, 1.04).
  tau = bipotential_predictor(vec({2.0, 0.0, 1.0}), 0.0, vec({0.003, -0.004}), 0.5, 10.0, &d);
  expect_vec_near(tau, vec({1.975, -0.03, 1.04}), kClosedFormTol);

  // Derivatives vs central differences (τ is smooth away from Δg_t = 0; h relative to the
  // jump scale 1e-3 keeps truncation error ~1e-12 relative).
  const double h = 1e-9;
  for (const LocalVector& r : {vec({1.0, 0.2}), vec({2.0, 0.0, 1.0})}) {
    const int n = static_cast<int>(r.size());
    LocalVector jump(n); // [g_n, Δg_t]
    jump(0) = 0.002;
    for (int i = 1; i < n; ++i)
      jump(i) = 0.003 * i - 0.005;
    const double mu = 0.4, rho = 50.0;
    auto f = [&](const LocalVector& j) {
      return bipotential_predictor(r, j(0), j.tail(n - 1), mu, rho);
    };
    bipotential_predictor(r, jump(0), jump.tail(n - 1), mu, rho, &d);
    EXPECT_LE(relative_error(d.dtau_djump, fd_jacobian(f, jump, h)), 1e-6);
    const LocalVector dmu = fd_derivative(
        [&](double m) { return bipotential_predictor(r, jump(0), jump.tail(n - 1), m, rho); }, mu,
        1e-6);
    EXPECT_LE(relative_error(d.dtau_dmu, dmu), 1e-6);
  }
  // At Δg_t = 0 the subgradient 0 of ‖Δg_t‖ is used: no NaN, ∂τ_n/∂Δg_t = 0.
  bipotential_predictor(vec({1.0, 0.0, 0.0}), 0.0, vec({0.0, 0.0}), 0.5, 10.0, &d);
  EXPECT_TRUE(d.dtau_djump.allFinite());
  EXPECT_EQ(d.dtau_djump(0, 1), 0.0);
  EXPECT_EQ(d.dtau_djump(0, 2), 0.0);
}

TEST(ContactStatus, Names) {
  EXPECT_STREQ(to_string(ContactStatus::Open), "open");
  EXPECT_STREQ(to_string(ContactStatus::Stick), "stick");
  EXPECT_STREQ(to_string(ContactStatus::Slip), "slip");
}

} // namespace
} // namespace bipot::contact
