#pragma once
/// Finding the nodes near a point without an O(n²) scan: nodes bucketed on a regular grid.

#include "fem/core/types.hpp"
#include "fem/mesh/mesh.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace bipot {

class NodeGrid {
public:
  /// Buckets the nodes `ids` of `mesh` (finite coordinates) for searches within `tol` (m,
  /// >= 0): buckets are no smaller than 2 tol, so that every node within `tol` of a point lies
  /// in one of the 27 buckets around it. O(n log n).
  NodeGrid(const Mesh& mesh, const std::vector<Index>& ids, double tol);

  /// Calls f(id) for every bucketed node in the 27 buckets around `x` (finite): every node
  /// within `tol` of it, and some farther ones, which the caller sorts out.
  template <class F> void for_each_near(const std::array<double, 3>& x, F&& f) const {
    const Key k = key(x);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const Key nk{k[0] + dx, k[1] + dy, k[2] + dz};
          auto it = std::lower_bound(sorted_.begin(), sorted_.end(),
                                     std::make_pair(nk, std::numeric_limits<Index>::min()));
          for (; it != sorted_.end() && it->first == nk; ++it)
            f(it->second);
        }
  }

private:
  using Key = std::array<std::int64_t, 3>;
  Key key(const std::array<double, 3>& x) const;

  double h_ = 1; ///< bucket size (m)
  std::vector<std::pair<Key, Index>> sorted_;
};

} // namespace bipot
