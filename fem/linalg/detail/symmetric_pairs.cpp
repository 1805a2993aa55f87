#include "fem/linalg/detail/symmetric_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bipot::detail {

SymmetricPairs::SymmetricPairs(const RootCsr& s, int index_base) : base_(index_base) {
  const std::size_t n = s.size();
  const std::size_t nnz = s.cols.size();
  if (nnz >= std::numeric_limits<std::uint32_t>::max() ||
      n >= static_cast<std::size_t>(std::numeric_limits<int>::max()))
    return;
  // Each row's entry positions sorted by column: the rows of a gathered matrix are in the
  // owners' local column order, not ascending. (Positions only: 4 bytes per entry.)
  std::vector<std::uint32_t> sorted(nnz);
  for (std::size_t k = 0; k < nnz; ++k)
    sorted[k] = static_cast<std::uint32_t>(k);
  const auto by_column = [&](std::uint32_t a, std::uint32_t b) { return s.cols[a] < s.cols[b]; };
  for (std::size_t r = 0; r < n; ++r)
    std::sort(sorted.begin() + static_cast<std::ptrdiff_t>(s.row_ptr[r]),
              sorted.begin() + static_cast<std::ptrdiff_t>(s.row_ptr[r + 1]), by_column);
  const auto find = [&](std::size_t row, long long col) -> std::int64_t {
    const auto first = sorted.begin() + static_cast<std::ptrdiff_t>(s.row_ptr[row]);
    const auto last = sorted.begin() + static_cast<std::ptrdiff_t>(s.row_ptr[row + 1]);
    const auto it = std::lower_bound(first, last, col,
                                     [&](std::uint32_t k, long long c) { return s.cols[k] < c; });
    return it != last && s.cols[*it] == col ? static_cast<std::int64_t>(*it) : -1;
  };
  diagonal_.assign(n, -1);
  for (std::size_t r = 0; r < n; ++r) {
    diagonal_[r] = find(r, static_cast<long long>(r));
    for (std::size_t k = s.row_ptr[r]; k < s.row_ptr[r + 1]; ++k) {
      const long long c = s.cols[k];
      if (c < 0 || static_cast<std::size_t>(c) >= n) return;
      const std::int64_t t = find(static_cast<std::size_t>(c), static_cast<long long>(r));
      if (t < 0) return; // not structurally symmetric: every matrix on it is unsymmetric
      if (c > static_cast<long long>(r)) continue;
      rows_.push_back(static_cast<int>(r) + base_);
      cols_.push_back(static_cast<int>(c) + base_);
      entry_.push_back(static_cast<std::uint32_t>(k));
      transpose_.push_back(static_cast<std::uint32_t>(t));
    }
  }
  usable_ = true;
}

bool SymmetricPairs::symmetric(const std::vector<double>& values, double tolerance) const {
  if (!usable_) return false;
  const auto diagonal = [&](int r) {
    const std::int64_t d = diagonal_[r - base_];
    return d < 0 ? 0.0 : std::abs(values[static_cast<std::size_t>(d)]);
  };
  for (std::size_t i = 0; i < entry_.size(); ++i) {
    const double gap = std::abs(values[entry_[i]] - values[transpose_[i]]);
    if (!(gap <= tolerance * std::max(diagonal(rows_[i]), diagonal(cols_[i])))) return false;
  }
  return true;
}

void SymmetricPairs::lower_values(const std::vector<double>& values,
                                  std::vector<double>& out) const {
  out.resize(entry_.size());
  for (std::size_t i = 0; i < entry_.size(); ++i)
    out[i] = 0.5 * (values[entry_[i]] + values[transpose_[i]]);
}

} // namespace bipot::detail
