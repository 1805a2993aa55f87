#pragma once
/// Named arrays of doubles: how the pieces of an analysis hand over their complete state for a
/// checkpoint (integers such as cell ids are stored exactly: below 2^53).

#include <map>
#include <string>
#include <vector>

namespace bipot {

using StateArrays = std::map<std::string, std::vector<double>>;

} // namespace bipot
