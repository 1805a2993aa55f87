#pragma once
/// The kinematic assumption of a continuum model: which strains a displacement field produces
/// and how volumes are measured.

#include <string>

namespace bipot {

/// - PlaneStrain: coordinates (x, y), displacement (u_x, u_y), ε_zz = 0, unit thickness.
/// - Axisymmetric: coordinates (r, z) stored as (x, y), displacement (u_r, u_z), hoop strain
///   ε_θθ = u_r / r, volumes and areas carry the factor 2π r (full revolution).
/// - ThreeD: coordinates (x, y, z).
enum class Kinematics { PlaneStrain, Axisymmetric, ThreeD };

/// Spatial dimension: 2 for plane strain and axisymmetry, 3 for ThreeD.
int spatial_dim(Kinematics kin);

/// "plane_strain", "axisymmetric" or "three_d" (the YAML spelling).
std::string to_string(Kinematics kin);

/// Inverse of to_string. Throws bipot::InputError naming the allowed values (and the nearest
/// one, if any) for an unknown name.
Kinematics parse_kinematics(const std::string& name);

} // namespace bipot
