#pragma once
/// 3×3 stress tensors for the plastic materials: conversion from and to Voigt vectors and the
/// derivative of an isotropic tensor function through its spectral decomposition.
/// Return mappings work on the full 3×3 tensor so one code path serves plane strain,
/// axisymmetry (Voigt size 4, the zz / hoop component a principal value) and 3D (size 6).

#include "fem/core/types.hpp"

#include <Eigen/Core>

namespace bipot {

using Mat3 = Eigen::Matrix3d;
using Vec3 = Eigen::Vector3d;
/// dσ/dσ_trial on tensor components [11, 22, 33, 12, 23, 13]; a shear column is the response to
/// a symmetric perturbation of both off-diagonal entries. Its top-left n×n block acts on the
/// stress Voigt vectors of fem/core/types.hpp.
using StressJacobian = Eigen::Matrix<double, 6, 6>;

/// Tensor indices (row, column) of Voigt component k.
inline constexpr int voigt_row[6] = {0, 1, 2, 0, 1, 0};
inline constexpr int voigt_col[6] = {0, 1, 2, 1, 2, 2};

/// The 3×3 tensor of a stress Voigt vector of size 4 ([xx, yy, zz, xy]) or 6.
Mat3 stress_tensor(const Voigt& stress);
/// The first n Voigt components (n = 4 or 6) of a symmetric tensor.
Voigt stress_voigt(const Mat3& stress, int n);

/// The Jacobian of a tensor map from its directional derivative: column k is
/// `derivative(B_k)` for the basis tensor B_k of Voigt component k (both shear entries 1).
template <class Derivative> StressJacobian jacobian_from(Derivative&& derivative);

/// Eigenvalues in descending order (σ1 ≥ σ2 ≥ σ3, tension positive) with the matching unit
/// eigenvectors as the columns of `directions`.
struct Principal {
  Vec3 values;
  Mat3 directions;
};
Principal principal(const Mat3& tensor);

/// σ = Σ_a s_a e_a⊗e_a for the eigenvectors e_a of the trial tensor, where the principal
/// values s(λ) of the result depend on the trial's principal values λ with Jacobian
/// J = ∂s/∂λ. Returns dσ/dσ_trial, including the rotation of the eigenvectors: the shear
/// term (s_a − s_b)/(λ_a − λ_b), replaced by its limit J_aa − J_ab for equal λ_a, λ_b.
StressJacobian isotropic_jacobian(const Principal& trial, const Vec3& s, const Mat3& J);

template <class Derivative> StressJacobian jacobian_from(Derivative&& derivative) {
  StressJacobian out;
  for (int k = 0; k < 6; ++k) {
    Mat3 B = Mat3::Zero();
    B(voigt_row[k], voigt_col[k]) = 1.0;
    B(voigt_col[k], voigt_row[k]) = 1.0;
    const Mat3 d = derivative(static_cast<const Mat3&>(B));
    for (int r = 0; r < 6; ++r)
      out(r, k) = d(voigt_row[r], voigt_col[r]);
  }
  return out;
}

} // namespace bipot
