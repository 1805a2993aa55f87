#pragma once
/// Quadrature rules on the reference cells of shape_functions.hpp.

#include "fem/core/cell_type.hpp"
#include "fem/element/kinematics.hpp"

#include <array>
#include <vector>

namespace bipot {

/// Points and weights on a reference cell. Weights sum to the reference measure
/// (2 for lines, 1/2 for triangles, 4 for quads, 1/6 for tetrahedra, 8 for hexahedra).
struct QuadratureRule {
  std::vector<std::array<double, 3>> points; ///< reference coordinates; unused components 0
  std::vector<double> weights;
  int degree = 0; ///< every polynomial of total degree <= degree is integrated exactly

  int size() const { return static_cast<int>(weights.size()); }
};

/// Gauss–Legendre points and weights on [-1, 1] with n points (1 <= n <= 32), exact for
/// degree 2n - 1. Computed by Newton iteration on the Legendre polynomial to round-off.
QuadratureRule gauss_legendre(int n);

/// A rule exact for all polynomials of total degree `degree` (0 <= degree <= 40) on the
/// reference cell of `type`; the returned rule's `degree` may be higher.
/// - Lines, quads, hexes: tensor Gauss–Legendre with ceil((degree + 1) / 2) points per direction.
/// - Triangles: symmetric rules with positive weights and interior points for degree <= 5
///   (1, 3, 6, 6 and 7 points: centroid; Strang–Fix; Dunavant 4 for degrees 3 and 4; Radon 7),
///   beyond that a collapsed (Duffy) Gauss–Legendre product rule.
/// - Tetrahedra: symmetric rules for degree <= 3 (centroid, 4 points, 8 points with positive
///   weights), beyond that a collapsed Gauss–Legendre product rule.
/// Throws bipot::Error for Point1 or a degree out of range.
QuadratureRule gauss_rule(CellType type, int degree);

/// A quadrature degree adequate for the stiffness matrix ∫ Bᵀ D B of a cell in plane strain
/// or 3D: 2 (order - 1) on simplices (affine map: Bᵀ D B is a polynomial of that degree) and
/// 2 order on quads/hexes (the usual full integration: 2x2, 3x3, 2x2x2 points).
int stiffness_degree(CellType type);

/// As above, one degree higher in axisymmetry, where the 1/r hoop terms and the 2πr volume
/// factor make the integrand rational (no rule is exact; one more degree keeps the error small).
int stiffness_degree(CellType type, Kinematics kin);

} // namespace bipot
