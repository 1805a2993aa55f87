#include "fem/element/element_values.hpp"

#include "fem/core/error.hpp"
#include "fem/mesh/mesh.hpp"

#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <string>

namespace bipot {
namespace {

constexpr double two_pi = 6.283185307179586476925286766559005768;

std::string cell_label(Index cell, CellType type) {
  return (cell >= 0 ? "cell " + std::to_string(cell) : std::string("cell (id unknown)")) + " (" +
         to_string(type) + ")";
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string format_point(const std::array<double, 3>& x) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", x[0], x[1], x[2]);
  return buf;
}

} // namespace

ElementValues::ElementValues(CellType type, Kinematics kin, int degree)
    : ElementValues(type, kin, gauss_rule(type, degree)) {}

ElementValues::ElementValues(CellType type, Kinematics kin, QuadratureRule rule)
    : type_(type), kin_(kin), rule_(std::move(rule)) {
  dim_ = spatial_dim(kin);
  if (type == CellType::Point1 || cell_dim(type) != dim_)
    throw Error("ElementValues: cell type " + to_string(type) + " cannot be used with " +
                to_string(kin) + " kinematics (cell dimension " + std::to_string(cell_dim(type)) +
                ", spatial dimension " + std::to_string(dim_) + ")");
  nq_ = rule_.size();
  nn_ = bipot::num_nodes(type);
  N_.resize(nq_ * nn_);
  dNref_.resize(nq_ * nn_ * dim_);
  dNdx_.assign(nq_ * nn_ * dim_, 0.0);
  x_.assign(nq_, {0, 0, 0});
  detJ_.assign(nq_, 0.0);
  JxW_.assign(nq_, 0.0);
  for (int q = 0; q < nq_; ++q) {
    shape_values(type, rule_.points[q].data(), &N_[q * nn_]);
    shape_gradients(type, rule_.points[q].data(), &dNref_[q * nn_ * dim_]);
  }
}

void ElementValues::reinit(const Mesh& mesh, Index cell) {
  if (mesh.cell_types[cell] != type_)
    throw Error("ElementValues for " + to_string(type_) + " given " +
                cell_label(cell, mesh.cell_types[cell]));
  const Index* nodes = mesh.cell(cell);
  for (int a = 0; a < nn_; ++a)
    for (int i = 0; i < 3; ++i)
      coords_[3 * a + i] = mesh.nodes[nodes[a]][i];
  reinit(coords_.data(), cell);
}

void ElementValues::reinit(const double* coords, Index cell) {
  using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;
  for (int q = 0; q < nq_; ++q) {
    const double* N = &N_[q * nn_];
    const double* dN = &dNref_[q * nn_ * dim_];
    // J_ij = ∂x_i/∂ξ_j = Σ_a x_ai ∂N_a/∂ξ_j.
    Mat J = Mat::Zero(dim_, dim_);
    std::array<double, 3> x{0, 0, 0};
    for (int a = 0; a < nn_; ++a) {
      for (int i = 0; i < dim_; ++i) {
        x[i] += N[a] * coords[3 * a + i];
        for (int j = 0; j < dim_; ++j)
          J(i, j) += coords[3 * a + i] * dN[a * dim_ + j];
      }
    }
    // One factorisation for both det J and J⁻¹: what J.determinant() and J.inverse() each
    // compute for a matrix of run-time size, so the values are the same to the bit.
    const Eigen::PartialPivLU<Mat> lu(J);
    const double det = lu.determinant();
    // Scale-free degeneracy test: det J relative to the volume of the box spanned by the
    // Jacobian's columns (equal when the columns are orthogonal).
    double scale = 1;
    for (int j = 0; j < dim_; ++j)
      scale *= J.col(j).norm();
    if (!(det > 1e-12 * scale))
      throw Error(cell_label(cell, type_) + " is inverted or degenerate: det J = " + num(det) +
                  " at quadrature point " + std::to_string(q) + " " + format_point(x));
    const Mat Jinv = lu.inverse();
    // ∂N_a/∂x_i = Σ_j ∂N_a/∂ξ_j (J⁻¹)_ji.
    double* g = &dNdx_[q * nn_ * dim_];
    for (int a = 0; a < nn_; ++a)
      for (int i = 0; i < dim_; ++i) {
        double s = 0;
        for (int j = 0; j < dim_; ++j)
          s += dN[a * dim_ + j] * Jinv(j, i);
        g[a * dim_ + i] = s;
      }
    double w = rule_.weights[q] * det;
    if (kin_ == Kinematics::Axisymmetric) {
      if (!(x[0] > 0))
        throw Error(cell_label(cell, type_) + " has a quadrature point at r = " + num(x[0]) +
                    " <= 0 " + format_point(x) + "; axisymmetric meshes must lie in r >= 0");
      w *= two_pi * x[0];
    }
    x_[q] = x;
    detJ_[q] = det;
    JxW_[q] = w;
  }
}

void ElementValues::strain_displacement(int q, Eigen::Ref<Eigen::MatrixXd> B) const {
  eigen_assert(B.rows() == voigt_size() && B.cols() == num_dofs());
  B.setZero();
  const double* g = shape_grads(q);
  if (dim_ == 2) {
    for (int a = 0; a < nn_; ++a) {
      const double dx = g[2 * a], dy = g[2 * a + 1];
      const int c = 2 * a;
      B(0, c) = dx;
      B(1, c + 1) = dy;
      B(3, c) = dy;
      B(3, c + 1) = dx;
      if (kin_ == Kinematics::Axisymmetric) B(2, c) = shape(q, a) / x_[q][0];
    }
  } else {
    for (int a = 0; a < nn_; ++a) {
      const double dx = g[3 * a], dy = g[3 * a + 1], dz = g[3 * a + 2];
      const int c = 3 * a;
      B(0, c) = dx;
      B(1, c + 1) = dy;
      B(2, c + 2) = dz;
      B(3, c) = dy, B(3, c + 1) = dx;
      B(4, c + 1) = dz, B(4, c + 2) = dy;
      B(5, c) = dz, B(5, c + 2) = dx;
    }
  }
}

Voigt ElementValues::strain(int q, const double* u) const {
  Voigt eps = Voigt::Zero(voigt_size());
  const double* g = shape_grads(q);
  if (dim_ == 2) {
    for (int a = 0; a < nn_; ++a) {
      const double dx = g[2 * a], dy = g[2 * a + 1], ux = u[2 * a], uy = u[2 * a + 1];
      eps[0] += dx * ux;
      eps[1] += dy * uy;
      eps[3] += dy * ux + dx * uy;
      if (kin_ == Kinematics::Axisymmetric) eps[2] += shape(q, a) * ux;
    }
    if (kin_ == Kinematics::Axisymmetric) eps[2] /= x_[q][0];
  } else {
    for (int a = 0; a < nn_; ++a) {
      const double dx = g[3 * a], dy = g[3 * a + 1], dz = g[3 * a + 2];
      const double ux = u[3 * a], uy = u[3 * a + 1], uz = u[3 * a + 2];
      eps[0] += dx * ux;
      eps[1] += dy * uy;
      eps[2] += dz * uz;
      eps[3] += dy * ux + dx * uy;
      eps[4] += dz * uy + dy * uz;
      eps[5] += dz * ux + dx * uz;
    }
  }
  return eps;
}

} // namespace bipot
