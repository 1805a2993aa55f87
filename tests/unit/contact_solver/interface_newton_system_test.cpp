// The exact generalized Newton's Jacobian (InterfaceNewtonSystem::add) against central
// finite differences of its residual, in every regime of the interface law: stick, slip,
// open, debonding (β = β(jump), α = 0 and viscous), debonding while sliding, β frozen. The
// sliding cases slide against their friction force (r_t opposite to g_t), as a solution does:
// there the slip branch's element (contact/laws/interface_law.cpp) is the exact derivative.
#include "contact/laws/coulomb_signorini.hpp"
#include "contact/laws/rccm.hpp"
#include "contact/solver/interface_newton_system.hpp"
#include "fem/linalg/dof_distribution.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

namespace bipot::contact {
namespace {

// One pair in plane strain: node 0 (body 1) and node 1 (body 2) at the same place, the
// normal tilted so that every DOF couples to both local components.
Interface one_pair() {
  Interface iface;
  iface.name = "joint";
  InterfacePair p;
  p.node_a = 0;
  p.node_b = 1;
  p.weight = 0.7;
  const double c = std::cos(0.3), s = std::sin(0.3);
  p.normal = {s, c, 0};
  p.tangent1 = {-c, s, 0}; // (−n_y, n_x)
  iface.pairs.push_back(p);
  return iface;
}

struct Case {
  std::string name;
  std::shared_ptr<InterfaceLaw> law;
  Eigen::Vector2d jump; ///< local [g_n, g_t] (m) at which to linearise
  Eigen::Vector2d r;    ///< multiplier r̂ (kPa)
  double dtau = 0.1;
  ContactStatus status;
  double frozen_beta = -1; ///< ≥ 0: β held (staggered fallback)
  bool debonding = false;  ///< β below its committed value 1 at this jump
};

TEST(InterfaceNewtonSystem, JacobianMatchesFiniteDifferencesInEveryRegime) {
  auto coulomb = std::make_shared<CoulombSignorini>(CoulombSignorini::Parameters{0.4});
  // C = 100 kN/m³, w = 0.5 kJ/m²: the bond breaks at E = C‖g‖² > w.
  auto rccm = std::make_shared<Rccm>(Rccm::Parameters{100.0, 100.0, 0.5, 0.4});
  auto viscous = std::make_shared<Rccm>(Rccm::Parameters{100.0, 100.0, 0.5, 0.4, 0.2});
  const std::vector<Case> cases = {
      {"stick", coulomb, {-0.01, 0.001}, {10.0, 1.0}, 0.1, ContactStatus::Stick},
      {"slip", coulomb, {-0.01, 0.02}, {10.0, -8.0}, 0.1, ContactStatus::Slip},
      {"open", coulomb, {0.02, 0.01}, {-5.0, 0.5}, 0.1, ContactStatus::Open},
      {"rccm_bonded_open", rccm, {0.02, 0.01}, {0.0, 0.0}, 0.1, ContactStatus::Open},
      {"rccm_debonding_open", rccm, {0.1, 0.05}, {0.0, 0.0}, 0.1, ContactStatus::Open, -1, true},
      {"rccm_debonding_slip", rccm, {-0.01, 0.1}, {10.0, -5.0}, 0.1, ContactStatus::Slip, -1, true},
      {"rccm_viscous_debonding",
       viscous,
       {0.1, 0.05},
       {0.0, 0.0},
       0.1,
       ContactStatus::Open,
       -1,
       true},
      {"rccm_beta_frozen_slip", rccm, {-0.01, 0.1}, {10.0, -5.0}, 0.1, ContactStatus::Slip, 0.6},
  };
  const DofMap dofs(2, 2);
  const DofDistribution dist(2, 2);
  const Interface iface = one_pair();
  const InterfacePair& p = iface.pairs[0];
  const Eigen::Vector2d n(p.normal[0], p.normal[1]), t(p.tangent1[0], p.tangent1[1]);
  for (const Case& cs : cases) {
    InterfaceAssembler ia(iface, *cs.law, dofs, dist);
    if (cs.frozen_beta >= 0) ia.freeze_adhesion({cs.frozen_beta});
    InterfaceNewtonSystem sys({&ia}, dofs);
    ASSERT_EQ(sys.num_dofs(), 4);
    ASSERT_EQ(sys.num_multipliers(), 2);
    // u_a = 0, u_b = the global jump: z = (x, λ) with x = [u_a, u_b], λ = A r.
    Eigen::VectorXd z(6);
    z << 0, 0, (cs.jump(0) * n + cs.jump(1) * t), p.weight * cs.r;
    const std::vector<bool> free(4, false);
    auto residual = [&](const Eigen::VectorXd& at, Eigen::MatrixXd* J) {
      std::vector<double> u(at.data(), at.data() + 4);
      sys.set_multipliers(at.tail(2));
      ia.evaluate(u, cs.dtau);
      Eigen::VectorXd F = Eigen::VectorXd::Zero(6);
      if (J) J->setZero(6, 6);
      sys.add(free, F, J);
      return F;
    };
    Eigen::MatrixXd J(6, 6);
    residual(z, &J);
    {
      // The sparse output of add() (the Newton matrix in operator form) holds the same terms.
      std::vector<Eigen::Triplet<double>> entries;
      Eigen::VectorXd F = Eigen::VectorXd::Zero(6);
      sys.add(free, F, entries);
      Eigen::SparseMatrix<double> P(6, 6);
      P.setFromTriplets(entries.begin(), entries.end());
      EXPECT_LE((Eigen::MatrixXd(P) - J).norm(), 1e-14 * J.norm()) << cs.name;
    }
    EXPECT_EQ(ia.results()[0].status, cs.status) << cs.name;
    if (cs.debonding) {
      EXPECT_LT(ia.results()[0].beta, 1.0 - 1e-3) << cs.name;
    }
    if (cs.frozen_beta >= 0) {
      EXPECT_EQ(ia.results()[0].beta, cs.frozen_beta) << cs.name;
    }
    Eigen::MatrixXd fd(6, 6);
    for (int k = 0; k < 6; ++k) {
      // Steps far below every distance to a kink of these points (≥ 1e-3 in the jump, ≥ 1
      // kPa in τ); central differences then err by O(h²) plus round-off ~ ε |F| / h.
      const double h = 1e-6 * std::max(1.0, std::abs(z(k)));
      Eigen::VectorXd zp = z, zm = z;
      zp(k) += h;
      zm(k) -= h;
      fd.col(k) = (residual(zp, nullptr) - residual(zm, nullptr)) / (2 * h);
    }
    const double error = (J - fd).norm() / J.norm();
    std::printf("[newton-jacobian] %-24s |J| = %.3e, |J - FD| / |J| = %.2e\n", cs.name.c_str(),
                J.norm(), error);
    EXPECT_LT(error, 1e-6) << cs.name << "\nJ =\n" << J << "\nFD =\n" << fd;
  }
}

// In stick the multiplier rows enforce the jump exactly: ∂F_λ/∂λ = 0 and ∂F_λ/∂x = A ρ ∂ĝ/∂x
// (no penalty left); in separation λ = 0 is imposed (∂F_λ/∂λ = I, ∂F_λ/∂x = 0).
TEST(InterfaceNewtonSystem, StickTiesTheJumpAndSeparationZeroesTheForce) {
  CoulombSignorini law({0.4});
  const DofMap dofs(2, 2);
  const DofDistribution dist(2, 2);
  const Interface iface = one_pair();
  InterfaceAssembler ia(iface, law, dofs, dist);
  InterfaceNewtonSystem sys({&ia}, dofs);
  const std::vector<bool> free(4, false);
  for (const bool stick : {true, false}) {
    const Eigen::Vector2d r = stick ? Eigen::Vector2d(10.0, 1.0) : Eigen::Vector2d(-5.0, 0.0);
    sys.set_multipliers(0.7 * r);
    ia.evaluate({0, 0, 0, 0}, 0.1);
    Eigen::VectorXd F = Eigen::VectorXd::Zero(6);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(6, 6);
    sys.add(free, F, &J);
    const Eigen::Matrix2d dF_dlambda = J.bottomRightCorner(2, 2);
    const Eigen::Matrix2d Qt = ia.frame(0).transpose();
    const Eigen::Matrix2d dF_dxb = J.block(4, 2, 2, 2);
    if (stick) {
      EXPECT_LT(dF_dlambda.norm(), 1e-14);
      EXPECT_LT((dF_dxb - 0.7 * 1.0 * Qt).norm(), 1e-12) << dF_dxb; // ρ = 1 (not set)
    } else {
      EXPECT_LT((dF_dlambda - Eigen::Matrix2d::Identity()).norm(), 1e-14);
      EXPECT_LT(dF_dxb.norm(), 1e-14);
      EXPECT_LT((F.tail(2) - 0.7 * r).norm(), 1e-12); // F_λ = λ − A·0
    }
  }
}

// A stuck pair whose four DOFs are all prescribed (a pile head pair pulled by both copies):
// its multipliers act on nothing and the law leaves them free in stick, so their columns
// would be zero. Each row then also fixes its own component: J is regular, and the rest of
// the rows are those of the stick law.
TEST(InterfaceNewtonSystem, StuckPairOnPrescribedDofsKeepsTheMatrixRegular) {
  CoulombSignorini law({0.4});
  const DofMap dofs(2, 2);
  const DofDistribution dist(2, 2);
  const Interface iface = one_pair();
  InterfaceAssembler ia(iface, law, dofs, dist);
  InterfaceNewtonSystem sys({&ia}, dofs);
  sys.set_multipliers(0.7 * Eigen::Vector2d(10.0, 1.0));
  ia.evaluate({0, 0, 0, 0}, 0.1);
  ASSERT_EQ(ia.results()[0].status, ContactStatus::Stick);
  const std::vector<bool> held(4, true);
  Eigen::VectorXd F = Eigen::VectorXd::Zero(6);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(6, 6);
  J.topLeftCorner(4, 4).setIdentity(); // the prescribed rows, as the condensed S gives them
  sys.add(held, F, &J);
  EXPECT_LT((J.bottomRightCorner(2, 2) - Eigen::Matrix2d::Identity()).norm(), 1e-14);
  EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(J).rank(), 6);
  // With a free node b, the multipliers act on its rows: nothing is added.
  std::vector<bool> b_free = {true, true, false, false};
  J.setZero();
  J.topLeftCorner(4, 4).setIdentity();
  sys.add(b_free, F, &J);
  EXPECT_LT(J.bottomRightCorner(2, 2).norm(), 1e-14);
}

} // namespace
} // namespace bipot::contact
