#pragma once
/// The vocabulary of interface points shared by the FE core (which drives and reports
/// interfaces through InterfaceEnforcement) and the contact module (which implements the laws):
/// local-frame vectors and the branch of the contact law.
///
/// Local frame: a LocalVector holds the normal component first, then 1 (2D, axisymmetric) or
/// 2 (3D) tangential components. Forces are tractions (kPa), jumps lengths (m).

#include <Eigen/Core>

namespace bipot {

/// A vector in an interface's local frame [normal, tangential...] (size 2 or 3, no heap).
using LocalVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3, 1>;
/// A matrix acting on local-frame vectors (2×2 or 3×3, no heap).
using LocalMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3>;

/// Which branch of the contact law is active at a point.
enum class ContactStatus {
  Open,  ///< separation: r = 0
  Stick, ///< r = τ inside (or on) the cone
  Slip   ///< r on the cone's boundary (frictionless: closed contact with free sliding)
};

/// "open", "stick", "slip".
const char* to_string(ContactStatus status);

} // namespace bipot
