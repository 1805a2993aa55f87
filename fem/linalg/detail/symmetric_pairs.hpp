#pragma once
/// Internal to fem/linalg: the entries of a gathered sparse matrix paired with their
/// transposes, so that a symmetric matrix can be factorised as LDLᵀ from its lower triangle
/// (half the work of an LU) while the same structure also serves unsymmetric ones.

#include "fem/linalg/detail/root_factorization.hpp"

#include <cstdint>
#include <vector>

namespace bipot::detail {

/// Built once per structure. Which values are symmetric is decided at each factorisation:
/// the structure of an FE matrix is symmetric, its values are or are not (a plastic tangent
/// is where the flow is associated; friction makes it unsymmetric).
class SymmetricPairs {
public:
  /// Pairs every entry (r, c) of `structure` with (c, r). usable() is false if some entry
  /// has no transpose, or if the matrix is too large for 32-bit entry positions. The lower
  /// triangle's indices count from `index_base` (1 for MUMPS, which then reads them as they
  /// are).
  explicit SymmetricPairs(const RootCsr& structure, int index_base = 0);

  bool usable() const { return usable_; }
  /// The lower triangle (r ≥ c), from index_base, in the order of lower_values().
  const std::vector<int>& lower_rows() const { return rows_; }
  const std::vector<int>& lower_cols() const { return cols_; }

  /// Whether |a_rc − a_cr| ≤ tolerance · max(|a_rr|, |a_cc|) for every pair: the rows' own
  /// scale, since an off-diagonal entry can be small by cancellation and still carry the
  /// round-off of the element matrices summed into it. `values` in the structure's order.
  bool symmetric(const std::vector<double>& values, double tolerance) const;
  /// (a_rc + a_cr) / 2 for each lower entry: the nearest symmetric matrix.
  void lower_values(const std::vector<double>& values, std::vector<double>& out) const;

private:
  bool usable_ = false;
  int base_ = 0;
  std::vector<int> rows_, cols_;
  std::vector<std::uint32_t> entry_, transpose_; ///< positions of (r, c) and (c, r)
  std::vector<std::int64_t> diagonal_;           ///< position of (r, r) per row, or -1
};

} // namespace bipot::detail
