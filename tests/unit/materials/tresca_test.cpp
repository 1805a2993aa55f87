#include "materials/material_registry.hpp"
#include "materials/tresca.hpp"
#include "point_driver.hpp"

#include <gtest/gtest.h>

namespace bipot {
namespace {

using test::cramer;
using test::expect_fd_tangent;
using test::expect_return;

// E = 2.5e4 kPa, ν = 0.25: λ = G = 1e4 kPa, C = 1e4 (1⊗1 + 2 I). c = 10 kPa, H = 1000 kPa.
// Planes n = m: n1 = (1, 0, −1), n2 = (0, 1, −1), n3 = (1, −1, 0); C n = 2e4 n (tr n = 0).
// f_i = n_i·σ − 2(c + H κ) with Δκ = 2 Σ Δλ, so M_ij = n_i·C n_j + 2H·2:
// n1·C n1 = 4e4, n1·C n2 = n1·C n3 = 2e4.
constexpr double E = 2.5e4, nu = 0.25, c = 10.0, H = 1000.0;

// Trial (10, −5, −30): f = 40 − 20 = 20, Δλ = 20/(4e4 + 4H), σ = t − 2e4 Δλ n1
// ≈ (0.91, −5, −20.91): σ1 − σ3 = 2(c + 2H Δλ), the hardened strength.
TEST(Tresca, PlaneReturnWithHardening) {
  Tresca m({E, nu, c, H});
  const Vec3 t(10, -5, -30), n1(1, 0, -1);
  const double dl = 20.0 / (4e4 + 4 * H);
  expect_return(m, t, t - 2e4 * dl * n1, Tresca::Plane);
}

// Trial (10, 8, −30): the plane return gives σ1 < σ2; left edge, M = [[4e4 + 4H, 2e4 + 4H],
// [2e4 + 4H, 4e4 + 4H]], rhs (20, 18). Trial (10, −28, −30): right edge, rhs (20, 18).
TEST(Tresca, EdgeReturns) {
  Tresca m({E, nu, c, H});
  const Vec3 n1(1, 0, -1), n2(0, 1, -1), n3(1, -1, 0);
  const double a = 4e4 + 4 * H, b = 2e4 + 4 * H;
  {
    const Vec3 t(10, 8, -30);
    const auto [l1, l2] = cramer(a, b, b, a, 20.0, 18.0);
    expect_return(m, t, t - 2e4 * (l1 * n1 + l2 * n2), Tresca::EdgeLeft);
  }
  {
    const Vec3 t(10, -28, -30);
    const auto [l1, l3] = cramer(a, b, b, a, 20.0, 18.0);
    expect_return(m, t, t - 2e4 * (l1 * n1 + l3 * n3), Tresca::EdgeRight);
  }
}

// Simple shear γ (3D and plane strain): τ = G γ up to c, then τ = c + H γp with
// γ = τ/G + γp, i.e. τ = (c + H γ)/(1 + H/G); κ = γp.
TEST(Tresca, SimpleShearHardeningCurve) {
  Tresca m({E, nu, c, H});
  const double G = 1e4;
  for (int n : {4, 6}) {
    std::vector<double> state(ElastoPlastic::state_size, 0.0), next(state);
    for (int step = 1; step <= 30; ++step) {
      const double gamma = step * 0.2 * c / G;
      Voigt strain = Voigt::Zero(n), s;
      strain(3) = gamma;
      VoigtMatrix D;
      m.update(strain, Voigt::Zero(n), state.data(), s, D, next.data());
      state = next;
      const double tau = gamma <= c / G ? G * gamma : (c + H * gamma) / (1 + H / G);
      EXPECT_NEAR(s(3), tau, 1e-10 * tau) << "n=" << n << " step " << step;
      EXPECT_NEAR(state[ElastoPlastic::hardening_slot], std::max(0.0, gamma - tau / G),
                  1e-10 * gamma);
    }
  }
}

TEST(Tresca, ConsistentTangentInEveryBranch) {
  Tresca m({E, nu, c, H});
  expect_fd_tangent(m, Vec3(10, -5, -30), Tresca::Plane);
  expect_fd_tangent(m, Vec3(10, 8, -30), Tresca::EdgeLeft);
  expect_fd_tangent(m, Vec3(10, -28, -30), Tresca::EdgeRight);
}

TEST(Tresca, ZeroCohesionIsRejected) {
  ParameterSet p;
  p.set("youngs_modulus", E);
  p.set("poissons_ratio", nu);
  p.set("cohesion", 0.0);
  try {
    builtin_materials().create("tresca", p);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tresca.cohesion: value 0 is out of range (0, inf) kPa"),
              std::string::npos)
        << e.what();
  }
}

} // namespace
} // namespace bipot
