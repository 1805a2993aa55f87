// LinearBulkResidual against the cell loop it replaces: for a linear bulk with an initial
// stress, prescribed increments on some constrained DOFs and zero on others, the residual
// from products with the eliminated K and the removed entries equals
// SolidAssembler::assemble(u, c, nullptr, R) on every row (free rows −f_int(u + du_c), the
// constrained ones diag(K) du_c), in 2D, axisymmetric and 3D, at 1 and 2 ranks; and again
// after the initial stress changed. So does the unconstrained internal force of every row
// (the reactions), which is refused for supports other than K's. And SolidAssembler::residual
// (a line search's trial, the constrained DOFs held) equals the loop with those held values.
#include "fem/assembly/constraints.hpp"
#include "fem/assembly/dof_map.hpp"
#include "fem/assembly/linear_bulk_residual.hpp"
#include "fem/assembly/solid_assembler.hpp"
#include "fem/linalg/distributed_vector.hpp"
#include "fem/linalg/dof_distribution.hpp"
#include "fem/linalg/sparse_matrix.hpp"
#include "fem/linalg/sparsity_pattern.hpp"
#include "fem/mesh/structured_mesh.hpp"
#include "materials/linear_elastic.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace bipot {
namespace {

struct Case {
  CellType cell;
  Kinematics kin;
};

class LinearBulkResidualTest : public testing::TestWithParam<Case> {};

double largest_difference(const DistributedVector& a, const DistributedVector& b, double* scale) {
  const std::vector<double> x = a.gather_all(), y = b.gather_all();
  double diff = 0;
  *scale = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    diff = std::max(diff, std::abs(x[i] - y[i]));
    *scale = std::max(*scale, std::abs(y[i]));
  }
  return diff;
}

TEST_P(LinearBulkResidualTest, EqualsTheCellLoop) {
  const auto [cell, kin] = GetParam();
  const int dim = spatial_dim(kin);
  Mesh mesh;
  if (dim == 2) {
    BlockMeshSpec spec;
    spec.x = {{0.5, 2.0}, {5}, {}}; // off the axis when axisymmetric
    spec.y = {{0.0, 1.0}, {4}, {}};
    spec.cell = cell;
    spec.block_regions = {"body"};
    mesh = make_block_mesh(spec);
  } else {
    mesh = make_box(0.0, 1.0, 3, 0.0, 1.0, 3, 0.0, 1.0, 2, cell);
  }
  const LinearElastic soil({3.0e4, 0.33});
  const DofMap dofs(mesh.num_nodes(), dim);
  const DofDistribution dist(mesh.num_nodes(), dim);
  std::vector<Index> owned_cells;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const Index* nodes = mesh.cell(c);
    if (dist.owner_of_node(*std::min_element(nodes, nodes + mesh.cell_num_nodes(c))) == dist.rank())
      owned_cells.push_back(c);
  }
  SolidAssembler solid(mesh, kin, dofs, {&soil}, owned_cells);
  const int nv = voigt_size(dim);
  auto stress = [nv](double scale) {
    return [nv, scale](const std::array<double, 3>& x, int) {
      Voigt s = Voigt::Zero(nv);
      for (int i = 0; i < nv; ++i)
        s(i) = scale * (10.0 + 3.0 * i) * (1.0 + x[1] + 0.5 * x[0] * x[0]);
      return s;
    };
  };
  solid.set_initial_stress(stress(-1.0));
  SparsityPattern pattern;
  solid.add_to_pattern(pattern);
  SparseMatrix K(dist, pattern);

  // Constrained: the bottom (held, du = 0) and the side x = max (moved); u smooth elsewhere.
  double x_max = 0;
  for (const auto& x : mesh.nodes)
    x_max = std::max(x_max, x[0]);
  Constraints constraints;
  std::vector<double> u(dofs.num_dofs());
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const auto& x = mesh.nodes[n];
    for (int i = 0; i < dim; ++i) {
      u[dofs.dof(n, i)] = 1e-3 * std::sin(1.3 * x[0] + 0.7 * (i + 1) * x[1] + 0.3 * x[2]);
      if (x[1] == 0.0) constraints.set(dofs.dof(n, i), 0.0);
      if (x[0] == x_max) constraints.set(dofs.dof(n, i), 2e-4 * (i + 1) * (1.0 + x[1]));
    }
  }
  // The product form is set up at another state with the same constrained DOFs (as at a
  // refactorisation, increments earlier), then used at u.
  LinearBulkResidual product(dist);
  {
    Constraints first = constraints;
    for (const auto& kv : constraints.values())
      first.set(kv.first, 0.5 * kv.second);
    DistributedVector R0(dist);
    K.set_zero();
    R0.set_zero();
    product.assemble(solid, std::vector<double>(u.size(), 0.0), first, K, R0);
    K.finish_assembly();
    R0.finish_assembly();
  }
  ASSERT_TRUE(product.ready());
  for (int round = 0; round < 2; ++round) {
    if (round == 1) { // a displacement reset or a loaded state changes σ0
      solid.set_initial_stress(stress(-2.5));
      product.initial_stress_changed();
    }
    DistributedVector by_loop(dist), by_product(dist);
    by_loop.set_zero();
    solid.assemble(u, constraints, nullptr, by_loop);
    by_loop.finish_assembly();
    by_product.set_zero();
    product.residual(solid, K, u, constraints, by_product);
    by_product.finish_assembly();
    double scale = 0;
    const double diff = largest_difference(by_product, by_loop, &scale);
    // Two summation orders of the same O(scale) terms: round-off, ~1e-15 relative.
    EXPECT_LE(diff, 1e-12 * scale) << "round " << round << ": " << diff << " of " << scale;
    EXPECT_GT(scale, 1.0); // the initial stress and the increments make it non-trivial

    // The unconstrained f_int(u) on every row (the reactions after an increment).
    DistributedVector f_loop(dist), f_product(dist);
    f_loop.set_zero();
    solid.internal_force(u, f_loop);
    f_loop.finish_assembly();
    f_product.set_zero();
    EXPECT_TRUE(product.internal_force(solid, K, u, constraints, f_product));
    f_product.finish_assembly();
    const double f_diff = largest_difference(f_product, f_loop, &scale);
    EXPECT_LE(f_diff, 1e-12 * scale) << "round " << round << ": " << f_diff << " of " << scale;
    EXPECT_GT(scale, 1.0);
  }
  // A line search's trial residual (SolidAssembler::residual: the constrained DOFs held, no
  // tangent products) is the cell loop's residual for those held values, exactly.
  Constraints held;
  for (const auto& kv : constraints.values())
    held.set(kv.first, 0.0);
  DistributedVector by_assemble(dist), by_residual(dist);
  by_assemble.set_zero();
  solid.assemble(u, held, nullptr, by_assemble);
  by_assemble.finish_assembly();
  by_residual.set_zero();
  solid.residual(u, held, by_residual);
  by_residual.finish_assembly();
  double held_scale = 0;
  EXPECT_EQ(largest_difference(by_residual, by_assemble, &held_scale), 0.0);
  EXPECT_GT(held_scale, 1.0);
  // Supports other than those K was assembled with: refused, nothing added.
  Constraints fewer = constraints;
  fewer.clear();
  for (const auto& kv : constraints.values())
    if (kv.second == 0.0) fewer.set(kv.first, 0.0);
  DistributedVector untouched(dist);
  untouched.set_zero();
  EXPECT_FALSE(product.internal_force(solid, K, u, fewer, untouched));
  untouched.finish_assembly();
  EXPECT_EQ(untouched.norm2(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Kinematics, LinearBulkResidualTest,
                         testing::Values(Case{CellType::Quad4, Kinematics::PlaneStrain},
                                         Case{CellType::Quad8, Kinematics::Axisymmetric},
                                         Case{CellType::Hex8, Kinematics::ThreeD}),
                         [](const testing::TestParamInfo<Case>& info) {
                           return to_string(info.param.cell) + "_" + to_string(info.param.kin);
                         });

} // namespace
} // namespace bipot
