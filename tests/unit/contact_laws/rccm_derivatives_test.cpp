// Derivatives of the RCCM law and of evaluate() against central finite differences, away
// from kinks (the brief's rel 1e-6). Jumps are O(1e-3) m, stiffnesses O(1e6) kN/m³.
#include "contact/laws/rccm.hpp"
#include "local_test_utils.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace bipot::contact {
namespace {

using test::fd_jacobian;
using test::relative_error;
using test::vec;

// Step 1e-9 m on jumps of 1e-4..1e-3 m: truncation ~(h/g)² ≈ 1e-10, rounding ~1e-16·g/h ≈
// 1e-10 relative, both far below the 1e-6 tolerance.
constexpr double kH = 1e-9;
constexpr double kRel = 1e-6;

const std::vector<LocalVector> kJumps = {vec({3e-4, 2e-4}), vec({-1e-4, 5e-4}),
                                         vec({4e-4, 1e-4, -3e-4}), vec({-2e-4, 3e-4, 2e-4})};

TEST(RccmDerivatives, AdhesionUpdateQuasiStaticAndViscous) {
  for (double alpha : {0.0, 1e-2}) {
    const Rccm law({1e6, 4e5, 0.01, 0.3, alpha});
    for (const auto& jump : kJumps) {
      const double beta_old = 0.9;
      LocalVector db;
      const double beta = law.update_adhesion(beta_old, jump, 0.5, &db);
      ASSERT_LT(beta, beta_old); // damaging branch: E β_old > w for every jump here
      auto f = [&](const LocalVector& j) { return vec({law.update_adhesion(beta_old, j, 0.5)}); };
      const LocalMatrix fd = fd_jacobian(f, jump, kH);
      EXPECT_LE(relative_error(db.transpose(), fd), kRel) << db.transpose() << " vs " << fd;
      if (jump(0) < 0) {
        EXPECT_EQ(db(0), 0.0); // a closing jump does not enter E
      }
    }
  }
}

TEST(RccmDerivatives, AdhesionUpdateIsFlatWhereBetaStays) {
  // Small jumps (E β_old < w): β = β_old, derivative exactly zero, as is its FD.
  for (double alpha : {0.0, 1e-2}) {
    const Rccm law({1e6, 4e5, 0.05, 0.3, alpha});
    for (const auto& small : {vec({1e-5, 1e-5}), vec({1e-5, -2e-5, 1e-5})}) {
      LocalVector db;
      EXPECT_EQ(law.update_adhesion(0.7, small, 0.5, &db), 0.7);
      EXPECT_EQ(db.norm(), 0.0);
      auto f = [&](const LocalVector& j) { return vec({law.update_adhesion(0.7, j, 0.5)}); };
      EXPECT_EQ(fd_jacobian(f, small, kH).norm(), 0.0);
    }
  }
}

TEST(RccmDerivatives, AdhesiveTraction) {
  const Rccm law({1e6, 4e5, 0.01});
  for (const auto& jump : kJumps) {
    const double beta = 0.6;
    LocalMatrix dt;
    law.adhesive_traction(beta, jump, &dt);
    auto f = [&](const LocalVector& j) { return law.adhesive_traction(beta, j); };
    EXPECT_LE(relative_error(dt, fd_jacobian(f, jump, kH)), kRel);
    // ∂/∂β: step 1e-6 on β = 0.6 (quadratic in β: central differences are exact up to rounding).
    const LocalVector dbeta = law.adhesive_traction_dbeta(beta, jump);
    const LocalVector fd =
        test::fd_derivative([&](double b) { return law.adhesive_traction(b, jump); }, beta, 1e-6);
    EXPECT_LE(relative_error(dbeta, fd), kRel);
    // Closed form −β²[C_n g_n, C_t g_t]: a couple of roundings.
    const LocalVector t = law.adhesive_traction(beta, jump);
    EXPECT_NEAR(t(0), -0.36 * 1e6 * jump(0), 1e-15 * 1e6 * 1e-3);
    for (Eigen::Index i = 1; i < jump.size(); ++i)
      EXPECT_NEAR(t(i), -0.36 * 4e5 * jump(i), 1e-15 * 4e5 * 1e-3);
  }
}

// evaluate() with adhesion being lost (viscous, so β, μ̄, τ and r all move with the jump) in
// each branch of the projection, 2D and 3D. The slip cases slide against their friction force
// (r_t opposite to Δg_t), as a solution does, where evaluate()'s slip element is the exact
// derivative (slip_linearisation_test.cpp covers the other side).
TEST(RccmDerivatives, EvaluateChainRuleInEachBranch) {
  const Rccm law({1.0, 1.0, 0.02, 0.6, 0.5}); // nondimensional: tractions, jumps O(0.1..1)
  struct Case {
    LocalVector old_jump, jump, r;
    ContactStatus status;
  };
  const std::vector<Case> cases = {
      {vec({0.0, 0.05}), vec({0.1, 0.15}), vec({1.0, -0.3}), ContactStatus::Slip},
      {vec({0.0, 0.05}), vec({0.1, 0.15}), vec({2.0, 0.05}), ContactStatus::Stick},
      {vec({0.0, 0.05}), vec({0.1, 0.15}), vec({0.05, 0.0}), ContactStatus::Open},
      {vec({0.0, 0.05, 0.02}), vec({0.1, 0.15, 0.05}), vec({1.0, -0.3, -0.09}),
       ContactStatus::Slip},
      {vec({0.0, 0.05, 0.02}), vec({0.1, 0.15, 0.05}), vec({2.0, 0.05, 0.0}), ContactStatus::Stick},
      {vec({0.0, 0.05, 0.02}), vec({0.1, 0.15, 0.05}), vec({0.05, 0.0, 0.0}), ContactStatus::Open}};
  const double h = 1e-7; // on O(0.1) jumps and O(1) tractions
  for (const auto& c : cases) {
    InterfaceState old = initial_state(law, static_cast<int>(c.jump.size()));
    old.beta = 0.7;
    old.jump = c.old_jump;
    InterfaceResponseDerivatives d;
    const auto resp = evaluate(law, old, c.jump, c.r, 0.1, 1.0, &d);
    ASSERT_EQ(resp.status, c.status);
    ASSERT_LT(resp.beta, old.beta); // the β(jump) chain is active
    auto traction = [&](const LocalVector& j) {
      return evaluate(law, old, j, c.r, 0.1, 1.0).traction;
    };
    auto r_of_jump = [&](const LocalVector& j) { return evaluate(law, old, j, c.r, 0.1, 1.0).r; };
    auto r_of_r = [&](const LocalVector& r) { return evaluate(law, old, c.jump, r, 0.1, 1.0).r; };
    auto beta = [&](const LocalVector& j) {
      return vec({evaluate(law, old, j, c.r, 0.1, 1.0).beta});
    };
    EXPECT_LE(relative_error(d.dt_djump, fd_jacobian(traction, c.jump, h)), kRel);
    EXPECT_LE(relative_error(d.dbeta_djump.transpose(), fd_jacobian(beta, c.jump, h)), kRel);
    if (c.status == ContactStatus::Open) {
      EXPECT_EQ(d.dr_djump.norm(), 0.0);
      EXPECT_EQ(d.dr_dr.norm(), 0.0);
    } else {
      EXPECT_LE(relative_error(d.dr_djump, fd_jacobian(r_of_jump, c.jump, h)), kRel);
      EXPECT_LE(relative_error(d.dr_dr, fd_jacobian(r_of_r, c.r, h)), kRel);
    }
    EXPECT_EQ((d.dt_dr - d.dr_dr).norm(), 0.0); // the adhesive part does not depend on r
  }
}

} // namespace
} // namespace bipot::contact
