// What every plastic material shares through ElastoPlastic: update() never writes old_state,
// the state advances only when the caller copies new_state (so a cut-back just discards it),
// and outputs come from the state.
#include "materials/drucker_prager.hpp"
#include "materials/mohr_coulomb.hpp"
#include "materials/tresca.hpp"
#include "materials/von_mises.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace bipot {
namespace {

std::vector<std::unique_ptr<ElastoPlastic>> all_plastic() {
  std::vector<std::unique_ptr<ElastoPlastic>> v;
  v.push_back(std::make_unique<VonMises>(2.5e4, 0.25, 30.0, 500.0));
  v.push_back(std::make_unique<Tresca>(2.5e4, 0.25, 15.0, 500.0));
  v.push_back(std::make_unique<MohrCoulomb>(2.5e4, 0.25, 10.0, 30.0, 10.0, 5.0));
  v.push_back(std::make_unique<DruckerPrager>(2.5e4, 0.25, 10.0, 30.0, 10.0));
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

} // namespace
} // namespace bipot
