#pragma once
/// Test helper of the restart tests: what one converged increment of a block-on-base model
/// (block_stage.hpp; its first interface the joint) shows, as one row of numbers to compare.

#include "fem/analysis/static_analysis.hpp"

#include <algorithm>
#include <vector>

namespace bipot::test {

/// Stage index, step, time, load factor; reactions of `top` and `bottom`; the joint's
/// resultant and smallest β; the energy totals (cumulative since the start).
inline std::vector<double> block_step_row(const StaticAnalysis& analysis, const StepReport& r) {
  std::vector<double> row = {double(r.stage_index), double(r.step), r.time, r.load_factor};
  for (const char* set : {"top", "bottom"})
    for (double f : analysis.reaction(set))
      row.push_back(f);
  const auto& ia = *analysis.interfaces()[0];
  for (double f : ia.resultant())
    row.push_back(f);
  double beta = 1;
  for (const auto& p : ia.results())
    beta = std::min(beta, p.beta);
  row.push_back(beta);
  for (double e : {r.energy.external_work, r.energy.bulk_energy, r.energy.interface_energy,
                   r.energy.adhesion_dissipation, r.energy.contact_work})
    row.push_back(e);
  return row;
}

} // namespace bipot::test
