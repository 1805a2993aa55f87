#pragma once
/// Basic index and small-matrix types shared by every layer.

#include <Eigen/Core>
#include <cstdint>

namespace bipot {

/// Global indices (nodes, cells, degrees of freedom): 64-bit so 1M+ DOF meshes never overflow.
using Index = std::int64_t;

/// Strain or stress in Voigt order with engineering shear strains.
/// 2D (plane strain, axisymmetric): [xx, yy, zz, xy]; in axisymmetry x = r, y = z, zz = θθ.
/// 3D: [xx, yy, zz, xy, yz, xz]. Fixed capacity 6 keeps quadrature loops free of heap allocation.
using Voigt = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;
/// Tangent moduli matching Voigt (4x4 or 6x6).
using VoigtMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;

/// Number of Voigt components for a spatial dimension (2 -> 4, 3 -> 6).
inline int voigt_size(int dim) {
  return dim == 2 ? 4 : 6;
}

} // namespace bipot
