#include "fem/mesh/node_grid.hpp"

#include <cmath>

namespace bipot {

NodeGrid::NodeGrid(const Mesh& mesh, const std::vector<Index>& ids, double tol) {
  // The lower bounds keep |x| / h well inside the int64 range for coordinates far from the
  // origin, and h > 0 when tol is 0.
  double extent = 0.0;
  for (const auto& x : mesh.nodes)
    for (double v : x)
      if (std::isfinite(v)) extent = std::max(extent, std::abs(v));
  h_ = std::max({2.0 * tol, extent * 1e-15, std::numeric_limits<double>::min()});
  sorted_.reserve(ids.size());
  for (Index n : ids)
    sorted_.emplace_back(key(mesh.nodes[n]), n);
  std::sort(sorted_.begin(), sorted_.end());
}

NodeGrid::Key NodeGrid::key(const std::array<double, 3>& x) const {
  return {static_cast<std::int64_t>(std::floor(x[0] / h_)),
          static_cast<std::int64_t>(std::floor(x[1] / h_)),
          static_cast<std::int64_t>(std::floor(x[2] / h_))};
}

} // namespace bipot
