#pragma once
/// Checks of a stage's boundary conditions that need the mesh: which nodes each set holds.

#include "fem/input/problem_spec.hpp"
#include "fem/mesh/mesh.hpp"

#include <string>
#include <vector>

namespace bipot {

/// Pairs of boundary conditions of one stage, on different sets, that fix a component of a
/// node both sets hold to different values (the later one would silently win). One problem
/// per pair, at the later condition: "file:line:col: key.path: message" naming the first node
/// and the other condition's location. Conditions on sets the mesh lacks are skipped (they
/// are reported elsewhere); the same set fixed twice is reported while reading.
std::vector<std::string> conflicting_conditions(const ProblemSpec& spec, const Mesh& mesh);

} // namespace bipot
