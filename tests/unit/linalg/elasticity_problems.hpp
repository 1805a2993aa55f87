#pragma once
// Small plane-strain and axisymmetric elasticity systems for the linalg solver tests.

#include "fem/linalg/distributed_vector.hpp"
#include "fem/linalg/dof_distribution.hpp"
#include "fem/linalg/sparse_matrix.hpp"
#include "fem/linalg/sparsity_pattern.hpp"

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <vector>

namespace bipot::test {

/// Plane-strain bilinear quadrilateral of size a x b (nodes counter-clockwise from the
/// lower-left corner), 2x2 Gauss points, E and nu; DOFs (u_x, u_y) per node.
inline Eigen::Matrix<double, 8, 8> plane_strain_quad(double a, double b, double E, double nu) {
  Eigen::Matrix3d D;
  const double c = E / ((1 + nu) * (1 - 2 * nu));
  D << c * (1 - nu), c * nu, 0, c * nu, c * (1 - nu), 0, 0, 0, c * (1 - 2 * nu) / 2;
  const double xi_n[4] = {-1, 1, 1, -1}, eta_n[4] = {-1, -1, 1, 1};
  const double g = 1.0 / std::sqrt(3.0);
  Eigen::Matrix<double, 8, 8> K = Eigen::Matrix<double, 8, 8>::Zero();
  for (double xi : {-g, g})
    for (double eta : {-g, g}) {
      Eigen::Matrix<double, 3, 8> B = Eigen::Matrix<double, 3, 8>::Zero();
      for (int n = 0; n < 4; ++n) {
        const double dx = xi_n[n] * (1 + eta * eta_n[n]) / 4 * 2 / a;
        const double dy = eta_n[n] * (1 + xi * xi_n[n]) / 4 * 2 / b;
        B(0, 2 * n) = dx;
        B(1, 2 * n + 1) = dy;
        B(2, 2 * n) = dy;
        B(2, 2 * n + 1) = dx;
      }
      K += B.transpose() * D * B * (a * b / 4); // Gauss weights 1, det J = ab/4
    }
  return K;
}

/// Plane-strain block [0, nx a] x [0, ny b], clamped on x = 0, loaded on x = nx a by a
/// traction (1, 0.5). Free node (i, j), i >= 1, has id (i-1)(ny+1) + j. Cell (i, j) is
/// assembled by the owner of its node (i+1, j).
struct ClampedBlock {
  int nx = 12, ny = 16;
  double a = 1.0, b = 1.0, E = 1.0, nu = 0.3;

  Index node_id(int i, int j) const { return i == 0 ? -1 : Index(i - 1) * (ny + 1) + j; }
  Index num_nodes() const { return Index(nx) * (ny + 1); }
  DofDistribution distribution() const { return DofDistribution(num_nodes(), 2); }
  std::array<Index, 8> cell_dofs(int i, int j) const {
    const Index n[4] = {node_id(i, j), node_id(i + 1, j), node_id(i + 1, j + 1), node_id(i, j + 1)};
    std::array<Index, 8> dofs;
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 2; ++c)
        dofs[2 * k + c] = n[k] < 0 ? -1 : 2 * n[k] + c;
    return dofs;
  }
  bool assembles(const DofDistribution& d, int i, int j) const {
    return d.owner_of_node(node_id(i + 1, j)) == d.rank();
  }
  SparsityPattern pattern(const DofDistribution& d) const {
    SparsityPattern p;
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j < ny; ++j)
        if (assembles(d, i, j)) p.add_cell(cell_dofs(i, j).data(), 8);
    return p;
  }
  void assemble(SparseMatrix& A) const {
    const auto& d = A.distribution();
    const Eigen::Matrix<double, 8, 8, Eigen::RowMajor> K = plane_strain_quad(a, b, E, nu);
    A.set_zero();
    for (int i = 0; i < nx; ++i)
      for (int j = 0; j < ny; ++j)
        if (assembles(d, i, j)) A.add_dense(cell_dofs(i, j).data(), 8, K.data());
    A.finish_assembly();
  }
  void assemble_rhs(DistributedVector& f) const {
    f.set_zero();
    if (f.distribution().rank() == 0) // loads may be added on any rank
      for (int j = 0; j < ny; ++j)
        for (int end : {j, j + 1}) {
          f.add(2 * node_id(nx, end), 0.5 * b * 1.0);
          f.add(2 * node_id(nx, end) + 1, 0.5 * b * 0.5);
        }
    f.finish_assembly();
  }
  /// x, y, z of each owned node.
  std::vector<double> owned_coordinates(const DofDistribution& d) const {
    std::vector<double> xyz;
    for (Index n = d.first_owned_node(); n < d.first_owned_node() + d.num_owned_nodes(); ++n) {
      xyz.push_back(a * static_cast<double>(n / (ny + 1) + 1));
      xyz.push_back(b * static_cast<double>(n % (ny + 1)));
      xyz.push_back(0.0);
    }
    return xyz;
  }
};

/// Axisymmetric bilinear quadrilateral [r0, r0 + a] x [0, b] in the (r, z) plane, 2x2 Gauss
/// points, strains [rr, zz, thetatheta, rz], integrated with weight r (the 2 pi dropped).
inline Eigen::Matrix<double, 8, 8> axisymmetric_quad(double r0, double a, double b, double E,
                                                     double nu) {
  Eigen::Matrix4d D;
  D << 1 - nu, nu, nu, 0, nu, 1 - nu, nu, 0, nu, nu, 1 - nu, 0, 0, 0, 0, (1 - 2 * nu) / 2;
  D *= E / ((1 + nu) * (1 - 2 * nu));
  const double xi_n[4] = {-1, 1, 1, -1}, eta_n[4] = {-1, -1, 1, 1};
  const double g = 1.0 / std::sqrt(3.0);
  Eigen::Matrix<double, 8, 8> K = Eigen::Matrix<double, 8, 8>::Zero();
  for (double xi : {-g, g})
    for (double eta : {-g, g}) {
      const double r = r0 + a * (1 + xi) / 2;
      Eigen::Matrix<double, 4, 8> B = Eigen::Matrix<double, 4, 8>::Zero();
      for (int n = 0; n < 4; ++n) {
        const double N = (1 + xi * xi_n[n]) * (1 + eta * eta_n[n]) / 4;
        const double dr = xi_n[n] * (1 + eta * eta_n[n]) / 4 * 2 / a;
        const double dz = eta_n[n] * (1 + xi * xi_n[n]) / 4 * 2 / b;
        B(0, 2 * n) = dr;
        B(1, 2 * n + 1) = dz;
        B(2, 2 * n) = N / r;
        B(3, 2 * n) = dz;
        B(3, 2 * n + 1) = dr;
      }
      K += B.transpose() * D * B * (a * b / 4) * r;
    }
  return K;
}

/// Thick hollow cylinder r in [r_in, r_in + nr], z in [0, nz] (unit cells), clamped at z = 0,
/// top face loaded by (0.3 r, -r) per unit area. Free node (i, j), j >= 1, has id
/// (j-1)(nr+1) + i. Cell (i, j) is assembled by the owner of its node (i, j+1).
struct Cylinder {
  int nr = 16, nz = 32;
  double r_in = 0.5, E = 1.0, nu = 0.3;

  Index node_id(int i, int j) const { return j == 0 ? -1 : Index(j - 1) * (nr + 1) + i; }
  Index num_nodes() const { return Index(nz) * (nr + 1); }
  DofDistribution distribution() const { return DofDistribution(num_nodes(), 2); }
  std::array<Index, 8> cell_dofs(int i, int j) const {
    const Index n[4] = {node_id(i, j), node_id(i + 1, j), node_id(i + 1, j + 1), node_id(i, j + 1)};
    std::array<Index, 8> dofs;
    for (int k = 0; k < 4; ++k)
      for (int c = 0; c < 2; ++c)
        dofs[2 * k + c] = n[k] < 0 ? -1 : 2 * n[k] + c;
    return dofs;
  }
  bool assembles(const DofDistribution& d, int i, int j) const {
    return d.owner_of_node(node_id(i, j + 1)) == d.rank();
  }
  SparsityPattern pattern(const DofDistribution& d) const {
    SparsityPattern p;
    for (int i = 0; i < nr; ++i)
      for (int j = 0; j < nz; ++j)
        if (assembles(d, i, j)) p.add_cell(cell_dofs(i, j).data(), 8);
    return p;
  }
  void assemble(SparseMatrix& A) const {
    const auto& d = A.distribution();
    A.set_zero();
    for (int i = 0; i < nr; ++i)
      for (int j = 0; j < nz; ++j)
        if (assembles(d, i, j)) {
          const Eigen::Matrix<double, 8, 8, Eigen::RowMajor> K =
              axisymmetric_quad(r_in + i, 1.0, 1.0, E, nu);
          A.add_dense(cell_dofs(i, j).data(), 8, K.data());
        }
    A.finish_assembly();
  }
  void assemble_rhs(DistributedVector& f) const {
    f.set_zero();
    if (f.distribution().rank() == 0)
      for (int i = 0; i <= nr; ++i) {
        const double r = r_in + i, share = (i == 0 || i == nr) ? 0.5 : 1.0;
        f.add(2 * node_id(i, nz), 0.3 * r * share);
        f.add(2 * node_id(i, nz) + 1, -r * share);
      }
    f.finish_assembly();
  }
  std::vector<double> owned_coordinates(const DofDistribution& d) const {
    std::vector<double> xyz;
    for (Index n = d.first_owned_node(); n < d.first_owned_node() + d.num_owned_nodes(); ++n) {
      xyz.push_back(r_in + static_cast<double>(n % (nr + 1)));
      xyz.push_back(static_cast<double>(n / (nr + 1) + 1));
      xyz.push_back(0.0);
    }
    return xyz;
  }
};

} // namespace bipot::test
