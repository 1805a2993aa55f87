#pragma once
/// Initial stress fields from the input (tension positive).

#include "fem/analysis/model.hpp"
#include "fem/core/types.hpp"

#include <array>
#include <functional>

namespace bipot {

/// σ0(x, region) for the model's `initial_stress` entries; zero in regions not listed.
/// Geostatic: vertical stress σ_v = −γ (surface − y) (compression negative; y is the
/// vertical axis in 2D/axisymmetry, z in 3D), horizontal and hoop/out-of-plane stresses
/// K0 σ_v, no shear. Above the surface the stress is zero.
std::function<Voigt(const std::array<double, 3>&, int)> initial_stress_function(const Model& model);

/// Throws InputError, at each `initial_stress` entry's place, when its stress lies outside
/// the yield surface of the region's (plastic) material somewhere: the message names the
/// region, the node where the yield function is largest, its coordinates and the value.
/// The geostatic field is linear in depth and the yield functions convex, so the largest
/// value over a cell is at one of its nodes.
void check_initial_stress_admissible(const Model& model);

} // namespace bipot
