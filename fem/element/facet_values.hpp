#pragma once
/// Shape functions, points, unit normals and integration weights on a boundary or interface
/// facet: a line (Line2, Line3) in 2D, a surface (Tri3, Quad4, and Tri6/Quad8) in 3D.
///
/// Normal convention (the right-hand rule of the facet node order, shared with
/// fem/mesh/cell_facets.hpp):
/// - 2D: with the tangent t = ∂x/∂ξ (from node 0 towards node 1), n = (t_y, -t_x) / |t|, i.e.
///   t rotated clockwise: outward for a boundary traversed counter-clockwise.
/// - 3D: n = (∂x/∂ξ × ∂x/∂η) / |∂x/∂ξ × ∂x/∂η|; for a Tri3 this is the direction of
///   (x1 - x0) × (x2 - x0), for a planar Quad4 that of (x1 - x0) × (x3 - x0).
/// Facets listed by cell_facets() therefore get normals pointing out of their cell.

#include "fem/core/cell_type.hpp"
#include "fem/core/types.hpp"
#include "fem/element/kinematics.hpp"
#include "fem/element/quadrature.hpp"
#include "fem/element/shape_functions.hpp"

#include <array>
#include <vector>

namespace bipot {

struct Mesh;
struct Facet;

/// Values of a facet type at the points of a rule. Construct once per (facet type,
/// kinematics, rule); reinit() per facet does not allocate.
class FacetValues {
public:
  /// Uses gauss_rule(type, degree). Throws bipot::Error unless cell_dim(type) =
  /// spatial_dim(kin) - 1 (lines for plane strain / axisymmetry, surfaces for ThreeD).
  FacetValues(CellType type, Kinematics kin, int degree);
  /// Uses the given rule on the reference cell of `type`.
  FacetValues(CellType type, Kinematics kin, QuadratureRule rule);

  /// Computes the values for a facet with node coordinates `coords` (num_nodes() x 3,
  /// row-major). `facet` only names it in error messages. Throws bipot::Error for a
  /// degenerate facet (zero length/area element at a point) or, in axisymmetry, a point at r < 0.
  void reinit(const double* coords, Index facet = -1);
  /// Same with the nodes of `facet` in `mesh` (facet.type must be facet_type()); errors name
  /// the facet's cell.
  void reinit(const Mesh& mesh, const Facet& facet);

  CellType facet_type() const { return type_; }
  Kinematics kinematics() const { return kin_; }
  const QuadratureRule& rule() const { return rule_; }
  int num_points() const { return nq_; }
  int num_nodes() const { return nn_; }
  /// Spatial dimension (2 or 3).
  int dim() const { return dim_; }

  /// N_a at point q.
  double shape(int q, int a) const { return N_[q * nn_ + a]; }
  /// All N_a at point q (num_nodes() values).
  const double* shapes(int q) const { return &N_[q * nn_]; }
  /// Physical coordinates of point q (z = 0 in 2D).
  const std::array<double, 3>& point(int q) const { return x_[q]; }
  /// Unit normal at point q (z component 0 in 2D), oriented as in the file comment.
  const std::array<double, 3>& normal(int q) const { return n_[q]; }
  /// Integration weight: w_q |∂x/∂ξ| (2D, per unit thickness; length) or
  /// w_q |∂x/∂ξ × ∂x/∂η| (3D; area); times 2π r in axisymmetry (area of the revolved strip).
  double JxW(int q) const { return JxW_[q]; }

private:
  void compute(const double* coords, Index id, bool id_is_cell);

  CellType type_;
  Kinematics kin_;
  QuadratureRule rule_;
  int nq_ = 0, nn_ = 0, dim_ = 0;
  std::vector<double> N_;     ///< nq x nn
  std::vector<double> dNref_; ///< nq x nn x (dim - 1)
  std::vector<std::array<double, 3>> x_, n_;
  std::vector<double> JxW_;
  std::array<double, 3 * max_cell_nodes> coords_{}; ///< gather buffer for reinit(Mesh)
};

} // namespace bipot
