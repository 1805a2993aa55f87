#pragma once
/// Warnings about a stage's load steps that need the mesh: its size.

#include "fem/input/problem_spec.hpp"
#include "fem/mesh/mesh.hpp"

#include <string>
#include <vector>

namespace bipot {

/// Prescribed displacements whose step per increment is larger than the model itself (the
/// diagonal of the nodes' bounding box). Every kinematics of bipot is small-strain: such a
/// step is far outside what it describes (a rotation or strain of order one is linearised),
/// and is nearly always a slip of units (mm written as m) or of a digit, so it is worth a
/// warning, not an error. A condition's step is the change from the same set and component's
/// value at the end of the previous stage (0 when that stage did not prescribe it or reset
/// the displacements) divided by the stage's increments. One line per condition,
/// "file:line:col: key.path: message", naming the stage, the set and component, the step and
/// the model's size. Conditions on sets the mesh lacks are skipped (reported elsewhere).
std::vector<std::string> large_increment_warnings(const ProblemSpec& spec, const Mesh& mesh);

} // namespace bipot
