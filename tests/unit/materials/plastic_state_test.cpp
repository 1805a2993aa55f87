// What every plastic material shares through ElastoPlastic: update() never writes old_state,
// the state advances only when the caller copies new_state (so a cut-back just discards it),
// and outputs come from the state.
#include "materials/drucker_prager.hpp"
#include "materials/mohr_coulomb.hpp"
#include "materials/tresca.hpp"
#include "materials/von_mises.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

namespace bipot {
namespace {

std::vector<std::unique_ptr<ElastoPlastic>> all_plastic() {
  std::vector<std::unique_ptr<ElastoPlastic>> v;
  v.push_back(std::make_unique<VonMises>(VonMises::Parameters{2.5e4, 0.25, 30.0, 500.0}));
  v.push_back(std::make_unique<Tresca>(Tresca::Parameters{2.5e4, 0.25, 15.0, 500.0}));
  v.push_back(
      std::make_unique<MohrCoulomb>(MohrCoulomb::Parameters{2.5e4, 0.25, 10.0, 30.0, 10.0, 5.0}));
  v.push_back(
      std::make_unique<DruckerPrager>(DruckerPrager::Parameters{2.5e4, 0.25, 10.0, 30.0, 10.0}));
  return v;
}

TEST(PlasticState, OldStateIsReadOnlyAndCommitIsTheCallersCopy) {
  for (const auto& m : all_plastic())
    for (int n : {4, 6}) {
      Voigt strain(n), sigma0 = Voigt::Zero(n);
      for (int i = 0; i < n; ++i)
        strain(i) = 1e-2 * (i == 1 ? -1.0 : 0.5);
      sigma0.head(3).setConstant(-50.0);
      const int ns = m->num_state_variables();
      std::vector<double> old(ns, 0.0), before = old, a(ns), b(ns), c(ns);
      Voigt s1, s2, s3;
      VoigtMatrix D;
      m->update(strain, sigma0, old.data(), s1, D, a.data());
      EXPECT_EQ(old, before) << m->name();
      m->update(strain, sigma0, old.data(), s2, D, b.data());
      EXPECT_EQ(a, b) << m->name(); // no hidden state: same inputs, same outputs
      EXPECT_EQ((s1 - s2).cwiseAbs().maxCoeff(), 0.0) << m->name();
      EXPECT_EQ(a[ElastoPlastic::plastic_flag_slot], 1.0) << m->name() << " should yield";
      // Committed: from the new state a slight unloading (0.999 ε) is elastic, with
      // σ = σ1 − D (0.001 ε) (the plastic strain is in the state); from the virgin state the
      // same strain would yield again.
      m->update(0.999 * strain, sigma0, a.data(), s3, D, c.data());
      EXPECT_EQ(c[ElastoPlastic::plastic_flag_slot], 0.0) << m->name();
      const Voigt expected = s1 - m->elasticity_matrix(n) * (0.001 * strain);
      EXPECT_LT((s3 - expected).cwiseAbs().maxCoeff(), 1e-10 * s1.cwiseAbs().maxCoeff())
          << m->name();
      double values[2];
      m->output(a.data(), values);
      EXPECT_GT(values[0], 0.0) << m->name();
      EXPECT_EQ(values[1], 1.0) << m->name();
      ASSERT_EQ(m->num_output_fields(), 2);
      EXPECT_EQ(m->output_field_name(1), "plastic");
    }
}

// Random trial stresses (general, near-hydrostatic, and with two equal principal values,
// where the corners are) must all return onto the surface: f(σ) = 0 to round-off. Before
// the cut-off corner σ1 = σ2 = σt on the yield surface had its 3-plane subsets, about 1 in
// 2000 such trials found no admissible active set; this catches that kind of gap.
TEST(PlasticState, RandomTrialsReturnOntoTheSurface) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0.0, 100.0);
  auto materials = all_plastic();
  materials.push_back(
      std::make_unique<MohrCoulomb>(MohrCoulomb::Parameters{2.5e4, 0.25, 10.0, 30.0, 0.0}));
  materials.push_back(
      std::make_unique<MohrCoulomb>(MohrCoulomb::Parameters{2.5e4, 0.3, 0.0, 35.0, 5.0, 0.0}));
  for (const auto& m : materials) {
    int plastic = 0;
    for (int k = 0; k < 4000; ++k) {
      Mat3 A;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j <= i; ++j)
          A(i, j) = A(j, i) = normal(rng);
      if (k % 3 == 1) A = normal(rng) * Mat3::Identity() + 1e-9 * A;
      if (k % 3 == 2) { // σxx = σyy with z principal: a double eigenvalue
        A(1, 1) = A(0, 0);
        A(0, 1) = A(1, 0) = A(0, 2) = A(2, 0) = A(1, 2) = A(2, 1) = 0.0;
      }
      const double scale = std::max(1.0, A.cwiseAbs().maxCoeff());
      ElastoPlastic::Return r;
      ASSERT_NO_THROW(r = m->return_stress(A, 0.0)) << m->name() << "\n" << A;
      if (r.branch == 0) {
        EXPECT_LE(m->yield_function(A, 0.0), 0.0);
        continue;
      }
      ++plastic;
      EXPECT_NEAR(m->yield_function(r.stress, r.hardening_increment), 0.0, 1e-12 * scale)
          << m->name() << " branch " << r.branch << "\n"
          << A;
    }
    EXPECT_GT(plastic, 1000) << m->name(); // the sample does exercise the returns
  }
}

} // namespace
} // namespace bipot
