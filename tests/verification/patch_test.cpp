// Patch tests: on distorted meshes, every element type and kinematics reproduces a linear
// displacement field (constant stress) to round-off when the field is prescribed on the
// boundary. Assembly-level (no YAML): element + material + assembly + distributed solve.
#include "fem/assembly/constraints.hpp"
#include "fem/assembly/dof_map.hpp"
#include "fem/assembly/solid_assembler.hpp"
#include "fem/linalg/distributed_vector.hpp"
#include "fem/linalg/dof_distribution.hpp"
#include "fem/linalg/linear_solver.hpp"
#include "fem/linalg/sparse_matrix.hpp"
#include "fem/mesh/cell_facets.hpp"
#include "fem/mesh/structured_mesh.hpp"
#include "materials/linear_elastic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace bipot {
namespace {

// Moves interior corner nodes by a smooth, non-affine perturbation and puts mid-edge nodes
// back at the middle of their (straight) edges, so cells are genuinely distorted.
void distort(Mesh& mesh, double amount) {
  std::set<Index> boundary;
  for (const auto& f : boundary_facets(mesh))
    boundary.insert(f.nodes.begin(), f.nodes.end());
  std::vector<bool> corner(mesh.num_nodes(), false);
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const int corners = cell_order(mesh.cell_types[c]) == 2
                            ? (mesh.cell_types[c] == CellType::Tri6 ? 3 : 4)
                            : mesh.cell_num_nodes(c);
    for (int a = 0; a < corners; ++a)
      corner[mesh.cell(c)[a]] = true;
  }
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    if (boundary.count(n) || !corner[n]) continue;
    auto& x = mesh.nodes[n];
    const double s = std::sin(7.3 * x[0] + 3.1 * x[1] + 1.7 * x[2]);
    const double t = std::cos(5.9 * x[0] - 2.3 * x[1] + 0.7 * x[2]);
    x[0] += amount * s;
    x[1] += amount * t;
    if (mesh.dim == 3) x[2] += amount * s * t;
  }
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const CellType type = mesh.cell_types[c];
    if (cell_order(type) != 2) continue;
    const int nc = type == CellType::Tri6 ? 3 : 4;
    for (int e = 0; e < nc; ++e) {
      const Index a = mesh.cell(c)[e], b = mesh.cell(c)[(e + 1) % nc], m = mesh.cell(c)[nc + e];
      for (int i = 0; i < 3; ++i)
        mesh.nodes[m][i] = 0.5 * (mesh.nodes[a][i] + mesh.nodes[b][i]);
    }
  }
}

struct PatchCase {
  CellType cell;
  Kinematics kin;
  Diagonals diagonals = Diagonals::Right; ///< triangle split of the quads (2D triangles)
};

std::string case_name(const testing::TestParamInfo<PatchCase>& info) {
  const std::string split = info.param.diagonals == Diagonals::Right
                                ? ""
                                : std::string("_") + to_string(info.param.diagonals);
  return to_string(info.param.cell) + "_" + to_string(info.param.kin) + split;
}

/// The 2D patch: [1, 2] x [0, 1] in 4 x 4 quads (split into triangles as `diagonals` says).
Mesh patch_2d(CellType cell, Diagonals diagonals) {
  BlockMeshSpec spec;
  spec.x = {{1.0, 2.0}, {4}, {}};
  spec.y = {{0.0, 1.0}, {4}, {}};
  spec.cell = cell;
  spec.diagonals = diagonals;
  spec.block_regions = {"body"};
  return make_block_mesh(spec);
}

class PatchTest : public testing::TestWithParam<PatchCase> {};

TEST_P(PatchTest, LinearFieldIsReproduced) {
  const auto [cell, kin, diagonals] = GetParam();
  const int dim = spatial_dim(kin);
  // Axisymmetric: r in [1, 2] keeps the patch off the axis.
  Mesh mesh =
      dim == 2 ? patch_2d(cell, diagonals) : make_box(0.0, 1.0, 3, 0.0, 1.0, 3, 0.0, 1.0, 3, cell);
  distort(mesh, dim == 2 ? 0.04 : 0.03);

  // Exact fields with constant strain. Axisymmetric: u_r = a r, u_z = d z + e is the
  // constant-strain field in equilibrium: eps_rr = eps_tt removes (s_rr - s_tt)/r from the
  // radial equation, and no shear removes tau_rz / r from the axial one.
  auto exact = [&](const std::array<double, 3>& x, int i) {
    if (kin == Kinematics::Axisymmetric) return i == 0 ? 2e-3 * x[0] : -3e-3 * x[1] + 0.5e-3;
    const double A[3][3] = {{1e-3, 2e-3, -1e-3}, {-0.5e-3, 3e-3, 1.5e-3}, {0.7e-3, -2e-3, 1e-3}};
    const double c[3] = {1e-3, -2e-3, 3e-3};
    double v = c[i];
    for (int j = 0; j < dim; ++j)
      v += A[i][j] * x[j];
    return v;
  };

  LinearElastic steel({2.0e8, 0.3});
  DofMap dofs(mesh.num_nodes(), dim);
  DofDistribution dist(mesh.num_nodes(), dim);
  std::vector<Index> owned_cells;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const Index* nodes = mesh.cell(c);
    if (dist.owner_of_node(*std::min_element(nodes, nodes + mesh.cell_num_nodes(c))) == dist.rank())
      owned_cells.push_back(c);
  }
  SolidAssembler solid(mesh, kin, dofs, {&steel}, owned_cells);
  SparsityPattern pattern;
  solid.add_to_pattern(pattern);
  SparseMatrix K(dist, pattern);
  DistributedVector R(dist), du(dist);

  Constraints constraints;
  std::set<Index> boundary;
  for (const auto& f : boundary_facets(mesh))
    boundary.insert(f.nodes.begin(), f.nodes.end());
  for (Index n : boundary)
    for (int i = 0; i < dim; ++i)
      constraints.set(dofs.dof(n, i), exact(mesh.nodes[n], i));

  std::vector<double> u(dofs.num_dofs(), 0.0);
  K.set_zero();
  R.set_zero();
  solid.assemble(u, constraints, &K, R);
  K.finish_assembly();
  R.finish_assembly();
  LinearSolverOptions direct;
  direct.method = "direct";
  LinearSolver solver(direct);
  solver.setup(K);
  du.set_zero();
  solver.solve(R, du);
  const std::vector<double> sol = du.gather_all();

  // Round-off scale: displacements ~1e-3, conditioning of a 2e8 kPa stiffness on
  // O(100) DOFs; 1e-10 relative is the criterion.
  double max_err = 0, max_u = 0;
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    for (int i = 0; i < dim; ++i) {
      max_err = std::max(max_err, std::abs(sol[dofs.dof(n, i)] - exact(mesh.nodes[n], i)));
      max_u = std::max(max_u, std::abs(exact(mesh.nodes[n], i)));
    }
  EXPECT_LT(max_err / max_u, 1e-10) << "max error " << max_err;

  // The stress is the constant elastic stress of the exact strain at every cell.
  solid.commit();
  std::vector<double> strain, stress;
  solid.cell_averages(sol, strain, stress);
  const int nv = voigt_size(dim);
  Voigt eps = Voigt::Zero(nv);
  if (kin == Kinematics::Axisymmetric)
    eps << 2e-3, -3e-3, 2e-3, 0.0;
  else if (dim == 2)
    eps << 1e-3, 3e-3, 0.0, 2e-3 - 0.5e-3;
  else
    eps << 1e-3, 3e-3, 1e-3, 2e-3 - 0.5e-3, 1.5e-3 - 2e-3, -1e-3 + 0.7e-3;
  const Voigt sigma = steel.elasticity_matrix(nv) * eps;
  for (std::size_t k = 0; k < solid.owned_cells().size(); ++k)
    for (int i = 0; i < nv; ++i)
      EXPECT_NEAR(stress[k * nv + i], sigma(i), 1e-9 * sigma.norm())
          << "cell " << k << " comp " << i;
}

INSTANTIATE_TEST_SUITE_P(AllElements, PatchTest,
                         testing::Values(PatchCase{CellType::Tri3, Kinematics::PlaneStrain},
                                         PatchCase{CellType::Tri6, Kinematics::PlaneStrain},
                                         PatchCase{CellType::Quad4, Kinematics::PlaneStrain},
                                         PatchCase{CellType::Quad8, Kinematics::PlaneStrain},
                                         PatchCase{CellType::Tri3, Kinematics::Axisymmetric},
                                         PatchCase{CellType::Tri6, Kinematics::Axisymmetric},
                                         PatchCase{CellType::Quad4, Kinematics::Axisymmetric},
                                         PatchCase{CellType::Quad8, Kinematics::Axisymmetric},
                                         PatchCase{CellType::Tet4, Kinematics::ThreeD},
                                         PatchCase{CellType::Hex8, Kinematics::ThreeD}),
                         case_name);

// Every triangle split of the blocks generator passes it too.
INSTANTIATE_TEST_SUITE_P(
    TriangleDiagonals, PatchTest,
    testing::Values(PatchCase{CellType::Tri3, Kinematics::PlaneStrain, Diagonals::Left},
                    PatchCase{CellType::Tri3, Kinematics::PlaneStrain, Diagonals::Alternating},
                    PatchCase{CellType::Tri3, Kinematics::PlaneStrain, Diagonals::Crossed},
                    PatchCase{CellType::Tri3, Kinematics::Axisymmetric, Diagonals::Crossed},
                    PatchCase{CellType::Tri6, Kinematics::PlaneStrain, Diagonals::Left},
                    PatchCase{CellType::Tri6, Kinematics::Axisymmetric, Diagonals::Alternating}),
    case_name);

} // namespace
} // namespace bipot
