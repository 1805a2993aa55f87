#pragma once
// 1D Poisson chain with a closed-form solution, and error norms, for the linalg tests.

#include "fem/linalg/communicator.hpp"
#include "fem/linalg/distributed_vector.hpp"
#include "fem/linalg/dof_distribution.hpp"
#include "fem/linalg/sparse_matrix.hpp"
#include "fem/linalg/sparsity_pattern.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace bipot::test {

/// -u'' = 1 on (0, 1), u(0) = u(1) = 0, linear elements: the nodal values are exactly
/// u(x) = x (1 - x) / 2. Node k sits at x = k h; interior node k carries DOF k - 1, the two
/// fixed end nodes carry DOF -1 (skipped). Cell e (nodes e, e+1) is assembled by the owner
/// of its left DOF, so the cells at a rank boundary write into the next rank's rows.
/// A "tie" spring joins DOFs tie_a and tie_b = n - 1 - tie_a, at mirror positions x and 1 - x:
/// by symmetry it is unstretched by the exact solution, which therefore still holds. It is
/// declared as extra couplings and assembled by the last rank, so on 2 ranks it adds to a
/// row owned by rank 0 from rank 1.
struct Chain {
  int num_elements = 100;
  Index tie_a = 4;
  double tie_stiffness = 100.0; // = 1/h, an element's stiffness
  /// The tie pulls DOF tie_a towards tie_b only: row tie_a gets k (u_a - u_b), row tie_b
  /// nothing, as a one-sided contact or friction tangent does (nonsymmetric). The pattern
  /// keeps both rows' couplings either way; unused entries are stored zeros.
  bool one_way_tie = false;

  Index num_dofs() const { return num_elements - 1; }
  Index tie_b() const { return num_dofs() - 1 - tie_a; }
  double h() const { return 1.0 / num_elements; }
  DofDistribution distribution() const { return DofDistribution(num_dofs(), 1); }
  std::array<Index, 2> cell_dofs(int e) const {
    const Index left = e - 1, right = e;
    return {left, right < num_dofs() ? right : -1};
  }
  bool assembles_cell(const DofDistribution& d, int e) const {
    const Index left = std::max<Index>(e - 1, 0);
    return d.owner_of_dof(std::min(left, num_dofs() - 1)) == d.rank();
  }
  bool assembles_tie(const DofDistribution& d) const { return d.rank() == d.size() - 1; }

  SparsityPattern pattern(const DofDistribution& d) const {
    SparsityPattern p;
    for (int e = 0; e < num_elements; ++e)
      if (assembles_cell(d, e)) p.add_cell(cell_dofs(e).data(), 2);
    if (assembles_tie(d)) {
      const std::vector<Index> both = {tie_a, tie_b()};
      p.add_coupling(tie_a, both);
      p.add_coupling(tie_b(), both);
    }
    return p;
  }

  /// Element e gets stiffness factor * stiffness(e) / h.
  void assemble(
      SparseMatrix& A, double factor = 1.0,
      const std::function<double(int)>& stiffness = [](int) { return 1.0; }) const {
    const auto& d = A.distribution();
    A.set_zero();
    for (int e = 0; e < num_elements; ++e) {
      if (!assembles_cell(d, e)) continue;
      const double k = factor * stiffness(e) / h();
      const double ke[4] = {k, -k, -k, k};
      A.add_dense(cell_dofs(e).data(), 2, ke);
    }
    if (assembles_tie(d)) {
      const Index dofs[2] = {tie_a, tie_b()};
      const double k = factor * tie_stiffness;
      const double ke[4] = {k, -k, -k, k};
      A.add_block(dofs, one_way_tie ? 1 : 2, dofs, 2, ke);
    }
    A.finish_assembly();
  }

  /// Consistent load of f = 1: h/2 to each node of each cell.
  void assemble_rhs(DistributedVector& b) const {
    const auto& d = b.distribution();
    b.set_zero();
    for (int e = 0; e < num_elements; ++e) {
      if (!assembles_cell(d, e)) continue;
      for (Index dof : cell_dofs(e))
        b.add(dof, 0.5 * h());
    }
    b.finish_assembly();
  }

  double exact(Index dof) const {
    const double x = static_cast<double>(dof + 1) * h();
    return 0.5 * x * (1.0 - x);
  }
};

/// ||x - exact|| / ||exact|| over all ranks.
inline double relative_error(const DistributedVector& x,
                             const std::function<double(Index)>& exact) {
  double num = 0, den = 0;
  for (Index i = 0; i < x.num_owned(); ++i) {
    const double e = exact(x.first_owned() + i);
    num += (x.owned_values()[i] - e) * (x.owned_values()[i] - e);
    den += e * e;
  }
  return std::sqrt(sum_all(num) / sum_all(den));
}

/// ||x - y|| / ||y||.
inline double relative_difference(const DistributedVector& x, const DistributedVector& y) {
  DistributedVector diff(x);
  diff.axpy(-1.0, y);
  return diff.norm2() / y.norm2();
}

} // namespace bipot::test
