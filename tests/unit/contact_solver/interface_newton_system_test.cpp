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
      // The law's ∂F_λ/∂λ is 0; J carries the stick regularisation ε I (two pairs on one node
      // pair would make it singular).
      const double eps = InterfaceNewtonSystem::stick_regularisation;
      EXPECT_LE((dF_dlambda - eps * Eigen::Matrix2d::Identity()).norm(), 1e-14 * eps);
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
  // With a free node b, the multipliers act on its rows: only the stick regularisation ε I.
  std::vector<bool> b_free = {true, true, false, false};
  J.setZero();
  J.topLeftCorner(4, 4).setIdentity();
  sys.add(b_free, F, &J);
  const double eps = InterfaceNewtonSystem::stick_regularisation;
  EXPECT_LE((J.bottomRightCorner(2, 2) - eps * Eigen::Matrix2d::Identity()).norm(), 1e-14 * eps);
}

// A node on two interfaces (the pile's toe corner is on the shaft's and the toe's): two pairs
// on the same two nodes, both stuck, tie the same jump twice, and only the sum of their forces
// is determined. Bulk springs k on the four DOFs stand for the condensed S and a load c pulls
// node b; in stick both nodes move by c / 2k and the pairs carry −c/2 together. The start
// has the right forces (each pair inside its cone, μ = 1.5 so that both cones of a right-angled
// corner hold them) and both nodes displaced together from the solution; stick is linear, so
// one Newton step must solve it: a finite step and a new residual of 1e-9 of the first. Without
// the stick regularisation J is singular, and the LU's step is not finite or is of size ≥ 1e12.
TEST(InterfaceNewtonSystem, TwoStuckPairsOnOneNodePairKeepTheStepFinite) {
  CoulombSignorini law({1.5});
  const DofMap dofs(2, 2);
  const DofDistribution dist(2, 2);
  const Interface shaft = one_pair();
  Interface toe = one_pair(); // the same nodes, the normal turned by 90°
  toe.name = "toe";
  InterfacePair& p = toe.pairs[0];
  p.weight = 0.4;
  p.normal = shaft.pairs[0].tangent1;
  p.tangent1 = {-p.normal[1], p.normal[0], 0};
  InterfaceAssembler ia_shaft(shaft, law, dofs, dist), ia_toe(toe, law, dofs, dist);
  InterfaceNewtonSystem sys({&ia_shaft, &ia_toe}, dofs);
  ASSERT_EQ(sys.num_dofs(), 4);
  ASSERT_EQ(sys.num_multipliers(), 4);
  const double k = 1e3;
  const Eigen::Vector2d lambda_shaft(1.0, 0.5), lambda_toe(2.0, -1.0); // kN, local frames
  const Eigen::Vector2d n(shaft.pairs[0].normal[0], shaft.pairs[0].normal[1]);
  const Eigen::Vector2d t(shaft.pairs[0].tangent1[0], shaft.pairs[0].tangent1[1]);
  const Eigen::Vector2d n2(p.normal[0], p.normal[1]), t2(p.tangent1[0], p.tangent1[1]);
  const Eigen::Vector2d force_b =
      lambda_shaft(0) * n + lambda_shaft(1) * t + lambda_toe(0) * n2 + lambda_toe(1) * t2;
  Eigen::VectorXd c = Eigen::VectorXd::Zero(4);
  c.tail(2) = -2.0 * force_b;
  const std::vector<bool> free(4, false);
  auto residual = [&](const Eigen::VectorXd& z, Eigen::MatrixXd* J) {
    std::vector<double> u(z.data(), z.data() + 4);
    sys.set_multipliers(z.tail(4));
    ia_shaft.evaluate(u, 0.1);
    ia_toe.evaluate(u, 0.1);
    Eigen::VectorXd F = Eigen::VectorXd::Zero(8);
    F.head(4) = c - k * z.head(4);
    if (J) {
      J->setZero(8, 8);
      J->topLeftCorner(4, 4) = -k * Eigen::Matrix4d::Identity();
    }
    sys.add(free, F, J);
    return F;
  };
  const Eigen::Vector2d u = c.tail(2) / (2 * k) + Eigen::Vector2d(1e-4, -2e-4);
  Eigen::VectorXd z(8);
  z << u, u, lambda_shaft, lambda_toe;
  Eigen::MatrixXd J;
  const Eigen::VectorXd F0 = residual(z, &J);
  ASSERT_EQ(ia_shaft.results()[0].status, ContactStatus::Stick);
  ASSERT_EQ(ia_toe.results()[0].status, ContactStatus::Stick);
  const Eigen::VectorXd dz = J.partialPivLu().solve(-F0);
  std::printf("[two-stuck-pairs] |dz| = %.3e\n", dz.norm());
  ASSERT_TRUE(dz.allFinite());
  EXPECT_LT(dz.norm(), 1.0) << dz.transpose();
  const Eigen::VectorXd F1 = residual(z + dz, nullptr);
  EXPECT_EQ(ia_shaft.results()[0].status, ContactStatus::Stick);
  EXPECT_EQ(ia_toe.results()[0].status, ContactStatus::Stick);
  std::printf("[two-stuck-pairs] |F1| / |F0| = %.2e\n", F1.norm() / F0.norm());
  EXPECT_LT(F1.norm(), 1e-9 * F0.norm());
}

} // namespace
} // namespace bipot::contact
