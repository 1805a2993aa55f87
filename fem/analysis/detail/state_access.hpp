#pragma once
/// Internal to fem/analysis: reading and writing the arrays of a saved analysis state
/// (analysis_state.cpp, stage_progress.cpp).

#include "fem/core/error.hpp"
#include "fem/core/state_arrays.hpp"

#include <array>
#include <string>
#include <vector>

namespace bipot::analysis_detail {

/// The array `name` of `state`; with `size` > 0 it must hold that many values (a state of
/// another model does not). Throws bipot::Error naming the array.
inline const std::vector<double>& state_array(const StateArrays& state, const std::string& name,
                                              std::size_t size = 0) {
  const auto it = state.find(name);
  if (it == state.end()) throw Error("analysis state: no array '" + name + "'");
  if (size > 0 && it->second.size() != size)
    throw Error("analysis state: array '" + name + "' holds " + std::to_string(it->second.size()) +
                " values, this model needs " + std::to_string(size));
  return it->second;
}

inline std::vector<double> flatten(const std::vector<std::array<double, 3>>& v) {
  std::vector<double> out;
  for (const auto& a : v)
    out.insert(out.end(), a.begin(), a.end());
  return out;
}

/// The triples of `state`'s array `name`, which must hold `count` of them.
inline std::vector<std::array<double, 3>> unflatten(const StateArrays& state,
                                                    const std::string& name, std::size_t count) {
  const std::vector<double>& v = state_array(state, name, 3 * count);
  std::vector<std::array<double, 3>> out(count);
  for (std::size_t k = 0; k < count; ++k)
    out[k] = {v[3 * k], v[3 * k + 1], v[3 * k + 2]};
  return out;
}

} // namespace bipot::analysis_detail
