#pragma once
/// Shape functions, physical gradients and integration weights of one volume cell at the
/// points of a quadrature rule (deal.II's FEValues, reduced to what solid mechanics needs).

#include "fem/core/cell_type.hpp"
#include "fem/core/types.hpp"
#include "fem/element/kinematics.hpp"
#include "fem/element/quadrature.hpp"
#include "fem/element/shape_functions.hpp"

#include <Eigen/Core>
#include <array>
#include <vector>

namespace bipot {

struct Mesh;

/// Strain-displacement matrix with fixed capacity (6 x 24): sized at run time without heap
/// allocation, and accepted by ElementValues::strain_displacement.
using StrainDisplacementMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 3 * max_cell_nodes>;

/// Values of a cell type under a kinematic assumption. Construct once per (cell type,
/// kinematics, rule); call reinit() for each cell, then read the per-point values. Reference
/// values are precomputed, so reinit() and the accessors do not allocate.
///
/// The cell dimension must equal the spatial dimension: Tri3/Tri6/Quad4/Quad8 for plane strain
/// and axisymmetry (x = r, y = z), Tet4/Hex8 for ThreeD.
class ElementValues {
public:
  /// Uses gauss_rule(type, degree). Throws bipot::Error if the cell type does not fit `kin`.
  ElementValues(CellType type, Kinematics kin, int degree);
  /// Uses the given rule on the reference cell of `type`.
  ElementValues(CellType type, Kinematics kin, QuadratureRule rule);

  /// Computes the values for a cell whose node coordinates are `coords` (num_nodes() x 3,
  /// row-major; unused components ignored). `cell` only names the cell in error messages.
  /// Throws bipot::Error naming the cell when det J <= 1e-12 x (product of the Jacobian's
  /// column norms) at a point (inverted or degenerate cell), or, in axisymmetry, when a
  /// point has r <= 0.
  void reinit(const double* coords, Index cell = -1);
  /// Same with the coordinates of cell `cell` of `mesh`, whose type must be cell_type().
  void reinit(const Mesh& mesh, Index cell);

  CellType cell_type() const { return type_; }
  Kinematics kinematics() const { return kin_; }
  const QuadratureRule& rule() const { return rule_; }
  int num_points() const { return nq_; }
  int num_nodes() const { return nn_; }
  /// Spatial dimension (2 or 3).
  int dim() const { return dim_; }
  /// Displacement DOFs of the cell: num_nodes() * dim(), interleaved per node.
  int num_dofs() const { return nn_ * dim_; }
  /// Rows of the strain-displacement matrix: 4 in 2D, 6 in 3D (see types.hpp Voigt).
  int voigt_size() const { return bipot::voigt_size(dim_); }

  /// N_a at point q.
  double shape(int q, int a) const { return N_[q * nn_ + a]; }
  /// All N_a at point q (num_nodes() values).
  const double* shapes(int q) const { return &N_[q * nn_]; }
  /// ∂N_a/∂x_i at point q (physical coordinates; valid after reinit).
  double shape_grad(int q, int a, int i) const { return dNdx_[(q * nn_ + a) * dim_ + i]; }
  /// All ∂N_a/∂x_i at point q, row-major num_nodes() x dim().
  const double* shape_grads(int q) const { return &dNdx_[q * nn_ * dim_]; }
  /// Physical coordinates of point q (z = 0 in 2D; x is r in axisymmetry).
  const std::array<double, 3>& point(int q) const { return x_[q]; }
  /// det J at point q (> 0 after a successful reinit).
  double det_jacobian(int q) const { return detJ_[q]; }
  /// Integration weight: w_q |det J| in plane strain (per unit thickness) and 3D,
  /// w_q |det J| 2π r in axisymmetry (full revolution). Units: length^3.
  double JxW(int q) const { return JxW_[q]; }

  /// Fills B (voigt_size() x num_dofs(), pre-sized by the caller, e.g. a
  /// StrainDisplacementMatrix) so that ε = B u_e at
  /// point q, with u_e = [u0x, u0y, (u0z), u1x, ...] and engineering shear strains:
  /// - plane strain: rows [ε_xx, ε_yy, ε_zz = 0, γ_xy];
  /// - axisymmetric (x = r, y = z): rows [ε_rr, ε_zz (axial), ε_θθ = N_a / r in the u_r
  ///   columns, γ_rz] — Voigt slot 1 ("yy") is the axial strain and slot 2 ("zz") the hoop;
  /// - 3D: rows [ε_xx, ε_yy, ε_zz, γ_xy, γ_yz, γ_xz].
  void strain_displacement(int q, Eigen::Ref<Eigen::MatrixXd> B) const;

  /// ε = B u_e at point q without forming B; `u` holds num_dofs() nodal values.
  Voigt strain(int q, const double* u) const;

private:
  CellType type_;
  Kinematics kin_;
  QuadratureRule rule_;
  int nq_ = 0, nn_ = 0, dim_ = 0;
  std::vector<double> N_;     ///< nq x nn, reference values (fixed)
  std::vector<double> dNref_; ///< nq x nn x dim, reference gradients (fixed)
  std::vector<double> dNdx_;  ///< nq x nn x dim, physical gradients
  std::vector<std::array<double, 3>> x_;
  std::vector<double> detJ_, JxW_;
  std::array<double, 3 * max_cell_nodes> coords_{}; ///< gather buffer for reinit(Mesh)
};

} // namespace bipot
