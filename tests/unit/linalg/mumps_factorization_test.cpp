// The rooted MUMPS factorisation picks LDL^T without pivoting, LDL^T with pivoting or LU from
// the values (detail/mumps_factorization.cpp), on the pairs of detail/symmetric_pairs.cpp.
// Every solution is compared with a dense LU of the same 6x6 matrix: its condition number is
// below 1e2 here, so two backward-stable solutions agree to ~1e-14; 1e-12 leaves room.
#include "fem/linalg/detail/root_factorization.hpp"
#include "fem/linalg/detail/symmetric_pairs.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace bipot::detail {
namespace {

constexpr int n = 6;

/// A band of width 2 with every row's columns in descending order, as a gathered row of a
/// 2-rank matrix comes (owned columns first): the pairing must not assume sorted rows.
RootCsr band_structure() {
  RootCsr s;
  s.row_ptr.push_back(0);
  for (int r = 0; r < n; ++r) {
    for (int c = std::min(n - 1, r + 2); c >= std::max(0, r - 2); --c)
      s.cols.push_back(c);
    s.row_ptr.push_back(s.cols.size());
  }
  return s;
}

/// The values of `A` in the structure's order.
std::vector<double> values_of(const RootCsr& s, const Eigen::MatrixXd& A) {
  std::vector<double> v;
  for (int r = 0; r < n; ++r)
    for (std::size_t k = s.row_ptr[r]; k < s.row_ptr[r + 1]; ++k)
      v.push_back(A(r, static_cast<int>(s.cols[k])));
  return v;
}

/// A symmetric band matrix with diagonal `d` and off-diagonals -1 (first) and 0.25 (second).
Eigen::MatrixXd band(const Eigen::VectorXd& d) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int r = 0; r < n; ++r) {
    A(r, r) = d(r);
    if (r + 1 < n) A(r, r + 1) = A(r + 1, r) = -1.0;
    if (r + 2 < n) A(r, r + 2) = A(r + 2, r) = 0.25;
  }
  return A;
}

/// Factorises A with `lu`, solves A x = b for a fixed b, and returns the relative difference
/// to the dense solution.
double solve_error(RootFactorization& lu, const RootCsr& s, const Eigen::MatrixXd& A) {
  lu.factorize(values_of(s, A));
  Eigen::VectorXd b(n), x(n);
  for (int i = 0; i < n; ++i)
    b(i) = 1.0 + 0.5 * i;
  lu.solve(b.data(), x.data());
  const Eigen::VectorXd exact = A.fullPivLu().solve(b);
  return (x - exact).norm() / exact.norm();
}

TEST(SymmetricPairs, PairsUnsortedRowsAndAveragesTheLowerTriangle) {
  const RootCsr s = band_structure();
  const SymmetricPairs pairs(s);
  ASSERT_TRUE(pairs.usable());
  ASSERT_EQ(pairs.lower_rows().size(), 6u + 5u + 4u); // diagonal and two sub-diagonals
  Eigen::MatrixXd A = band(Eigen::VectorXd::Constant(n, 4.0));
  A(3, 1) += 0.5; // a_31 = 0.75 against a_13 = 0.25
  std::vector<double> lower;
  pairs.lower_values(values_of(s, A), lower);
  for (std::size_t i = 0; i < lower.size(); ++i) {
    const int r = pairs.lower_rows()[i], c = pairs.lower_cols()[i];
    EXPECT_GE(r, c);
    EXPECT_EQ(lower[i], 0.5 * (A(r, c) + A(c, r))) << r << ", " << c;
  }
  EXPECT_FALSE(pairs.symmetric(values_of(s, A), 1e-13));
}

// The test is relative to the larger of the two rows' diagonals (4 here): an asymmetry of
// 1e-15 x 4 is round-off, 1e-12 x 4 is not at the tolerance 1e-13.
TEST(SymmetricPairs, SymmetryIsJudgedAgainstTheDiagonals) {
  const RootCsr s = band_structure();
  const SymmetricPairs pairs(s);
  Eigen::MatrixXd A = band(Eigen::VectorXd::Constant(n, 4.0));
  EXPECT_TRUE(pairs.symmetric(values_of(s, A), 1e-13));
  A(4, 2) += 4e-15;
  EXPECT_TRUE(pairs.symmetric(values_of(s, A), 1e-13));
  A(4, 2) += 4e-12;
  EXPECT_FALSE(pairs.symmetric(values_of(s, A), 1e-13));
}

TEST(SymmetricPairs, AnEntryWithoutItsTransposeIsNotUsable) {
  RootCsr s = band_structure();
  // Row 0 gets column 5; row 5 has no column 0.
  s.cols.insert(s.cols.begin(), 5);
  for (std::size_t r = 1; r < s.row_ptr.size(); ++r)
    ++s.row_ptr[r];
  EXPECT_FALSE(SymmetricPairs(s).usable());
  auto lu = make_mumps_factorization("");
  lu->analyse(s);
  Eigen::MatrixXd A = band(Eigen::VectorXd::Constant(n, 4.0));
  A(0, 5) = 0.1;
  EXPECT_LE(solve_error(*lu, s, A), 1e-12);
  EXPECT_EQ(std::string(lu->method()), "LU");
}

// Positive definite, then indefinite, then unsymmetric values on one structure: each is
// solved right, and the kind only moves towards LU.
TEST(MumpsFactorization, TheKindFollowsTheValuesTowardsLu) {
  const RootCsr s = band_structure();
  auto lu = make_mumps_factorization("");
  lu->analyse(s);
  const Eigen::MatrixXd spd = band(Eigen::VectorXd::Constant(n, 4.0)); // diagonally dominant
  EXPECT_LE(solve_error(*lu, s, spd), 1e-12);
  EXPECT_EQ(std::string(lu->method()), "Cholesky-type LDL^T");

  Eigen::VectorXd d(n);
  d << 4.0, -3.0, 4.0, 4.0, -2.5, 3.0; // two negative eigenvalues
  const Eigen::MatrixXd indefinite = band(d);
  ASSERT_GT(std::abs(indefinite.determinant()), 1.0);
  EXPECT_LE(solve_error(*lu, s, indefinite), 1e-12);
  EXPECT_EQ(std::string(lu->method()), "LDL^T");

  EXPECT_LE(solve_error(*lu, s, spd), 1e-12); // stays with pivoting
  EXPECT_EQ(std::string(lu->method()), "LDL^T");

  Eigen::MatrixXd unsymmetric = spd;
  unsymmetric(2, 0) = 0.0; // a one-way coupling, as friction gives
  unsymmetric(1, 2) = -0.5;
  EXPECT_LE(solve_error(*lu, s, unsymmetric), 1e-12);
  EXPECT_EQ(std::string(lu->method()), "LU");

  EXPECT_LE(solve_error(*lu, s, spd), 1e-12); // LU from now on
  EXPECT_EQ(std::string(lu->method()), "LU");
}

// An indefinite matrix from the start goes straight to pivoting (the factorisation without
// it meets a negative pivot and is redone), and a singular one still fails, naming MUMPS'
// diagnosis.
TEST(MumpsFactorization, IndefiniteIsRedoneWithPivotingAndSingularFails) {
  const RootCsr s = band_structure();
  auto lu = make_mumps_factorization("");
  lu->analyse(s);
  const Eigen::MatrixXd negative = -band(Eigen::VectorXd::Constant(n, 4.0));
  EXPECT_LE(solve_error(*lu, s, negative), 1e-12);
  EXPECT_EQ(std::string(lu->method()), "LDL^T");

  auto fresh = make_mumps_factorization("");
  fresh->analyse(s);
  std::string message;
  try {
    fresh->factorize(std::vector<double>(s.cols.size(), 0.0));
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("singular"), std::string::npos) << message;
}

} // namespace
} // namespace bipot::detail
