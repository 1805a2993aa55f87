#pragma once
/// Turns a pile pull-out description into a toolkit problem (ProblemSpec): the blocked mesh,
/// node sets, materials, geostatic initial stress, the shaft and toe interfaces and the three
/// stages. Everything physical is done by the toolkit; this file only lays the problem out.

#include "apps/pile_pullout/pile_input.hpp"
#include "fem/input/problem_spec.hpp"

namespace bipot::pile {

/// Region and set names of the generated problem.
inline constexpr const char* kShaft = "shaft"; ///< interface pile | soil beside it
inline constexpr const char* kToe = "toe";     ///< interface pile | soil below the toe
inline constexpr const char* kHead = "head";   ///< node set: pile nodes at z = 0

ProblemSpec make_problem(const PileSpec& pile);

} // namespace bipot::pile
