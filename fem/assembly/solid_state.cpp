// SolidAssembler's state for checkpoints: every per-point and per-cell array, by global cell.
#include "fem/assembly/solid_assembler.hpp"

#include "fem/core/error.hpp"

#include <algorithm>
#include <unordered_map>

namespace bipot {

std::vector<SolidAssembler::StateArrayRef> SolidAssembler::state_array_refs() {
  const std::size_t n = owned_cells_.size();
  std::vector<Index> per_point(n + 1);
  for (std::size_t k = 0; k <= n; ++k)
    per_point[k] = qp_offset_[k] * nv_;
  // Internal variables: materials without any store none (state_offset_ is then empty).
  std::vector<Index> per_state(n + 1, 0);
  if (!state_offset_.empty()) per_state = state_offset_;
  return {{"point.initial_stress", &sigma0_, per_point},
          {"point.internal_variables", &state_, per_state},
          {"point.strain_offset", &strain_offset_, per_point}};
}

StateArrays SolidAssembler::save_state() const {
  StateArrays out;
  std::vector<double>& cells = out["cells"];
  for (Index c : owned_cells_)
    cells.push_back(static_cast<double>(c));
  // The arrays are only read; state_array_refs() is non-const because load_state() writes.
  for (const StateArrayRef& a : const_cast<SolidAssembler*>(this)->state_array_refs()) {
    std::vector<double>& values = out[a.name];
    std::vector<double>& count = out[std::string(a.name) + ".count"];
    // An array not allocated yet (σ0 before any is set) is saved as zeros: every rank then
    // contributes the same arrays.
    values = a.values->empty() ? std::vector<double>(a.offsets.back(), 0.0) : *a.values;
    for (std::size_t k = 0; k + 1 < a.offsets.size(); ++k)
      count.push_back(static_cast<double>(a.offsets[k + 1] - a.offsets[k]));
  }
  return out;
}

void SolidAssembler::load_state(const StateArrays& state) {
  const auto get = [&](const std::string& name) -> const std::vector<double>& {
    const auto it = state.find(name);
    if (it == state.end()) throw Error("solid state: no array '" + name + "'");
    return it->second;
  };
  const std::vector<double>& cells = get("cells");
  std::unordered_map<Index, std::size_t> index_of;
  for (std::size_t i = 0; i < cells.size(); ++i)
    index_of[static_cast<Index>(cells[i])] = i;
  for (const StateArrayRef& a : state_array_refs()) {
    const std::vector<double>& from = get(a.name);
    const std::vector<double>& count = get(std::string(a.name) + ".count");
    if (count.size() != cells.size())
      throw Error("solid state: '" + std::string(a.name) + ".count' does not match 'cells'");
    std::vector<Index> start(count.size() + 1, 0);
    for (std::size_t i = 0; i < count.size(); ++i)
      start[i + 1] = start[i] + static_cast<Index>(count[i]);
    if (static_cast<Index>(from.size()) != start.back())
      throw Error("solid state: array '" + std::string(a.name) + "' has the wrong size");
    a.values->assign(a.offsets.back(), 0.0);
    for (std::size_t k = 0; k + 1 < a.offsets.size(); ++k) {
      const auto it = index_of.find(owned_cells_[k]);
      const Index n = a.offsets[k + 1] - a.offsets[k];
      if (it == index_of.end() || static_cast<Index>(count[it->second]) != n)
        throw Error("solid state: cell " + std::to_string(owned_cells_[k]) + " is missing from '" +
                    a.name + "' or has another number of values");
      std::copy(from.begin() + start[it->second], from.begin() + start[it->second] + n,
                a.values->begin() + a.offsets[k]);
    }
  }
  trial_state_ = state_;
  // A strain offset saved before any reset comes back as zeros: drop it, as if never set.
  if (std::all_of(strain_offset_.begin(), strain_offset_.end(), [](double v) { return v == 0; }))
    strain_offset_.clear();
}

} // namespace bipot
